// Kernel-generic implementation of detail::geometricChecks*. Include only from
// the instantiation files (cgal_checks_epick.cpp, cgal_checks_epeck.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <iterator>
#include <optional>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include "verify/detail/cgal_checks.h"
#include "verify/triangle_bvh.h"

// On near-degenerate contacts CGAL's preconditions fail in the filtered
// kernel and throw; solid_checks.cpp catches that and redoes the check with
// the exact kernel. So they must stay on in the Release build too, which
// defines NDEBUG: CMakeLists.txt defines CGAL_DEBUG everywhere.
static_assert(CGAL_PRECONDITIONS_ENABLED, "CGAL's preconditions are off: build with CGAL_DEBUG (CMakeLists.txt)");

namespace tsf::detail {

inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Exact shortcuts for the planes a terrain mesh is made of: horizontal
// tops and bottoms (and any plane x_k = const), and vertical walls (a
// triangle with two corners at one (x, y)). In such planes the general
// predicates are degenerate, and CGAL's filtered kernel falls back to exact
// arithmetic for each of them. Here the side of a point comes from comparing
// coordinates, or from CGAL's 2D orientation in plan (filtered, exact), and
// positions within the plane from the 2D orientation in a projection onto
// two axes that maps the plane one-to-one (it may mirror the plane, which
// flips every orientation alike and changes no answer below).
namespace flat {

using P2 = CGAL::Exact_predicates_inexact_constructions_kernel::Point_2;

inline double coord(const Vec3& p, int k) { return k == 0 ? p.x : (k == 1 ? p.y : p.z); }

inline int orient2(const Vec3& p, const Vec3& q, const Vec3& r, int i, int j) {
    return int(CGAL::orientation(P2(coord(p, i), coord(p, j)), P2(coord(q, i), coord(q, j)),
                                 P2(coord(r, i), coord(r, j))));
}

struct Plane {
    int axis = -1;    // x_axis = c, or -1: the vertical plane through p and q (in plan)
    double c = 0;
    Vec3 p, q;        // vertical plane: two points of different (x, y)
    int i = 0, j = 1;  // the projection for orientations within the plane

