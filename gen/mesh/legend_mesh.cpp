#include "gen/mesh/legend_mesh.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <array>
#include <map>
#include <numbers>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

namespace tsf {
namespace {

using K = CGAL::Exact_predicates_exact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<int64_t, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_intersections_tag>;

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

Mesh meshLegendPlate(const PlateSpec& s) {
    assert(s.height_mm > 0 && s.x1_mm > s.x0_mm && s.y1_mm > s.y0_mm);
    Builder b;
    const double r = s.standard.dot_base_mm / 2, h = s.height_mm;

    Cdt cdt;
    auto insert = [&cdt](double x, double y) { return cdt.insert(K::Point_2(x, y)); };
    const Cdt::Vertex_handle corner[4] = {insert(s.x0_mm, s.y0_mm), insert(s.x1_mm, s.y0_mm), insert(s.x1_mm, s.y1_mm),
                                          insert(s.x0_mm, s.y1_mm)};
    for (int k = 0; k < 4; ++k) cdt.insert_constraint(corner[k], corner[(k + 1) % 4]);
    std::vector<std::vector<Cdt::Vertex_handle>> bases;
    for (const LegendDot& d : s.dots) {
        std::vector<Cdt::Vertex_handle> ring;
        for (const Vec3& p : domeBase(d, s.standard, h)) ring.push_back(insert(p.x, p.y));
        for (int k = 0; k < kDomeSides; ++k) cdt.insert_constraint(ring[size_t(k)], ring[size_t((k + 1) % kDomeSides)]);
        bases.push_back(ring);
    }
    for (const PlateSegment& e : s.top_edges) cdt.insert_constraint(K::Point_2(e.ax, e.ay), K::Point_2(e.bx, e.by));

    // Top and bottom copies of every triangulation vertex.
    std::map<Cdt::Vertex_handle, std::pair<uint32_t, uint32_t>> ids;
    for (auto v = cdt.finite_vertices_begin(); v != cdt.finite_vertices_end(); ++v) {
        const double x = CGAL::to_double(v->point().x()), y = CGAL::to_double(v->point().y());
        ids[v] = {b.add(x, y, h), b.add(x, y, 0)};
    }
    // A face inside a dot's base is the dome's, not the plate top's.
    auto insideDot = [&](const K::Point_2& c) {
        const double x = CGAL::to_double(c.x()), y = CGAL::to_double(c.y());
        for (const LegendDot& d : s.dots)
            if (std::hypot(x - d.x_mm, y - d.y_mm) < r * std::cos(std::numbers::pi / kDomeSides)) return true;
        return false;
    };
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        const auto a = f->vertex(0), c = f->vertex(1), d = f->vertex(2);  // counter-clockwise
        b.tri(ids[a].second, ids[d].second, ids[c].second);                // bottom, normal -z
        if (!insideDot(CGAL::centroid(a->point(), c->point(), d->point())))
            b.tri(ids[a].first, ids[c].first, ids[d].first);
    }
    // Sides: every triangulation edge on the outline, outward.
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
        Cdt::Face_handle f = e->first;
        int i = e->second;
        if (cdt.is_infinite(f)) {  // look from the finite side
            const Cdt::Face_handle nb = f->neighbor(i);
            i = nb->index(f);
            f = nb;
        }
        if (!cdt.is_infinite(f->neighbor(i))) continue;
        // The finite face runs along the edge from ccw(i) to cw(i) (counter-clockwise).
        const auto p = f->vertex(Cdt::ccw(i)), q = f->vertex(Cdt::cw(i));
        b.tri(ids[p].second, ids[q].second, ids[q].first);
        b.tri(ids[p].second, ids[q].first, ids[p].first);
    }
    // Domes on the base octagons.
    for (size_t n = 0; n < s.dots.size(); ++n) {
        std::vector<uint32_t> base;
        for (const auto& v : bases[n]) base.push_back(ids[v].first);
        addDome(b, s.dots[n], s.standard, h, base);
    }
    return b.mesh;
}

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
