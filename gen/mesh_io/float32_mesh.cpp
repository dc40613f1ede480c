#include "gen/mesh_io/float32_mesh.h"

#include "gen/mesh_io/exact_weld.h"
#include "gen/util/workers.h"

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
    // Each position rounded, then welded exactly as a reader welds the
    // file's corners (positions that round alike become one vertex), on
    // every core; the triangles renumbered.
    const size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
    const unsigned workers = detail::workerCount(0);
    std::vector<Vec3> rounded(nv);
    detail::runOnRanges(workers, nv, [&](unsigned, size_t begin, size_t end) {
        for (size_t v = begin; v < end; ++v) {
            const Vec3& p = mesh.positions[v];
            rounded[v] = Vec3{asFloat32(p.x), asFloat32(p.y), asFloat32(p.z)};
        }
    });
    mesh_io::WeldedPositions welded = mesh_io::weldExact(std::move(rounded));
    Mesh out;
    out.positions = std::move(welded.positions);
    out.triangles.resize(nt);
    const std::vector<uint32_t>& remap = welded.index_of;
    detail::runOnRanges(workers, nt, [&](unsigned, size_t begin, size_t end) {
        for (size_t t = begin; t < end; ++t) {
            const auto& q = mesh.triangles[t];
            out.triangles[t] = {remap[q[0]], remap[q[1]], remap[q[2]]};
        }
    });
    return out;
}

}  // namespace tsf