    // -1, 0, +1: below, in, above the plane (the sign is consistent, its meaning arbitrary).
    int side(const Vec3& r) const {
        if (axis >= 0) {
            const double x = coord(r, axis);
            return x > c ? 1 : (x < c ? -1 : 0);
        }
        if ((r.x == p.x && r.y == p.y) || (r.x == q.x && r.y == q.y)) return 0;
        return orient2(p, q, r, 0, 1);
    }
    int orient(const Vec3& a, const Vec3& b, const Vec3& r) const { return orient2(a, b, r, i, j); }
};

// Which of those planes the triangle (a, b, c) is in, as one byte, computed
// once per triangle (planeCode) and turned into a Plane per pair
// (planeFromCode): 0 none; 1 + k the axis plane x_k = const; 4, 5, 6 the
// vertical plane whose two verticals hold corners (a, b), (b, c) or (c, a).
// A triangle with area is in at most one axis plane.
inline uint8_t planeCode(const Vec3& a, const Vec3& b, const Vec3& c) {
    for (int k : {2, 0, 1})
        if (coord(a, k) == coord(b, k) && coord(b, k) == coord(c, k)) return uint8_t(1 + k);
    auto samePlan = [](const Vec3& u, const Vec3& v) { return u.x == v.x && u.y == v.y; };
    const Vec3 *p, *q;
    uint8_t code;
    if (samePlan(a, b)) p = &a, q = &c, code = 4;
    else if (samePlan(b, c)) p = &b, q = &a, code = 5;
    else if (samePlan(c, a)) p = &c, q = &b, code = 6;
    else return 0;
    if (samePlan(*p, *q)) return 0;  // no area (excluded before)
    return code;
}

inline std::optional<Plane> planeFromCode(uint8_t code, const Vec3& a, const Vec3& b, const Vec3& c) {
    if (code == 0) return std::nullopt;
    Plane pl;
    if (code <= 3) {
        const int k = code - 1;
        pl.axis = k;
        pl.c = coord(a, k);
        pl.i = (k + 1) % 3;
        pl.j = (k + 2) % 3;
        return pl;
    }
    if (code == 4) pl.p = a, pl.q = c;
    else if (code == 5) pl.p = b, pl.q = a;
    else pl.p = c, pl.q = b;
    // (x, z) maps a vertical plane one-to-one unless it runs north-south (x = const).
    pl.i = pl.p.x != pl.q.x ? 0 : 1;
    pl.j = 2;
    return pl;
}

// Is the direction x - v inside the closed angle of the triangle (v, a, b)
// at v? (All four points in the plane.)
inline bool inAngle(const Plane& pl, const Vec3& v, const Vec3& a, const Vec3& b, const Vec3& x) {
    const int o = pl.orient(v, a, b);
    return pl.orient(v, a, x) * o >= 0 && pl.orient(v, x, b) * o >= 0;
}

// Triangles sharing the edge u-v, the one with far corner c in the plane:
// they overlap only if the other's far corner d is in the plane too, on c's
// side of u-v.
inline bool sharedEdge(const Plane& pl, const Vec3& u, const Vec3& v, const Vec3& c, const Vec3& d) {
    if (pl.side(d) != 0) return false;  // not coplanar
    return pl.orient(u, v, c) == pl.orient(u, v, d);
}

// Triangles sharing the corner v, (v, a1, b1) in the plane and (v, a2, b2)
// the other: nullopt when the other crosses the plane at v (CGAL decides).
inline std::optional<bool> sharedCorner(const Plane& pl, const Vec3& v, const Vec3& a1, const Vec3& b1, const Vec3& a2,
                                        const Vec3& b2) {
    const int sa = pl.side(a2), sb = pl.side(b2);
    if (sa != 0 && sa == sb) return false;  // touches the plane at v only
    if (sa == 0 && sb == 0)  // coplanar: do their angles at v overlap?
        return inAngle(pl, v, a1, b1, a2) || inAngle(pl, v, a1, b1, b2) || inAngle(pl, v, a2, b2, a1) ||
               inAngle(pl, v, a2, b2, b1);
    // One far corner w in the plane, the other off it: the other triangle
    // meets the plane in the segment v-w.
    if (sa == 0) return inAngle(pl, v, a1, b1, a2);
    if (sb == 0) return inAngle(pl, v, a1, b1, b2);
    return std::nullopt;
}

// Triangles that share no corner, (a1, b1, c1) in the plane and `o` the
// other, whose corners are in the plane or all on one side of it (it touches
// the plane without crossing it): they meet exactly where the part of `o` in
// the plane (a corner, an edge, or all of it) meets the first triangle, a
// question within the plane. nullopt when `o` crosses the plane.
inline std::optional<bool> touchingPlane(const Plane& pl, const Vec3& a1, const Vec3& b1, const Vec3& c1,
                                         const std::array<const Vec3*, 3>& o) {
    int side[3], on = 0, sign = 0;
    for (int i = 0; i < 3; ++i) {
        side[i] = pl.side(*o[i]);
        if (side[i] == 0) {
            ++on;
        } else {
            if (sign != 0 && side[i] != sign) return std::nullopt;  // crosses
            sign = side[i];
        }
    }
    if (on == 0) return false;  // strictly on one side
    // 2D orientations within the plane; the projection may mirror it, which
    // flips every sign alike.
    auto orient = [&](const Vec3& u, const Vec3& v, const Vec3& w) { return pl.orient(u, v, w); };
    const int ccw = orient(a1, b1, c1);  // nonzero: the triangle has area
    auto inside = [&](const Vec3& x) {   // in the closed triangle
        return orient(a1, b1, x) * ccw >= 0 && orient(b1, c1, x) * ccw >= 0 && orient(c1, a1, x) * ccw >= 0;
    };
    // Do the closed segments u-v and p-q meet? (All in the plane.)
    auto segmentsMeet = [&](const Vec3& u, const Vec3& v, const Vec3& p, const Vec3& q) {
        const int o1 = orient(u, v, p), o2 = orient(u, v, q), o3 = orient(p, q, u), o4 = orient(p, q, v);
        if (o1 * o2 < 0 && o3 * o4 < 0) return true;
        auto within = [&](const Vec3& x, const Vec3& y, const Vec3& z) {  // z on the segment x-y, given collinear
            return std::min(coord(x, pl.i), coord(y, pl.i)) <= coord(z, pl.i) &&
                   coord(z, pl.i) <= std::max(coord(x, pl.i), coord(y, pl.i)) &&
                   std::min(coord(x, pl.j), coord(y, pl.j)) <= coord(z, pl.j) &&
                   coord(z, pl.j) <= std::max(coord(x, pl.j), coord(y, pl.j));
        };
        return (o1 == 0 && within(u, v, p)) || (o2 == 0 && within(u, v, q)) || (o3 == 0 && within(p, q, u)) ||
               (o4 == 0 && within(p, q, v));
    };
    auto segmentMeetsTriangle = [&](const Vec3& u, const Vec3& v) {
        return inside(u) || inside(v) || segmentsMeet(u, v, a1, b1) || segmentsMeet(u, v, b1, c1) ||
               segmentsMeet(u, v, c1, a1);
    };
    std::array<const Vec3*, 3> in{};
    for (int i = 0, k = 0; i < 3; ++i)
        if (side[i] == 0) in[k++] = o[i];
    if (on == 1) return inside(*in[0]);
    if (on == 2) return segmentMeetsTriangle(*in[0], *in[1]);
    // Coplanar: an edge of one crosses or touches the other, or one holds the other.
    const Vec3 &a2 = *o[0], &b2 = *o[1], &c2 = *o[2];
    if (segmentMeetsTriangle(a2, b2) || segmentMeetsTriangle(b2, c2) || segmentMeetsTriangle(c2, a2)) return true;
    const int ccw2 = orient(a2, b2, c2);
    return orient(a2, b2, a1) * ccw2 >= 0 && orient(b2, c2, a1) * ccw2 >= 0 && orient(c2, a2, a1) * ccw2 >= 0;
}

}  // namespace flat

// Do the triangles a and b of a closed, manifold, consistently oriented
// soup meet other than in the vertices or the edge they share by index?
// The same answer as CGAL 5.5's PMP::self_intersections on the
// Surface_mesh of that soup (do_faces_intersect): in such a soup two
// triangles share an edge exactly when they share two vertex indices, and
// a vertex exactly when they share one index; sharing an edge, they meet
// when coplanar and folded onto each other; sharing a vertex, when the
// edge opposite it in one meets the other (equivalently: their
// intersection is more than that vertex). Flat triangles are decided by the
// shortcuts above, everything else by CGAL's predicates. Neither triangle
// may have three collinear corners.
template <class K>
bool trianglesMeet(const std::vector<typename K::Point_3>& points, const std::vector<Vec3>& pos,
                   const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b, uint8_t code_a,
                   uint8_t code_b) {
    using Triangle = typename K::Triangle_3;
    using Segment = typename K::Segment_3;
    int ia = -1, ib = -1, shared = 0;  // the first shared corner, in a and in b
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
            if (a[i] == b[j]) {
                if (shared++ == 0) {
                    ia = i;
                    ib = j;
                }
                break;
            }
    const std::optional<flat::Plane> pa = flat::planeFromCode(code_a, pos[a[0]], pos[a[1]], pos[a[2]]);
    const std::optional<flat::Plane> pb = flat::planeFromCode(code_b, pos[b[0]], pos[b[1]], pos[b[2]]);
    if (shared >= 2) {
        // A shared edge u-v: they overlap only when the four corners are
        // coplanar and the opposite corners lie on the same side of u-v.
        auto inB = [&](uint32_t x) { return x == b[0] || x == b[1] || x == b[2]; };
        uint32_t common[3] = {0, 0, 0}, c = a[0];
        int k = 0;
        for (int i = 0; i < 3; ++i) {
            if (inB(a[i])) common[k++] = a[i];
            else c = a[i];
        }
        const uint32_t u = common[0], v = common[1];
        // Three shared corners: the opposite corners coincide, and the
        // triangles overlap (as CGAL finds across any of their edges).
        if (shared == 3) c = common[2];
        uint32_t d = c;
        for (int j = 0; j < 3; ++j)
            if (b[j] != u && b[j] != v) d = b[j];
        if (pa) return flat::sharedEdge(*pa, pos[u], pos[v], pos[c], pos[d]);
        if (pb) return flat::sharedEdge(*pb, pos[u], pos[v], pos[d], pos[c]);
        const auto &pu = points[u], &pv = points[v], &pc = points[c], &pd = points[d];
        return CGAL::coplanar(pu, pv, pc, pd) && CGAL::coplanar_orientation(pu, pv, pc, pd) == CGAL::POSITIVE;
    }
    if (shared == 1) {
        const Vec3& v = pos[a[ia]];
        const Vec3 &a1 = pos[a[(ia + 1) % 3]], &b1 = pos[a[(ia + 2) % 3]];
        const Vec3 &a2 = pos[b[(ib + 1) % 3]], &b2 = pos[b[(ib + 2) % 3]];
        std::optional<bool> known;
        if (pa) known = flat::sharedCorner(*pa, v, a1, b1, a2, b2);
        if (!known && pb) known = flat::sharedCorner(*pb, v, a2, b2, a1, b1);
        if (known) return *known;
    }
    const Triangle ta(points[a[0]], points[a[1]], points[a[2]]);
    const Triangle tb(points[b[0]], points[b[1]], points[b[2]]);
    if (shared == 1) {
        // A shared corner: they meet elsewhere only if the edge opposite it in
        // one triangle meets the other triangle.
        const Segment sa(points[a[(ia + 1) % 3]], points[a[(ia + 2) % 3]]);
        const Segment sb(points[b[(ib + 1) % 3]], points[b[(ib + 2) % 3]]);
        return CGAL::do_intersect(ta, sb) || CGAL::do_intersect(tb, sa);
    }
    // Nothing shared: a triangle that does not cross the other's plane meets
    // it only within that plane (decided there, exactly).
    auto corners = [&](const std::array<uint32_t, 3>& t) {
        return std::array<const Vec3*, 3>{&pos[t[0]], &pos[t[1]], &pos[t[2]]};
    };
    if (pa)
        if (const auto known = flat::touchingPlane(*pa, pos[a[0]], pos[a[1]], pos[a[2]], corners(b))) return *known;
    if (pb)
        if (const auto known = flat::touchingPlane(*pb, pos[b[0]], pos[b[1]], pos[b[2]], corners(a))) return *known;
    return CGAL::do_intersect(ta, tb);
}

template <class K>
GeometricFindings geometricChecks(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs, bool self_intersections,
                                  const TriangleBvh* bvh, unsigned workers) {
    using P = typename K::Point_3;
    using SM = CGAL::Surface_mesh<P>;
    namespace PMP = CGAL::Polygon_mesh_processing;
    assert(topo.nonfinite_vertices.empty());

    GeometricFindings out;
    auto t0 = std::chrono::steady_clock::now();

    std::vector<P> points;
    points.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);

