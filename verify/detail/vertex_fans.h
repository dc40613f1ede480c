// The triangles around one vertex, as a cycle, and an exact certificate that
// they meet only where the mesh's indices say they do: the self-intersection
// test (cgal_checks_impl.h) decides all the pairs of a vertex's fan at once
// with it, rather than pair by pair. Internal to verify/.
//
// Why it holds. Let v's triangles (v, a_i, b_i), in the winding order, form
// one closed cycle (b_i = a_{i+1}), and let q - v be a direction along which
// each of them projects with one and the same non-zero orientation: each
// projects one-to-one onto a wedge at v' of less than half a turn, turning
// the same way. If the wedges turn once around v' in all, they tile the
// plane around v' once: two wedges not next to each other share only v',
// two next to each other only their common ray. Two triangles of the fan
// then share only the points whose projections both hold, and as each
// projects one-to-one, those are v, or the edge v-b_i that two neighbours
// share. So no pair of the fan meets other than in v or their shared edge,
// which is CGAL's verdict on such pairs (do_faces_intersect: a shared vertex
// meets when an opposite edge meets the other triangle; a shared edge when
// coplanar with the far corners on one side of it). Every test is an exact
// orientation of four double points (CGAL's filtered predicate), so the
// direction q, computed in doubles, need not be exact: any q would do, the
// sum of the triangles' normals just makes one likely to.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "gen/geometry/mesh.h"

namespace tsf::detail {

/// Triangle t seen from its corner at the fan's vertex v: the corner after v
/// in t's winding (next) and the one before it (prev).
struct FanCorner {
    uint32_t t = 0, next = 0, prev = 0;
};

/// The lowest vertex index triangles a and b share, or UINT32_MAX if they
/// share none: the fan where a pair that shares an edge (two indices) is
/// decided, once.
inline uint32_t lowestSharedIndex(const std::array<uint32_t, 3>& a, const std::array<uint32_t, 3>& b) {
    uint32_t low = UINT32_MAX;
    for (uint32_t x : a)
        if (x == b[0] || x == b[1] || x == b[2]) low = std::min(low, x);
    return low;
}

/// Puts the corners in cycle order (each triangle followed by its neighbour
/// across the edge v-prev, whose `next` is that `prev`) and returns true
/// when they form exactly one closed cycle; false otherwise (an open fan, a
/// pinched vertex, two triangles leaving v along one edge the same way), in
/// which case the order is unspecified.
inline bool orderFan(std::vector<FanCorner>& fan) {
    const size_t k = fan.size();
    if (k < 3) return false;
    if (k <= 16) {
        // A few triangles (nearly every vertex): in place, each followed by
        // the one whose `next` is its `prev`.
        for (size_t i = 0; i + 1 < k; ++i) {
            size_t j = i + 1;
            while (j < k && fan[j].next != fan[i].prev) ++j;
            if (j == k) return false;  // open here, or closed too early: more than one cycle
            std::swap(fan[i + 1], fan[j]);
        }
        return fan[k - 1].prev == fan[0].next;
    }
    std::sort(fan.begin(), fan.end(), [](const FanCorner& x, const FanCorner& y) { return x.next < y.next; });
    for (size_t i = 1; i < k; ++i)
        if (fan[i].next == fan[i - 1].next) return false;
    std::vector<FanCorner> cycle;
    cycle.reserve(k);
    std::vector<uint8_t> seen(k, 0);
    size_t at = 0;
    for (size_t step = 0; step < k; ++step) {
        if (seen[at]) return false;  // back to a triangle before all were seen: more than one cycle
        seen[at] = 1;
        cycle.push_back(fan[at]);
        const uint32_t want = fan[at].prev;
        const auto it = std::lower_bound(fan.begin(), fan.end(), want,
                                         [](const FanCorner& x, uint32_t w) { return x.next < w; });
        if (it == fan.end() || it->next != want) return false;  // open: no triangle continues the fan
        at = size_t(it - fan.begin());
    }
    if (at != 0) return false;
    fan.swap(cycle);
    return true;
}

/// The certificate above, for the fan of v in cycle order (orderFan): true
/// only if no two of its triangles meet other than in v or the edge they
/// share. False says nothing (the pairs must then be decided one by one).
/// Exact.
inline bool fanMeetsOnlyAlongItsEdges(const std::vector<Vec3>& pos, uint32_t v, const std::vector<FanCorner>& fan) {
    using P = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    const Vec3& o = pos[v];
    // The direction: the sum of the triangles' (unnormalised) normals,
    // scaled to the fan's size so that v + it is a point apart from v.
    double n[3] = {0, 0, 0}, size = 0;
    for (const FanCorner& c : fan) {
        const Vec3 &a = pos[c.next], &b = pos[c.prev];
        const double u[3] = {a.x - o.x, a.y - o.y, a.z - o.z}, w[3] = {b.x - o.x, b.y - o.y, b.z - o.z};
        n[0] += u[1] * w[2] - u[2] * w[1];
        n[1] += u[2] * w[0] - u[0] * w[2];
        n[2] += u[0] * w[1] - u[1] * w[0];
        size = std::max({size, std::fabs(u[0]), std::fabs(u[1]), std::fabs(u[2])});
    }
    const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (!(len > 0) || !std::isfinite(len) || !(size > 0)) return false;
    const double s = size / len;
    const P pv(o.x, o.y, o.z), pq(o.x + n[0] * s, o.y + n[1] * s, o.z + n[2] * s);
    auto point = [&](uint32_t i) { return P(pos[i].x, pos[i].y, pos[i].z); };
    // Seen along q - v, the orientation of the directions v -> x, v -> y.
    auto turn = [&](const P& x, const P& y) { return int(CGAL::orientation(pv, x, y, pq)); };
    // The reference direction for the winding: any one counts the turns;
    // a point inside the first wedge, at uneven weights, is unlikely to be
    // exactly in line with v and a corner (the lattice puts many corners in
    // line with v, and an exact zero costs the predicate its exact fallback).
    const Vec3 &a0 = pos[fan[0].next], &b0 = pos[fan[0].prev];
    const P r(o.x + 0.6180339887 * (a0.x - o.x) + 0.3090169944 * (b0.x - o.x),
              o.y + 0.6180339887 * (a0.y - o.y) + 0.3090169944 * (b0.y - o.y),
              o.z + 0.6180339887 * (a0.z - o.z) + 0.3090169944 * (b0.z - o.z));
    int sense = 0, winding = 0;
    for (const FanCorner& c : fan) {
        const P a = point(c.next), b = point(c.prev);
        const int t = turn(a, b);
        if (t == 0 || (sense != 0 && t != sense)) return false;
        sense = t;
        // The wedge from a to b (less than half a turn) passes r when r is
        // past a and not past b: each full turn is counted once, at the
        // wedge whose half-open range (a, b] holds r.
        if (turn(a, r) == sense && turn(r, b) != -sense) ++winding;
    }
    return winding == 1;
}

}  // namespace tsf::detail
