#include "gen/mesh_io/mesh_write_checks.h"

#include <cmath>
#include <limits>
#include <stdexcept>

#include "gen/util/error.h"

namespace tsf::mesh_io {
namespace {

std::string describeVertex(size_t index, const Vec3& p) {
    return "vertex " + std::to_string(index) + " (" + std::to_string(p.x) + ", " + std::to_string(p.y) + ", " +
           std::to_string(p.z) + ")";
}

}  // namespace

void checkMeshForWriting(const Mesh& mesh, const std::string& path, bool float32_format) {
    const double float_max = std::numeric_limits<float>::max();
    for (size_t i = 0; i < mesh.positions.size(); ++i) {
        const Vec3& p = mesh.positions[i];
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
            throw InputError(path, 0, 0, "cannot write: " + describeVertex(i, p) + " has a coordinate that is not a finite number");
        }
        // A double that rounds to float infinity: anything beyond the largest
        // float plus half an ulp; comparing against float max is the safe side.
        if (float32_format && (std::fabs(p.x) > float_max || std::fabs(p.y) > float_max || std::fabs(p.z) > float_max)) {
            throw InputError(path, 0, 0, "cannot write: " + describeVertex(i, p) + " does not fit in a 32-bit float");
        }
    }
    const size_t vertex_count = mesh.positions.size();
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        for (uint32_t v : mesh.triangles[t]) {
            if (v >= vertex_count) {
                throw std::invalid_argument("mesh triangle " + std::to_string(t) + " refers to vertex " + std::to_string(v) +
                                            " but the mesh has " + std::to_string(vertex_count) + " vertices");
            }
        }
    }
}

std::string printableTitle(const std::string& title) {
    std::string out = title;
    for (char& c : out) {
        const auto byte = static_cast<unsigned char>(c);
        if (byte < 0x20 || byte == 0x7F) c = ' ';
    }
    return out;
}

}  // namespace tsf::mesh_io
