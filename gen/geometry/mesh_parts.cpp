#include "gen/geometry/mesh_parts.h"

namespace tsf {

Mesh joinParts(const std::vector<MeshPart>& parts) {
    Mesh out;
    for (const MeshPart& p : parts) {
        const uint32_t base = uint32_t(out.positions.size());
        out.positions.insert(out.positions.end(), p.mesh.positions.begin(), p.mesh.positions.end());
        for (const auto& t : p.mesh.triangles) out.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return out;
}

}  // namespace tsf
