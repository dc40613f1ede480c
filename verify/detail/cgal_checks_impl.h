// Kernel-generic implementation of detail::geometricChecks*. Include only from
// the instantiation files (cgal_checks_epick.cpp, cgal_checks_epeck.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <atomic>
#include <cassert>
#include <chrono>
#include <iterator>
#include <optional>
#include <type_traits>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
// With the exact-construction kernel, g++ 12 warns that a temporary in
// CGAL's own self_intersections.h (line 215) may be used uninitialised: a
// false alarm inside CGAL, silenced for that header only.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#pragma GCC diagnostic pop
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include "verify/detail/cgal_checks.h"
#include "verify/detail/flat_planes.h"
#include "verify/detail/pairwise_sum.h"
#include "verify/column_grid.h"
#include "verify/detail/vertex_fans.h"
#include "gen/util/workers.h"
#include "verify/mesh_topology.h"

// On near-degenerate contacts CGAL's preconditions fail in the filtered
// kernel and throw; solid_checks.cpp catches that and redoes the check with
// the exact kernel. So they must stay on in the Release build too, which
// defines NDEBUG: CMakeLists.txt defines CGAL_DEBUG everywhere.
static_assert(CGAL_PRECONDITIONS_ENABLED, "CGAL's preconditions are off: build with CGAL_DEBUG (CMakeLists.txt)");

namespace tsf::detail {

inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// The mesh's vertices as the kernel's points. With the filtered kernel a
// point is three doubles, made from the position where it is read: a copy
// of every vertex cost 153 MiB on a 1000 x 1000 model, alive through the
// self-intersection test beside the column grid. The exact-construction
// kernel's points share reference-counted numbers and are made once.
template <class K>
class KernelPoints {
public:
    using P = typename K::Point_3;
    static constexpr bool kMadeWhenRead = std::is_same_v<K, CGAL::Exact_predicates_inexact_constructions_kernel>;

