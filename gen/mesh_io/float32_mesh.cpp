#include "gen/mesh_io/float32_mesh.h"

#include "gen/mesh_io/exact_vertex_index.h"

namespace tsf {
namespace {

// One coordinate as float32 stores it. Kept out of line: g++ 12 at -O2
// vectorised (double)(float)x over x and y into a plain copy, dropping the
// rounding (seen in this very function), so the conversion is a call.
[[gnu::noinline]] double asFloat32(double v) {
    volatile float f = static_cast<float>(v);
    return f;
}

}  // namespace

Mesh float32Mesh(const Mesh& mesh) {
    mesh_io::ExactVertexIndex index(mesh.positions.size());
    std::vector<uint32_t> remap(mesh.positions.size());
    for (size_t v = 0; v < mesh.positions.size(); ++v) {
        const Vec3& p = mesh.positions[v];
        remap[v] = index.insert(Vec3{asFloat32(p.x), asFloat32(p.y), asFloat32(p.z)});
    }
    Mesh out;
    out.positions = index.takePositions();
    out.triangles.reserve(mesh.triangles.size());
    for (const auto& t : mesh.triangles) out.triangles.push_back({remap[t[0]], remap[t[1]], remap[t[2]]});
    return out;
}

}  // namespace tsf
