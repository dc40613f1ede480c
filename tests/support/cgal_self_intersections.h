// CGAL's own verdict on a mesh's self-intersections, the reference the
// verifier's self-intersection check is held to (tests/verify).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
// g++ 12 warns falsely inside this CGAL header (see verify/detail/cgal_checks_impl.h).
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#pragma GCC diagnostic pop
#include <CGAL/Surface_mesh.h>

#include "gen/geometry/mesh.h"

namespace tsf::test {

/// Intersecting triangle pairs (a < b), sorted, by CGAL on a Surface_mesh.
inline std::vector<std::pair<uint32_t, uint32_t>> cgalPairs(const Mesh& m) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using SM = CGAL::Surface_mesh<K::Point_3>;
    SM sm;
    std::vector<SM::Vertex_index> vid;
    for (const Vec3& p : m.positions) vid.push_back(sm.add_vertex(K::Point_3(p.x, p.y, p.z)));
    for (const auto& t : m.triangles) EXPECT_NE(sm.add_face(vid[t[0]], vid[t[1]], vid[t[2]]), SM::null_face());
    std::vector<std::pair<SM::Face_index, SM::Face_index>> pairs;
    CGAL::Polygon_mesh_processing::self_intersections(sm, std::back_inserter(pairs));
    std::vector<std::pair<uint32_t, uint32_t>> out;
    for (const auto& [f, g] : pairs)
        if (f != g) out.emplace_back(std::min(uint32_t(f), uint32_t(g)), std::max(uint32_t(f), uint32_t(g)));
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

}  // namespace tsf::test
