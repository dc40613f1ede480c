// Shaped tops: accessors and the crossing geometry. See top_shapes.h.
#include "gen/top_shapes.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "gen/scene.h"

namespace tsf {
namespace {

int cornerOf(const Scene& s, size_t k, int64_t id) {
    for (int e = 0; e < kHexCorners; ++e)
        if (hexCornerId(s.grid, s.col[k], s.row[k], e) == id) return e;
    assert(false && "the vertex is not a corner of the cell");
    return 0;
}

}  // namespace

int64_t cornerTop(const Scene& s, size_t k, int e) {
    return s.top[k] + (s.shapes.empty() ? 0 : s.shapes.top_dz[k][size_t(e)]);
}
int64_t cornerBottom(const Scene& s, size_t k, int e) {
    return s.bottom[k] + (s.shapes.bottom_dz.empty() ? 0 : s.shapes.bottom_dz[k][size_t(e)]);
}
int64_t cornerTopAt(const Scene& s, size_t k, int64_t id) {
    return s.shapes.empty() ? s.top[k] : cornerTop(s, k, cornerOf(s, k, id));
}
int64_t cornerBottomAt(const Scene& s, size_t k, int64_t id) {
    return s.shapes.bottom_dz.empty() ? s.bottom[k] : cornerBottom(s, k, cornerOf(s, k, id));
}
int64_t centreTop(const Scene& s, size_t k) { return s.top[k] + (s.shapes.empty() ? 0 : s.shapes.top_centre_dz[k]); }
int64_t centreBottom(const Scene& s, size_t k) {
    return s.bottom[k] + (s.shapes.bottom_centre_dz.empty() ? 0 : s.shapes.bottom_centre_dz[k]);
}

void buildTopShapeGeometry(Scene& s) {
    TopShapes& t = s.shapes;
    if (t.empty()) return;
    const size_t n = s.keptCount();
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    t.first_id = latticeVertexIdCount(s.grid) + int64_t(s.faces.extra.size());
    t.extra.clear();
    t.extra_z.clear();
    t.shaped.assign(n, 0);
    t.centre_top_id.assign(n, -1);
    t.centre_bottom_id.assign(n, -1);
    t.crossing_top.assign(kHexCorners * n, -1);
    t.crossing_bottom.assign(kHexCorners * n, -1);
    auto addExtra = [&t](PlanarPoint p, int64_t z) {
        t.extra.push_back(p);
        t.extra_z.push_back(z);
        return t.first_id + int64_t(t.extra.size()) - 1;
    };
    for (size_t k = 0; k < n; ++k) {
        bool any = t.top_centre_dz[k] != 0 || (mirrored && t.bottom_centre_dz[k] != 0);
        for (int e = 0; e < kHexCorners; ++e) any = any || t.top_dz[k][size_t(e)] != 0;
        t.shaped[k] = any;
    }
    // The crossing may come no nearer than kMinCrossingMm to an end of the
    // edge (pitch / sqrt 3 long), and never past its quarter points.
    const double t_min = std::min(0.25, kMinCrossingMm / (s.pitch_mm / kSqrt3));
    auto drawnByFace = [&s](size_t k) { return !s.drawn_by_face.empty() && s.drawn_by_face[k]; };
    for (size_t k = 0; k < n; ++k) {
        if (drawnByFace(k)) continue;
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t j = s.keptNeighbour(k, e);
            if (j < 0 || size_t(j) < k || drawnByFace(size_t(j))) continue;
            const int64_t v = hexCornerId(s.grid, s.col[k], s.row[k], e);
            const int64_t w = hexCornerId(s.grid, s.col[k], s.row[k], (e + 1) % kHexCorners);
            for (int part = 0; part < (mirrored ? 2 : 1); ++part) {
                const bool top = part == 0;
                const int64_t av = top ? cornerTop(s, k, e) : cornerBottom(s, k, e);
                const int64_t aw = top ? cornerTop(s, k, (e + 1) % kHexCorners) : cornerBottom(s, k, (e + 1) % kHexCorners);
                const int64_t bv = top ? cornerTopAt(s, size_t(j), v) : cornerBottomAt(s, size_t(j), v);
                const int64_t bw = top ? cornerTopAt(s, size_t(j), w) : cornerBottomAt(s, size_t(j), w);
                const int64_t dv = av - bv, dw = aw - bw;
                if (!((dv > 0 && dw < 0) || (dv < 0 && dw > 0))) continue;
                const double at = std::clamp(double(dv) / double(dv - dw), t_min, 1.0 - t_min);
                const LatticePoint pv = latticeVertexPoint(s.grid, v), pw = latticeVertexPoint(s.grid, w);
                const PlanarPoint p{double(pv.i) + at * double(pw.i - pv.i), double(pv.j) + at * double(pw.j - pv.j)};
                const double za = double(av) + at * double(aw - av), zb = double(bv) + at * double(bw - bv);
                const int64_t id = addExtra(p, std::llround(0.5 * (za + zb)));
                auto& cross = top ? t.crossing_top : t.crossing_bottom;
                cross[kHexCorners * k + size_t(e)] = id;
                cross[kHexCorners * size_t(j) + size_t((e + 3) % kHexCorners)] = id;
                t.shaped[k] = t.shaped[size_t(j)] = 1;
            }
        }
    }
    for (size_t k = 0; k < n; ++k) {
        if (!t.shaped[k]) continue;
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        const PlanarPoint p{double(c.i), double(c.j)};
        t.centre_top_id[k] = addExtra(p, centreTop(s, k));
        if (mirrored) t.centre_bottom_id[k] = addExtra(p, centreBottom(s, k));
    }
}

}  // namespace tsf
