#include "gen/mesh_io/mesh_reader.h"

#include <filesystem>

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

// Bytes enough to tell the formats apart by their content.
constexpr size_t kSniffBytes = 4096;
// Binary STL: an 80-byte header, a 32-bit little-endian triangle count, 50 bytes a triangle.
constexpr int64_t kStlCountOffset = 80, kStlFirstFacet = 84, kStlFacetBytes = 50;

bool startsWithSolidText(std::string_view bytes) {
    size_t i = 0;
    while (i < bytes.size() && (bytes[i] == ' ' || bytes[i] == '\t' || bytes[i] == '\r' || bytes[i] == '\n')) ++i;
    if (bytes.size() - i < 5) return false;
    std::string word(bytes.substr(i, 5));
    for (char& c : word) c = char(c | 0x20);
    return word == "solid";
}

// A binary STL's size follows from its triangle count.
bool hasBinaryStlSize(std::string_view head, int64_t file_bytes) {
    if (head.size() < size_t(kStlFirstFacet)) return false;
    const auto* p = reinterpret_cast<const unsigned char*>(head.data()) + kStlCountOffset;
    const int64_t count = int64_t(p[0]) | int64_t(p[1]) << 8 | int64_t(p[2]) << 16 | int64_t(p[3]) << 24;
    return file_bytes == kStlFirstFacet + count * kStlFacetBytes;
}

std::string unknownTypeMessage(const std::string& ext) {
    return "unknown mesh file type '" + (ext.empty() ? std::string("(no extension)") : ext) +
           "' and the content is not STL, 3MF or OFF; supported: .stl, .3mf, .off, .obj";
}

// Looks at the first bytes and the size before the whole file is read, so
// that a large file of another kind (a disk image, a video) is refused at
// once instead of after reading gigabytes: a file without a mesh extension
// must start like a 3MF (ZIP), an OFF or an ASCII STL, or have exactly the
// size its binary STL header says; a .3mf must be a ZIP package.
void sniffBeforeReading(const std::string& path) {
    const std::string ext = lowerCaseExtension(path);
    if (ext == ".stl" || ext == ".off" || ext == ".obj") return;
    const std::string head = readFileHead(path, kSniffBytes);
    std::error_code ec;
    const auto size = std::filesystem::file_size(path, ec);
    if (ec) return;  // not a regular file: the reader says what is wrong
    if (ext == ".3mf") {
        if (!startsWithZipSignature(head) && !head.empty())
            throw InputError(path, 0, 0, "is not a 3MF file: a 3MF is a ZIP package, and this file does not start like one");
        return;
    }
    if (startsWithZipSignature(head) || startsWithOffHeader(head) || startsWithSolidText(head) ||
        hasBinaryStlSize(head, int64_t(size)))
        return;
    throw InputError(path, 0, 0, unknownTypeMessage(ext));
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
        throw InputError(path, 0, 0, unknownTypeMessage(ext));
    }
}

}  // namespace

Mesh readMesh(const std::string& path, MeshReadReport* report) {
    sniffBeforeReading(path);
    return parseMesh(readFileBytes(path, kMaxMeshFileBytes), path, report);
}

std::vector<MeshPart> readMeshParts(const std::string& path, MeshReadReport* report) {
    sniffBeforeReading(path);
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
