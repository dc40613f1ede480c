// Kernel-generic implementation of detail::geometricChecks*. Include only from
// the instantiation files (cgal_checks_epick.cpp, cgal_checks_epeck.cpp).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <chrono>
#include <iterator>
#include <vector>

#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/intersections.h>

#include "verify/detail/cgal_checks.h"

// On near-degenerate contacts CGAL's preconditions fail in the filtered
// kernel and throw; solid_checks.cpp catches that and redoes the check with
// the exact kernel. So they must stay on in the Release build too, which
// defines NDEBUG: CMakeLists.txt defines CGAL_DEBUG everywhere.
static_assert(CGAL_PRECONDITIONS_ENABLED, "CGAL's preconditions are off: build with CGAL_DEBUG (CMakeLists.txt)");

namespace tsf::detail {

inline double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// A point (mm) on the intersection of two triangles, for locating it.
template <class K>
Vec3 intersectionPoint(const typename K::Triangle_3& a, const typename K::Triangle_3& b) {
    using P = typename K::Point_3;
    auto toVec = [](const P& p) { return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}; };
    auto mean = [&](const auto& pts) {
        Vec3 c;
        for (const P& p : pts) {
            const Vec3 v = toVec(p);
            c = {c.x + v.x, c.y + v.y, c.z + v.z};
        }
        const double n = double(pts.size());
        return Vec3{c.x / n, c.y / n, c.z / n};
    };
    const auto result = CGAL::intersection(a, b);
    if (result) {
        if (const P* p = boost::get<P>(&*result)) return toVec(*p);
        if (const auto* s = boost::get<typename K::Segment_3>(&*result)) return mean(std::vector<P>{s->source(), s->target()});
        if (const auto* t = boost::get<typename K::Triangle_3>(&*result))
            return mean(std::vector<P>{t->vertex(0), t->vertex(1), t->vertex(2)});
        if (const auto* poly = boost::get<std::vector<P>>(&*result)) return mean(*poly);
    }
    // Touching at a vertex or edge that the two triangles do not share by
    // index: the intersection is degenerate; fall back to the centroids' midpoint.
    std::vector<P> all{a.vertex(0), a.vertex(1), a.vertex(2), b.vertex(0), b.vertex(1), b.vertex(2)};
    return mean(all);
}

template <class K>
GeometricFindings geometricChecks(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs, bool self_intersections) {
    using P = typename K::Point_3;
    using SM = CGAL::Surface_mesh<P>;
    namespace PMP = CGAL::Polygon_mesh_processing;
    assert(topo.nonfinite_vertices.empty());

    GeometricFindings out;
    auto t0 = std::chrono::steady_clock::now();

    std::vector<P> points;
    points.reserve(mesh.positions.size());
    for (const Vec3& p : mesh.positions) points.emplace_back(p.x, p.y, p.z);

    // The soup handed to CGAL: usable triangles, and their original ids.
    std::vector<uint8_t> unusable(mesh.triangles.size(), 0);
    for (uint32_t t : topo.out_of_range_triangles) unusable[t] = 1;
    for (uint32_t t : topo.index_degenerate_triangles) unusable[t] = 1;
    std::vector<std::array<size_t, 3>> polygons;
    std::vector<uint32_t> original;
    polygons.reserve(mesh.triangles.size());
    original.reserve(mesh.triangles.size());
    for (size_t t = 0; t < mesh.triangles.size(); ++t) {
        if (unusable[t]) continue;
        const auto& tri = mesh.triangles[t];
        polygons.push_back({tri[0], tri[1], tri[2]});
        original.push_back(uint32_t(t));
    }

    // Zero-area triangles: three collinear points, decided exactly.
    typename K::Collinear_3 collinear = K().collinear_3_object();
    for (size_t i = 0; i < polygons.size(); ++i) {
        const auto& q = polygons[i];
        if (collinear(points[q[0]], points[q[1]], points[q[2]])) out.zero_area_triangles.push_back(original[i]);
    }
    out.degenerate_ms = msSince(t0);

    out.self_intersections_requested = self_intersections;
    if (self_intersections) {
        // Build the Surface_mesh. A soup our own edge analysis found valid is
        // added as is; anything else goes through orient_polygon_soup, which
        // flips triangles and duplicates points at non-manifold places (the
        // repair is reported, never used for the verdict of the topology checks).
        t0 = std::chrono::steady_clock::now();
        const bool valid_soup =
            topo.nonmanifold_edges.empty() && topo.misoriented_edges.empty() && topo.nonmanifold_vertices.empty();
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
        out.build_ms = msSince(t0);

        // Self-intersections: pairs of triangles that meet other than in a shared
        // vertex or edge. CGAL lists a degenerate face f as (f, f); those are
        // already counted as zero-area triangles and are dropped here.
        if (out.mesh_built) {
            t0 = std::chrono::steady_clock::now();
            std::vector<std::pair<typename SM::Face_index, typename SM::Face_index>> pairs;
            PMP::self_intersections(sm, std::back_inserter(pairs));
            std::vector<std::pair<uint32_t, uint32_t>> ids;
            ids.reserve(pairs.size());
            for (const auto& [f, g] : pairs) {
                if (f == g) continue;
                uint32_t a = original[size_t(f)], b = original[size_t(g)];
                if (a > b) std::swap(a, b);
                ids.emplace_back(a, b);
            }
            std::sort(ids.begin(), ids.end());
            ids.erase(std::unique(ids.begin(), ids.end()), ids.end());
            out.intersecting_pair_count = ids.size();
            if (ids.size() > max_pairs) ids.resize(max_pairs);
            auto triangle = [&](uint32_t t) {
                const auto& tri = mesh.triangles[t];
                const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
                return typename K::Triangle_3(P(a.x, a.y, a.z), P(b.x, b.y, b.z), P(c.x, c.y, c.z));
            };
            for (const auto& [a, b] : ids) out.intersection_points.push_back(intersectionPoint<K>(triangle(a), triangle(b)));
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