    explicit KernelPoints(const std::vector<Vec3>& positions) : positions_(&positions) {
        if constexpr (!kMadeWhenRead) {
            made_.reserve(positions.size());
            for (const Vec3& p : positions) made_.emplace_back(p.x, p.y, p.z);
        }
    }
    /// A point by value (filtered kernel) or by reference (exact one).
    decltype(auto) operator[](size_t v) const {
        if constexpr (kMadeWhenRead) {
            const Vec3& p = (*positions_)[v];
            return P(p.x, p.y, p.z);
        } else {
            return (made_[v]);
        }
    }
    size_t size() const { return positions_->size(); }
    /// Every point, in a list of its own (for CGAL's functions that take one).
    std::vector<P> list() const {
        if constexpr (kMadeWhenRead) {
            std::vector<P> all;
            all.reserve(size());
            for (size_t v = 0; v < size(); ++v) all.push_back((*this)[v]);
            return all;
        } else {
            return made_;
        }
    }

private:
    const std::vector<Vec3>* positions_;
    std::vector<P> made_;  // exact kernel only
};

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
bool trianglesMeet(const KernelPoints<K>& points, const std::vector<Vec3>& pos,
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
                                  const ColumnGrid* grid, unsigned workers) {
    using P = typename K::Point_3;
    using SM = CGAL::Surface_mesh<P>;
    namespace PMP = CGAL::Polygon_mesh_processing;
    assert(topo.nonfinite_vertices.empty());

    GeometricFindings out;
    auto t0 = std::chrono::steady_clock::now();

    // The zero-area test on the workers, each a run of triangles; the runs'
    // findings joined in order, so the list is the same for any number of
    // threads. (Points of the exact-construction kernel share
    // reference-counted numbers: they are read on one thread.)
    const unsigned point_workers = KernelPoints<K>::kMadeWhenRead ? workerCount(workers) : 1u;
    const KernelPoints<K> points(mesh.positions);

    // Usable triangles: indices in range and distinct.
    std::vector<uint8_t> usable(mesh.triangles.size(), 1);
    for (uint32_t t : topo.out_of_range_triangles) usable[t] = 0;
    for (uint32_t t : topo.index_degenerate_triangles) usable[t] = 0;

    // Zero-area triangles: three collinear points, decided exactly.
    std::vector<std::vector<uint32_t>> zero_area(point_workers);
    runOnRanges(point_workers, mesh.triangles.size(), [&](unsigned w, size_t begin, size_t end) {
        typename K::Collinear_3 collinear = K().collinear_3_object();
        for (size_t t = begin; t < end; ++t) {
            if (!usable[t]) continue;
            const auto& q = mesh.triangles[t];
            if (collinear(points[q[0]], points[q[1]], points[q[2]])) zero_area[w].push_back(uint32_t(t));
        }
    });
    for (const std::vector<uint32_t>& part : zero_area)
        out.zero_area_triangles.insert(out.zero_area_triangles.end(), part.begin(), part.end());
    out.degenerate_ms = msSince(t0);

    out.self_intersections_requested = self_intersections;
    if (self_intersections) {
        t0 = std::chrono::steady_clock::now();
        const bool valid_soup =
            topo.nonmanifold_edges.empty() && topo.misoriented_edges.empty() && topo.nonmanifold_vertices.empty();
        std::vector<std::pair<uint32_t, uint32_t>> ids;  // intersecting pairs, original ids, first < second
        if (valid_soup && grid) {
            // Broad phase: the pairs of a vertex's fan, and the pairs whose
            // boxes overlap in a column of the grid; exact predicates on
            // those only, on `workers` threads.
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
            std::vector<std::vector<std::pair<uint32_t, uint32_t>>> found(detail::workerCount(workers));
            auto decide = [&](unsigned w, uint32_t a, uint32_t b) {
                if (trianglesMeet<K>(points, mesh.positions, mesh.triangles[a], mesh.triangles[b], plane[a], plane[b]))
                    found[w].emplace_back(std::min(a, b), std::max(a, b));
            };
            // The pairs that share a vertex index (about two thirds of the
            // candidates on a terrain: neighbours in a fan touch), fan by
            // fan: a fan the certificate of vertex_fans.h clears needs no
            // pair tested; another has each of its pairs decided here, a
            // pair sharing an edge at its lower vertex only.
            // The corners are listed a block of vertices at a time, of at
            // most kCornersPerBlock corners on average (64 MB: a 13 M
            // triangle model takes three blocks, and its check's peak of
            // memory does not grow).
            constexpr size_t kCornersPerBlock = size_t(1) << 24;
            const size_t nv = mesh.positions.size();
            const size_t blocks = std::max<size_t>(1, (3 * mesh.triangles.size() + kCornersPerBlock - 1) / kCornersPerBlock);
            for (size_t block = 0; block < blocks; ++block) {
                const size_t first = nv * block / blocks, last = nv * (block + 1) / blocks;
                const VertexCorners corners = cornersByVertex(mesh, &tested, uint32_t(first), uint32_t(last));
                constexpr size_t kVerticesPerTask = 4096;
                std::atomic<size_t> next_vertex{first};
                runOnWorkers(unsigned(found.size()), [&](unsigned w, const std::atomic<bool>& stop) {
                    std::vector<FanCorner> fan;
                    for (size_t task; !stop.load() && (task = next_vertex.fetch_add(kVerticesPerTask)) < last;) {
                        for (size_t v = task; v < std::min(last, task + kVerticesPerTask); ++v) {
                            fan.clear();
                            for (uint32_t e = corners.start[v - first]; e < corners.start[v - first + 1]; ++e) {
                                const uint32_t t = corners.list[e] / 3, i = corners.list[e] % 3;
                                const auto& q = mesh.triangles[t];
                                fan.push_back({t, q[(i + 1) % 3], q[(i + 2) % 3]});
                            }
                            if (fan.size() < 2) continue;
                            if (orderFan(fan) && fanMeetsOnlyAlongItsEdges(mesh.positions, uint32_t(v), fan)) continue;
                            for (size_t i = 0; i + 1 < fan.size(); ++i)
                                for (size_t j = i + 1; j < fan.size(); ++j)
                                    if (lowestSharedIndex(mesh.triangles[fan[i].t], mesh.triangles[fan[j].t]) == v)
                                        decide(w, fan[i].t, fan[j].t);
                        }
                    }
                });
            }
            // The pairs that share no vertex index, from the grid.
            grid->forEachOverlappingPair(
                [&](unsigned w, uint32_t a, uint32_t b) {
                    if (tested[a] && tested[b]) decide(w, a, b);
                },
                workers, true);
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
            std::vector<P> soup_points = points.list();
            if (!valid_soup) {
                const size_t before = soup_points.size();
                PMP::orient_polygon_soup(soup_points, polygons);
                out.soup_repaired = true;
                out.points_duplicated = soup_points.size() - before;
            }
            SM sm;
            sm.reserve(typename SM::size_type(soup_points.size()), typename SM::size_type(3 * polygons.size()),
                       typename SM::size_type(polygons.size()));
            std::vector<typename SM::Vertex_index> vid;
            vid.reserve(soup_points.size());
            for (const P& p : soup_points) vid.push_back(sm.add_vertex(p));
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
        // Each term on its own (on the workers with plain doubles), the sum
        // in one order, pairwise: the same bits for any number of threads,
        // and a depth of log2(terms) for the exact kernel's lazy numbers.
        std::vector<FT> per_component;
        for (const MeshComponent& c : topo.components) {
            const P o = points[mesh.triangles[c.triangles.front()][0]];
            const FT v = pairwiseSum<FT>(c.triangles.size(), point_workers, [&](size_t k) {
                const auto& tri = mesh.triangles[c.triangles[k]];
                return tetra(o, points[tri[0]], points[tri[1]], points[tri[2]]);
            });
            out.component_volume_mm3.push_back(CGAL::to_double(v));
            out.component_volume_sign.push_back(int(CGAL::sign(v)));  // exact with Epeck
            per_component.push_back(v);
        }
        const FT total = pairwiseSum<FT>(per_component.size(), 1, [&](size_t k) { return per_component[k]; });
        out.volume_mm3 = CGAL::to_double(total);
        out.volumes_computed = true;
        out.volume_ms = msSince(t0);
    }
    return out;
}

}  // namespace tsf::detail
