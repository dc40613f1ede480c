// Shaped tops: accessors and the crossing geometry. See top_shapes.h.
#include "gen/model/features/top_shapes.h"

#include <algorithm>
#include <cassert>
#include <cmath>

#include "gen/util/error.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

int cornerOf(const Scene& s, size_t k, int64_t id) {
    for (int e = 0; e < kHexCorners; ++e)
        if (hexCornerId(s.grid, s.col[k], s.row[k], e) == id) return e;
    assert(false && "the vertex is not a corner of the cell");
    return 0;
}

}  // namespace

TopShapes levelTopShapes(size_t cells, bool mirrored) {
    TopShapes t;
    t.top_dz.assign(cells, {});
    t.top_centre_dz.assign(cells, 0);
    if (mirrored) {
        t.bottom_dz.assign(cells, {});
        t.bottom_centre_dz.assign(cells, 0);
    }
    t.slope_x.assign(cells, 0.0);
    t.slope_y.assign(cells, 0.0);
    t.structural.assign(cells, 0);
    return t;
}

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
int64_t highestPillarTop(const Scene& s) {
    int64_t top = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        int64_t t = s.top[k];
        if (!s.shapes.empty()) {
            for (const int32_t dz : s.shapes.top_dz[k]) t = std::max(t, s.top[k] + dz);
            t = std::max(t, s.top[k] + s.shapes.top_centre_dz[k]);
        }
        top = std::max(top, t);
    }
    return top;
}

int64_t centreTop(const Scene& s, size_t k) { return s.top[k] + (s.shapes.empty() ? 0 : s.shapes.top_centre_dz[k]); }
int64_t centreBottom(const Scene& s, size_t k) {
    return s.bottom[k] + (s.shapes.bottom_centre_dz.empty() ? 0 : s.shapes.bottom_centre_dz[k]);
}

std::map<std::pair<int64_t, int64_t>, int32_t> facesOnEdges(const Scene& s) {
    std::map<std::pair<int64_t, int64_t>, int32_t> out;
    for (size_t f = 0; f < s.faces.faces.size(); ++f)
        for (const auto& ring : s.faces.faces[f].rings)
            for (size_t i = 0; i < ring.size(); ++i) out[{ring[i], ring[(i + 1) % ring.size()]}] = int32_t(f);
    return out;
}

namespace {

[[noreturn]] void fail(const Scene& s, size_t k, const std::string& what) {
    throw InputError("scene: cell (" + std::to_string(s.col[k]) + ", " + std::to_string(s.row[k]) + "): " + what);
}

bool cross(int64_t av, int64_t aw, int64_t bv, int64_t bw) {
    const int64_t dv = av - bv, dw = aw - bw;
    return (dv > 0 && dw < 0) || (dv < 0 && dw > 0);
}

}  // namespace

void checkTopShapes(const Scene& s) {
    const TopShapes& t = s.shapes;
    if (t.empty()) return;
    const size_t n = s.keptCount();
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    if (t.top_dz.size() != n || t.top_centre_dz.size() != n || t.slope_x.size() != n || t.slope_y.size() != n ||
        t.structural.size() != n || t.shaped.size() != n || t.centre_top_id.size() != n ||
        t.centre_bottom_id.size() != n || t.crossing_top.size() != kHexCorners * n ||
        t.crossing_bottom.size() != kHexCorners * n || t.extra.size() != t.extra_z.size() ||
        (mirrored ? t.bottom_dz.size() != n || t.bottom_centre_dz.size() != n
                  : !t.bottom_dz.empty() || !t.bottom_centre_dz.empty()))
        throw InputError("scene: the shaped tops' lists do not match the kept cells");
    if (t.first_id != latticeVertexIdCount(s.grid) + int64_t(s.faces.extra.size()))
        throw InputError("scene: the shaped tops' planar ids must follow the marks'");
    const int64_t end_id = t.first_id + int64_t(t.extra.size());
    auto validId = [&](int64_t id) { return id >= t.first_id && id < end_id; };
    auto byFace = [&s](size_t k) { return !s.drawn_by_face.empty() && s.drawn_by_face[k]; };
    const auto faces_on = facesOnEdges(s);
    for (size_t k = 0; k < n; ++k) {
        if (t.shaped[k] && (!validId(t.centre_top_id[k]) || (mirrored && !validId(t.centre_bottom_id[k]))))
            fail(s, k, "a shaped top needs its centre vertex");
        if (!(centreBottom(s, k) < centreTop(s, k))) fail(s, k, "the bottom of its centre must be below the top");
        for (int e = 0; e < kHexCorners; ++e) {
            if (!(cornerBottom(s, k, e) < cornerTop(s, k, e)))
                fail(s, k, "corner " + std::to_string(e) + ": the bottom must be below the top");
            if (!t.shaped[k] && (t.top_dz[k][size_t(e)] != 0 || t.crossing_top[kHexCorners * k + size_t(e)] >= 0))
                fail(s, k, "a level top has no corner offsets or crossings");
        }
        if (byFace(k)) continue;
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t j = s.keptNeighbour(k, e);
            if (j < 0) continue;
            const int e1 = (e + 1) % kHexCorners;
            const int64_t v = hexCornerId(s.grid, s.col[k], s.row[k], e), w = hexCornerId(s.grid, s.col[k], s.row[k], e1);
            const int64_t av = cornerTop(s, k, e), aw = cornerTop(s, k, e1);
            const int64_t abv = cornerBottom(s, k, e), abw = cornerBottom(s, k, e1);
            int64_t bv, bw, bbv, bbw;
            if (byFace(size_t(j))) {
                const auto f = faces_on.find({w, v});
                if (f == faces_on.end()) {
                    if (t.shaped[k]) fail(s, k, "a shaped top beside a mark must meet it along a whole edge");
                    continue;
                }
                const PlanarFace& face = s.faces.faces[size_t(f->second)];
                bv = bw = s.faceTop(face);
                bbv = bbw = s.faceBottom(face);
                if (cross(av, aw, bv, bw) || (mirrored && cross(abv, abw, bbv, bbw)))
                    fail(s, k, "its top crosses an orientation mark's face");
            } else {
                bv = cornerTopAt(s, size_t(j), v);
                bw = cornerTopAt(s, size_t(j), w);
                bbv = cornerBottomAt(s, size_t(j), v);
                bbw = cornerBottomAt(s, size_t(j), w);
                const int64_t xt = t.crossing_top[kHexCorners * k + size_t(e)];
                const int64_t xb = t.crossing_bottom[kHexCorners * k + size_t(e)];
                if (cross(av, aw, bv, bw) != validId(xt) || (mirrored && cross(abv, abw, bbv, bbw) != validId(xb)))
                    fail(s, k, "tops that cross along edge " + std::to_string(e) + " need their crossing point (and only they)");
            }
            if (!(bbv < av && abv < bv && bbw < aw && abw < bw))
                fail(s, k, "does not overlap its neighbour in z at a shared corner");
        }
    }
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
