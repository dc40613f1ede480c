#include "gen/model/features/legend/legend_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <array>
#include <numbers>

#include "gen/geometry/polygon_triangulation.h"

namespace tsf {
namespace {

double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

struct Builder {
    Mesh mesh;
    uint32_t add(double x, double y, double z) {
        mesh.positions.push_back({x, y, z});
        return uint32_t(mesh.positions.size() - 1);
    }
    void tri(uint32_t a, uint32_t b, uint32_t c) { mesh.triangles.push_back({a, b, c}); }
};

// Angle of base vertex k of a dome.
double domeAngle(int k) { return 2 * std::numbers::pi * k / kDomeSides; }

// Base octagon of the dome over dot d on a surface at height h, counter-clockwise from above.
std::array<Vec3, kDomeSides> domeBase(const LegendDot& d, const BrailleStandard& st, double h) {
    const double r = st.dot_base_mm / 2;
    std::array<Vec3, kDomeSides> out;
    for (int k = 0; k < kDomeSides; ++k)
        out[size_t(k)] = {snapUm(d.x_mm + r * std::cos(domeAngle(k))), snapUm(d.y_mm + r * std::sin(domeAngle(k))), h};
    return out;
}

// The dome over dot d (a low-poly spherical cap on a surface at height h)
// on its base octagon `base` (vertex indices of domeBase's points, in order).
void addDome(Builder& b, const LegendDot& d, const BrailleStandard& st, double h, const std::vector<uint32_t>& base) {
    const double r = st.dot_base_mm / 2, hd = st.dot_height_mm;
    const double R = (r * r + hd * hd) / (2 * hd), theta_max = std::asin(r / R), zc = h + hd - R;
    std::vector<std::vector<uint32_t>> rings{base};
    for (int ring = 1; ring <= kDomeRings; ++ring) {
        const double theta = theta_max * (1.0 - double(ring) / double(kDomeRings + 1));
        std::vector<uint32_t> v;
        for (int k = 0; k < kDomeSides; ++k)
            v.push_back(b.add(snapUm(d.x_mm + R * std::sin(theta) * std::cos(domeAngle(k))),
                              snapUm(d.y_mm + R * std::sin(theta) * std::sin(domeAngle(k))),
                              snapUm(zc + R * std::cos(theta))));
        rings.push_back(v);
    }
    const uint32_t apex = b.add(snapUm(d.x_mm), snapUm(d.y_mm), snapUm(h + hd));
    for (int ring = 0; ring < kDomeRings; ++ring)
        for (int k = 0; k < kDomeSides; ++k) {
            const size_t k0 = size_t(k), k1 = size_t((k + 1) % kDomeSides);
            const std::vector<uint32_t>&lo = rings[size_t(ring)], &hi = rings[size_t(ring + 1)];
            b.tri(lo[k0], lo[k1], hi[k1]);
            b.tri(lo[k0], hi[k1], hi[k0]);
        }
    const std::vector<uint32_t>& last = rings.back();
    for (int k = 0; k < kDomeSides; ++k) b.tri(last[size_t(k)], last[size_t((k + 1) % kDomeSides)], apex);
}

}  // namespace

JoinedBody meshPlateBody(const PlateSpec& s, bool joined) {
    assert(s.height_mm > s.bottom_mm && (!s.outline.edges.empty() || (s.x1_mm > s.x0_mm && s.y1_mm > s.y0_mm)));
    PlateOutline box;
    if (s.outline.edges.empty()) {
        box.points = {{s.x0_mm, s.y0_mm, -1}, {s.x1_mm, s.y0_mm, -1}, {s.x1_mm, s.y1_mm, -1}, {s.x0_mm, s.y1_mm, -1}};
        for (uint32_t k = 0; k < 4; ++k) box.edges.push_back({k, (k + 1) % 4});
    }
    const PlateOutline& o = s.outline.edges.empty() ? box : s.outline;
    JoinedBody body;
    Builder b;
    const double h = s.height_mm, z0 = s.bottom_mm;
    const uint32_t n = uint32_t(o.points.size());
    // Corners of the outline on the bottom (0 .. n-1) and the top (n .. 2n-1).
    for (const double z : {z0, h})
        for (const OutlinePoint& p : o.points) {
            b.add(p.x_mm, p.y_mm, z);
            body.lattice_id.push_back(p.lattice);
        }
    std::vector<std::array<uint32_t, 2>> bottom, top;
    for (const PlateOutline::Edge& e : o.edges) {
        bottom.push_back({e.a, e.b});
        top.push_back({e.a + n, e.b + n});
    }
    for (const auto& t : triangulateSegments(b.mesh.positions, bottom)) b.tri(t[0], t[2], t[1]);  // facing down
    // The dots' base octagons are loops of the top: the region inside one is its dome's.
    std::vector<std::vector<uint32_t>> bases;
    for (const LegendDot& d : s.dots) {
        std::vector<uint32_t> ring;
        for (const Vec3& p : domeBase(d, s.standard, h)) {
            ring.push_back(b.add(p.x, p.y, p.z));
            body.lattice_id.push_back(-1);
        }
        for (size_t k = 0; k < ring.size(); ++k) top.push_back({ring[k], ring[(k + 1) % ring.size()]});
        bases.push_back(ring);
    }
    for (const auto& t : triangulateSegments(b.mesh.positions, top)) b.tri(t[0], t[1], t[2]);
    // The sides: the outline runs with the plate on its left, so the outward
    // normal of edge a -> b is (b - a) x up. A side that starts above the bed
    // stands on the pillar below it (a no-data pit). Every corner carries
    // each height a side meets it at, and each side zips up through the
    // heights of both its corners, so no corner line has a T-junction.
    std::vector<double> from(o.edges.size(), 0.0);
    std::vector<std::vector<std::pair<double, uint32_t>>> column(n);  // per outline point: (z, vertex), by z
    for (uint32_t v = 0; v < n; ++v) column[v] = {{z0, v}, {h, v + n}};
    auto addHeight = [&](uint32_t v, double z) {
        for (const auto& [zz, id] : column[v])
            if (zz == z) return;
        column[v].push_back({z, b.add(o.points[v].x_mm, o.points[v].y_mm, z)});
        body.lattice_id.push_back(o.points[v].lattice);
        std::sort(column[v].begin(), column[v].end());
    };
    if (joined)
        for (uint32_t v = 0; v < n && v < s.point_heights_mm.size(); ++v)
            for (const double z : s.point_heights_mm[v])
                if (z > z0 && z < h) addHeight(v, z);
    for (size_t k = 0; k < o.edges.size(); ++k) {
        from[k] = joined && k < s.side_from_mm.size() ? std::max(z0, s.side_from_mm[k]) : z0;
        if (from[k] > z0 && from[k] < h) {
            addHeight(o.edges[k].a, from[k]);
            addHeight(o.edges[k].b, from[k]);
        }
    }
    for (size_t k = 0; k < o.edges.size(); ++k) {
        if (from[k] >= h) continue;
        std::vector<uint32_t> l, r;
        for (const auto& [z, id] : column[o.edges[k].a])
            if (z >= from[k]) l.push_back(id);
        for (const auto& [z, id] : column[o.edges[k].b])
            if (z >= from[k]) r.push_back(id);
        // Advance the side whose next point is lower (left on ties).
        size_t li = 0, ri = 0;
        while (li + 1 < l.size() || ri + 1 < r.size()) {
            const bool left = ri + 1 == r.size() ||
                              (li + 1 < l.size() && b.mesh.positions[l[li + 1]].z <= b.mesh.positions[r[ri + 1]].z);
            if (left) {
                b.tri(l[li], r[ri], l[li + 1]);
                ++li;
            } else {
                b.tri(l[li], r[ri], r[ri + 1]);
                ++ri;
            }
        }
    }
    for (size_t k = 0; k < s.dots.size(); ++k) {
        const size_t before = b.mesh.positions.size();
        addDome(b, s.dots[k], s.standard, h, bases[k]);
        body.lattice_id.resize(body.lattice_id.size() + (b.mesh.positions.size() - before), -1);
    }
    body.mesh = std::move(b.mesh);
    return body;
}

Mesh meshLegendPlate(const PlateSpec& s) { return meshPlateBody(s, /*joined=*/false).mesh; }

Mesh meshLegendDots(const PlateSpec& s) {
    Builder b;
    for (const LegendDot& d : s.dots) {
        std::vector<uint32_t> base;
        for (const Vec3& p : domeBase(d, s.standard, s.height_mm)) base.push_back(b.add(p.x, p.y, p.z));
        // The base octagon faces down (clockwise seen from above): a fan from its first corner.
        for (int k = 2; k < kDomeSides; ++k) b.tri(base[0], base[size_t(k)], base[size_t(k - 1)]);
        addDome(b, d, s.standard, s.height_mm, base);
    }
    return b.mesh;
}

Mesh meshLegendPlate(const LegendLayout& l, double plate_height_mm) {
    if (l.dots.empty()) return {};
    PlateSpec s;
    s.x1_mm = l.width_mm;
    s.y1_mm = l.depth_mm;
    s.height_mm = plate_height_mm;
    s.dots = l.dots;
    s.standard = l.standard;
    return meshLegendPlate(s);
}

}  // namespace tsf
