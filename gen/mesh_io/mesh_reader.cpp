#include "gen/mesh_io/mesh_reader.h"

#include "gen/util/error.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/obj_reader.h"
#include "gen/mesh_io/off_reader.h"
#include "gen/mesh_io/stl_reader.h"
#include "gen/mesh_io/three_mf_reader.h"
#include "gen/util/file_bytes.h"

namespace tsf {

namespace {

bool startsWithZipSignature(std::string_view bytes) { return bytes.size() >= 4 && bytes.substr(0, 4) == "PK\x03\x04"; }

bool startsWithOffHeader(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
    for (std::string_view header : {"OFF", "COFF", "NOFF", "CNOFF"}) {
        if (bytes.substr(i, header.size()) == header) return true;
    }
    return false;
}

}  // namespace

namespace {

// The mesh in bytes, read from path.
Mesh parseMesh(const std::string& bytes, const std::string& path, MeshReadReport* report) {
    const std::string ext = lowerCaseExtension(path);
    if (ext == ".stl") return parseStl(bytes, path, report);
    if (ext == ".3mf") return parse3mf(bytes, path, report);
    if (ext == ".off") return parseOff(bytes, path, report);
    if (ext == ".obj") return parseObj(bytes, path, report);
    if (startsWithZipSignature(bytes)) return parse3mf(bytes, path, report);
    if (startsWithOffHeader(bytes)) return parseOff(bytes, path, report);
    try {
        return parseStl(bytes, path, report);
    } catch (const InputError&) {
        throw InputError(path, 0, 0,
                         "unknown mesh file type '" + (ext.empty() ? std::string("(no extension)") : ext) +
                             "' and the content is not STL, 3MF or OFF; supported: .stl, .3mf, .off, .obj");
    }
}

}  // namespace

Mesh readMesh(const std::string& path, MeshReadReport* report) {
    return parseMesh(readFileBytes(path, kMaxMeshFileBytes), path, report);
}

std::vector<MeshPart> readMeshParts(const std::string& path, MeshReadReport* report) {
    const std::string bytes = readFileBytes(path, kMaxMeshFileBytes);
    const std::string ext = lowerCaseExtension(path);
    if (ext == ".3mf" || (ext != ".stl" && ext != ".off" && ext != ".obj" && startsWithZipSignature(bytes)))
        return parse3mfParts(bytes, path, report);
    std::vector<MeshPart> parts;
    parts.push_back({"model", parseMesh(bytes, path, report)});
    return parts;
}

std::string describeReadReport(const MeshReadReport& report) {
    std::string text = "format: " + report.format + "\n";
    text += "triangles: " + std::to_string(report.input_triangles) + "\n";
    text += "input vertices: " + std::to_string(report.input_vertices) + " (" +
            std::to_string(report.merged_vertices) + " merged as exactly equal)\n";
    text += "triangles repeating a vertex: " + std::to_string(report.degenerate_index_triangles) + "\n";
    for (const std::string& note : report.notes) text += "note: " + note + "\n";
    return text;
}

}  // namespace tsf
