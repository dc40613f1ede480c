#include "gen/mesh_io/mesh_writer.h"

#include <cctype>
#include <filesystem>

#include "gen/util/error.h"
#include "gen/mesh_io/obj_writer.h"
#include "gen/mesh_io/off_writer.h"
#include "gen/mesh_io/stl_writer.h"
#include "gen/mesh_io/three_mf_writer.h"

namespace tsf {

const std::vector<std::string>& supportedMeshExtensions() {
    static const std::vector<std::string> kExtensions = {".stl", ".3mf", ".off", ".obj"};
    return kExtensions;
}

std::string lowerCaseExtension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    for (char& c : ext) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return ext;
}

void writeMesh(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts) {
    const std::string ext = lowerCaseExtension(path);
    if (ext == ".stl") return writeStl(mesh, path, opts);
    if (ext == ".3mf") return write3mf(mesh, path, opts);
    if (ext == ".off") return writeOff(mesh, path, opts);
    if (ext == ".obj") return writeObj(mesh, path, opts);
    std::string list;
    for (const std::string& e : supportedMeshExtensions()) list += (list.empty() ? "" : ", ") + e;
    throw InputError(path, 0, 0,
                     "unknown mesh file type '" + (ext.empty() ? std::string("(no extension)") : ext) +
                         "'; supported: " + list);
}

}  // namespace tsf