    // Usable triangles: indices in range and distinct.
    std::vector<uint8_t> usable(mesh.triangles.size(), 1);
    for (uint32_t t : topo.out_of_range_triangles) usable[t] = 0;
    for (uint32_t t : topo.index_degenerate_triangles) usable[t] = 0;

    // Zero-area triangles: three collinear points, decided exactly.
    typename K::Collinear_3 collinear = K().collinear_3_object();
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (!usable[t]) continue;
        const auto& q = mesh.triangles[t];
        if (collinear(points[q[0]], points[q[1]], points[q[2]])) out.zero_area_triangles.push_back(uint32_t(t));
    }
    out.degenerate_ms = msSince(t0);

    out.self_intersections_requested = self_intersections;
    if (self_intersections) {
        t0 = std::chrono::steady_clock::now();
        const bool valid_soup =
            topo.nonmanifold_edges.empty() && topo.misoriented_edges.empty() && topo.nonmanifold_vertices.empty();
        std::vector<std::pair<uint32_t, uint32_t>> ids;  // intersecting pairs, original ids, first < second
        if (valid_soup && bvh) {
            // Broad phase: the pairs whose boxes overlap, from the verifier's
            // tree; exact predicates on those only, on `workers` threads.
            // Triangles with collinear corners are left out, as CGAL leaves
            // them out (they are counted as zero-area triangles).
            std::vector<uint8_t>& tested = usable;
            for (uint32_t t : out.zero_area_triangles) tested[t] = 0;
            std::vector<uint8_t> plane(mesh.triangles.size(), 0);
            for (size_t t = 0; t < mesh.triangles.size(); ++t)
                if (tested[t]) {
                    const auto& q = mesh.triangles[t];
                    plane[t] = flat::planeCode(mesh.positions[q[0]], mesh.positions[q[1]], mesh.positions[q[2]]);
                }
            std::vector<std::vector<std::pair<uint32_t, uint32_t>>> found(TriangleBvh::workerCount(workers));
            bvh->forEachOverlappingPair(
                [&](unsigned w, uint32_t a, uint32_t b) {
                    if (!tested[a] || !tested[b]) return;
                    if (trianglesMeet<K>(points, mesh.positions, mesh.triangles[a], mesh.triangles[b], plane[a],
                                         plane[b]))
                        found[w].emplace_back(std::min(a, b), std::max(a, b));
                },
                workers);
            for (const auto& f : found) ids.insert(ids.end(), f.begin(), f.end());
            out.mesh_built = true;
        } else {
            // The soup handed to CGAL: usable triangles, and their original ids.
            std::vector<std::array<size_t, 3>> polygons;
            std::vector<uint32_t> original;
            for (size_t t = 0; t < mesh.triangles.size(); ++t) {
                if (!usable[t]) continue;
                const auto& tri = mesh.triangles[t];
                polygons.push_back({tri[0], tri[1], tri[2]});
                original.push_back(uint32_t(t));
            }
            // Build a Surface_mesh. A soup our own edge analysis found valid is
            // added as is; anything else goes through orient_polygon_soup, which
            // flips triangles and duplicates points at non-manifold places (the
            // repair is reported, never used for the verdict of the topology checks).
            if (!valid_soup) {
                const size_t before = points.size();
                PMP::orient_polygon_soup(points, polygons);
                out.soup_repaired = true;
                out.points_duplicated = points.size() - before;
            }
            SM sm;
            sm.reserve(typename SM::size_type(points.size()), typename SM::size_type(3 * polygons.size()),
                       typename SM::size_type(polygons.size()));
            std::vector<typename SM::Vertex_index> vid;
            vid.reserve(points.size());
            for (const P& p : points) vid.push_back(sm.add_vertex(p));
            bool all_added = true;
            for (const auto& q : polygons) {
                if (sm.add_face(vid[q[0]], vid[q[1]], vid[q[2]]) == SM::null_face()) {
                    all_added = false;
                    break;
                }
            }
            out.mesh_built = all_added;
            out.cgal_mesh_used = true;
            out.build_ms = msSince(t0);
            t0 = std::chrono::steady_clock::now();
            // CGAL lists a degenerate face f as (f, f); those are already
            // counted as zero-area triangles and are dropped here.
            if (out.mesh_built) {
                std::vector<std::pair<typename SM::Face_index, typename SM::Face_index>> pairs;
                PMP::self_intersections(sm, std::back_inserter(pairs));
                ids.reserve(pairs.size());
                for (const auto& [f, g] : pairs) {
                    if (f == g) continue;
                    uint32_t a = original[size_t(f)], b = original[size_t(g)];
                    if (a > b) std::swap(a, b);
                    ids.emplace_back(a, b);
                }
            }
        }
        if (out.mesh_built) {
            std::sort(ids.begin(), ids.end());
            ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
            out.intersecting_pair_count = ids.size();
            if (ids.size() > max_pairs) ids.resize(max_pairs);
            for (const auto& [a, b] : ids) out.intersection_points.push_back(intersectionPoint(mesh, a, b));
            out.intersecting_pairs = std::move(ids);
            out.self_intersection_ms = msSince(t0);
        }
    }

    // Volumes: per component, as a sum of signed tetrahedra against a point of
    // the component, in the kernel's number type (exact with Epeck).
    if (topo.isClosedOrientedManifold()) {
        t0 = std::chrono::steady_clock::now();
        typename K::Compute_volume_3 tetra = K().compute_volume_3_object();
        using FT = typename K::FT;
        // Summed pairwise: a lazy exact number records every operation, and a
        // million-term running sum is a million-deep chain that overflows the
        // stack when evaluated or freed; pairwise the depth is log2(terms).
        auto pairwiseSum = [](std::vector<FT>& terms) {
            if (terms.empty()) return FT(0);
            while (terms.size() > 1) {
                const size_t half = terms.size() / 2;
                for (size_t i = 0; i < half; ++i) terms[i] = terms[2 * i] + terms[2 * i + 1];
                if (terms.size() % 2) terms[half] = terms.back();
                terms.resize(half + terms.size() % 2);
            }
            return terms[0];
        };
        std::vector<FT> per_component;
        std::vector<FT> terms;
        for (const MeshComponent& c : topo.components) {
            const P o = points[mesh.triangles[c.triangles.front()][0]];
            terms.clear();
            for (uint32_t t : c.triangles) {
                const auto& tri = mesh.triangles[t];
                terms.push_back(tetra(o, points[tri[0]], points[tri[1]], points[tri[2]]));
            }
            const FT v = pairwiseSum(terms);
            out.component_volume_mm3.push_back(CGAL::to_double(v));
            out.component_volume_sign.push_back(int(CGAL::sign(v)));  // exact with Epeck
            per_component.push_back(v);
        }
        const FT total = pairwiseSum(per_component);
        out.volume_mm3 = CGAL::to_double(total);
        out.volumes_computed = true;
        out.volume_ms = msSince(t0);
    }
    return out;
}

}  // namespace tsf::detail
