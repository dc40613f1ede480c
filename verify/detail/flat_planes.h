// Exact shortcuts for the planes a terrain mesh is made of, shared by the
// self-intersection test (cgal_checks_impl.h) and the printability check's
// planar regions (printability.cpp). Internal to verify/.
#pragma once

#include <array>
#include <cstdint>
#include <optional>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "gen/geometry/mesh.h"

namespace tsf::detail {

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

// Is d in the plane of the triangle (a, b, c), when that plane is one of
// these? nullopt when it is not (ask the general predicate). Exact; when
// a, b, c are collinear the answer says nothing.
inline std::optional<bool> inPlaneOf(const Vec3& a, const Vec3& b, const Vec3& c, const Vec3& d) {
    const std::optional<Plane> pl = planeFromCode(planeCode(a, b, c), a, b, c);
    if (!pl) return std::nullopt;
    return pl->side(d) == 0;
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

}  // namespace tsf::detail
