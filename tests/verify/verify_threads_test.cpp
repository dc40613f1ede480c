// The verifier's threaded stages on a mesh large enough to run them on every
// core: the column grid (built on the worker threads from 20 000 triangles),
// the self-intersection test's exact predicates, the printability rays and
// the topology. Hand-drawn boxes only, so that run-sanitizers.sh can build
// these tests under AddressSanitizer and ThreadSanitizer with the verifier's
// sources and no mesher (tests/CMakeLists.txt, test_verify_threads).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/intersections.h>

#include "gen/mesh_io/exact_vertex_index.h"
#include "gen/mesh_io/exact_weld.h"
#include "tests/support/meshes.h"
#include "verify/column_grid.h"
#include "verify/mesh_topology.h"
#include "verify/printability.h"
#include "verify/solid_checks.h"

namespace tsf {
namespace {

constexpr int kSide = 42;          // boxes a side: 42 * 42 * 12 = 21 168 triangles
constexpr double kWidthMm = 1.0;   // each box's side, x and y
constexpr double kPitchMm = 2.0;   // box to box: a 1 mm gap between neighbours
constexpr double kHeightMm = 3.0;

// kSide x kSide separate boxes, 1 mm wide, 1 mm apart, 3 mm tall.
Mesh boxGrid() {
    Mesh m;
    for (int r = 0; r < kSide; ++r)
        for (int c = 0; c < kSide; ++c) {
            const Vec3 lo{c * kPitchMm, r * kPitchMm, 0};
            m = test::append(std::move(m), test::box(lo, {lo.x + kWidthMm, lo.y + kWidthMm, kHeightMm}));
        }
    return m;
}

const Check& findCheck(const std::vector<Check>& checks, const std::string& id) {
    for (const Check& c : checks)
        if (c.id == id) return c;
    ADD_FAILURE() << "no check " << id;
    return checks.front();
}

TEST(VerifyThreads, SeparateBoxesHaveNoSelfIntersectionAndOneComponentEach) {
    const Mesh m = boxGrid();
    ASSERT_GT(m.triangles.size(), 20000u);  // the grid is built on several threads
    const MeshTopology topo = analyzeTopology(m);
    EXPECT_EQ(topo.components.size(), size_t(kSide * kSide));
    EXPECT_TRUE(topo.border_edges.empty());
    EXPECT_TRUE(topo.nonmanifold_edges.empty());
    EXPECT_TRUE(topo.misoriented_edges.empty());
    EXPECT_EQ(topo.edge_count, size_t(kSide * kSide * 18));  // 12 box edges + 6 face diagonals
    SolidOptions o;
    o.pieces_allowed = true;
    const SolidResult r = checkSolid(m, o);
    EXPECT_EQ(findCheck(r.checks, "self_intersections").status, CheckStatus::Pass);
    EXPECT_EQ(findCheck(r.checks, "outward_orientation").status, CheckStatus::Pass);
}

// Defects at both ends of the vertex order, so in the first and the last
// worker's run of vertices: a hole in the first box, a flipped triangle in
// the last, a pinch (a box sharing a corner vertex) in the middle; each
// listed once, in vertex order, as on one thread.
TEST(VerifyThreads, TopologyListsDefectsFoundOnSeveralThreadsInVertexOrder) {
    Mesh m = boxGrid();
    m.triangles.erase(m.triangles.begin());                      // box 0's {0, 3, 2}: edges 0-3, 2-3, 0-2 open
    auto& last = m.triangles.back();                             // the last box's {3, 4, 7}, flipped
    std::swap(last[1], last[2]);
    const uint32_t corner = 8 * (kSide * kSide / 2) + 6;         // a middle box's top corner (hi)
    const Vec3 c = m.positions[corner];
    Mesh pinch = test::box(c, {c.x + 0.5, c.y + 0.5, c.z + 0.5});
    const uint32_t base = uint32_t(m.positions.size());
    m.positions.insert(m.positions.end(), pinch.positions.begin() + 1, pinch.positions.end());
    for (auto t : pinch.triangles) {
        for (uint32_t& v : t) v = v == 0 ? corner : base + v - 1;  // its lo corner is the box's vertex
        m.triangles.push_back(t);
    }
    const MeshTopology topo = analyzeTopology(m);
    ASSERT_EQ(topo.border_edges.size(), 3u);
    EXPECT_EQ(std::make_pair(topo.border_edges[0].a, topo.border_edges[0].b), std::make_pair(0u, 2u));
    EXPECT_EQ(std::make_pair(topo.border_edges[1].a, topo.border_edges[1].b), std::make_pair(0u, 3u));
    EXPECT_EQ(std::make_pair(topo.border_edges[2].a, topo.border_edges[2].b), std::make_pair(2u, 3u));
    const uint32_t l = 8 * (kSide * kSide - 1);  // the last box's first vertex
    ASSERT_EQ(topo.misoriented_edges.size(), 3u);
    EXPECT_EQ(std::make_pair(topo.misoriented_edges[0].a, topo.misoriented_edges[0].b), std::make_pair(l + 3, l + 4));
    EXPECT_EQ(std::make_pair(topo.misoriented_edges[1].a, topo.misoriented_edges[1].b), std::make_pair(l + 3, l + 7));
    EXPECT_EQ(std::make_pair(topo.misoriented_edges[2].a, topo.misoriented_edges[2].b), std::make_pair(l + 4, l + 7));
    EXPECT_EQ(topo.nonmanifold_vertices, std::vector<uint32_t>{corner});
    EXPECT_TRUE(topo.nonmanifold_edges.empty());
    // The pinched boxes share no edge: still two components.
    EXPECT_EQ(topo.components.size(), size_t(kSide * kSide + 1));
}

// The corners grouped by vertex on several threads, each thread a run of
// triangles: every vertex's corners by ascending triangle, as the one-thread
// pass over a range of vertices lists them, with vertices whose corners lie
// in every run and triangles left out.
TEST(VerifyThreads, CornersAreGroupedByVertexOnSeveralThreadsAsOnOne) {
    const Mesh grid = boxGrid();
    Mesh m = test::append(test::append(grid, grid), test::append(grid, grid));
    ASSERT_GE(m.triangles.size(), size_t(1) << 16);  // enough to run on several threads
    for (size_t t = 0; t < m.triangles.size(); t += 997) m.triangles[t][t % 3] = 5;  // vertex 5 in every run
    std::vector<uint8_t> usable(m.triangles.size(), 1);
    for (size_t t = 3; t < m.triangles.size(); t += 7) usable[t] = 0;
    for (const std::vector<uint8_t>* keep : std::vector<const std::vector<uint8_t>*>{nullptr, &usable}) {
        const VertexCorners threaded = cornersByVertex(m, keep);
        const VertexCorners one = cornersByVertex(m, keep, 0, uint32_t(m.positions.size()));
        EXPECT_EQ(threaded.start, one.start);
        EXPECT_EQ(threaded.list, one.list);
        // Vertex 5's corners: its own box's and every 997th triangle's, in order.
        std::vector<uint32_t> at5;
        for (size_t t = 0; t < m.triangles.size(); ++t)
            for (uint32_t i = 0; i < 3; ++i)
                if (m.triangles[t][i] == 5 && (!keep || usable[t])) at5.push_back(3 * uint32_t(t) + i);
        EXPECT_EQ(std::vector<uint32_t>(threaded.list.begin() + threaded.start[5], threaded.list.begin() + threaded.start[6]),
                  at5);
    }
}

// Every box twice, at the same place, with vertices of its own: each of the
// second copy's vertices repeats a position, counted once however the
// threads meet in the hash set.
TEST(VerifyThreads, RepeatedPositionsAreCountedOnSeveralThreads) {
    const Mesh grid = boxGrid();
    const MeshTopology topo = analyzeTopology(test::append(grid, grid));
    EXPECT_EQ(topo.duplicate_position_vertices, grid.positions.size());
    EXPECT_EQ(analyzeTopology(grid).duplicate_position_vertices, 0u);
}

// One more box planted through the first: exactly the pairs of their
// triangles that CGAL says meet, with either kernel, and no others.
TEST(VerifyThreads, APlantedOverlapIsFoundPairByPair) {
    const Mesh grid = boxGrid();
    const Mesh extra = test::box({0.5, 0.25, 0.5}, {1.5, 1.25, 3.5});  // short of the neighbours at 2 mm
    const Mesh m = test::append(grid, extra);
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    auto tri = [&](size_t t) {
        const auto& q = m.triangles[t];
        auto p = [&](uint32_t i) { return K::Point_3(m.positions[i].x, m.positions[i].y, m.positions[i].z); };
        return K::Triangle_3(p(q[0]), p(q[1]), p(q[2]));
    };
    int64_t expected = 0;  // box 0 is triangles 0..11; the extra box the last 12
    for (size_t a = 0; a < 12; ++a)
        for (size_t b = grid.triangles.size(); b < m.triangles.size(); ++b) expected += CGAL::do_intersect(tri(a), tri(b));
    ASSERT_GT(expected, 0);
    for (bool exact : {false, true}) {
        SolidOptions o;
        o.pieces_allowed = true;
        o.exact = exact;
        o.max_offenders = 1000;
        const SolidResult r = checkSolid(m, o);
        const Check& si = findCheck(r.checks, "self_intersections");
        EXPECT_EQ(si.count, expected) << (exact ? "exact" : "filtered");
        ASSERT_EQ(si.worst.size(), size_t(expected));
        for (const Offender& off : si.worst) {
            unsigned a = 0, b = 0;
            ASSERT_EQ(std::sscanf(off.detail.c_str(), "triangles %u and %u", &a, &b), 2) << off.detail;
            EXPECT_LT(a, 12u) << off.detail;
            EXPECT_GE(b, grid.triangles.size()) << off.detail;
        }
    }
}

// Walls 1 mm thick, gaps 1 mm wide, slabs the boxes' height, measured on
// every core.
TEST(VerifyThreads, PrintabilityMeasuresTheBoxesOnEveryCore) {
    const Mesh m = boxGrid();
    const ColumnGrid caster(m);
    PrintabilityOptions o;
    o.nozzle_mm = 0.4;  // gaps looked for up to 4 mm
    const PrintabilityResult r = checkPrintability(m, true, caster, o);
    EXPECT_NEAR(r.figures.min_wall_mm, kWidthMm, 1e-9);
    EXPECT_NEAR(r.figures.min_gap_mm, kPitchMm - kWidthMm, 1e-9);
    EXPECT_NEAR(r.figures.min_slab_mm, kHeightMm, 1e-9);
    EXPECT_EQ(findCheck(r.checks, "wall_thickness").status, CheckStatus::Pass);
}

// The model as written is rounded to float32 and its positions welded on
// every core (float32Mesh): the buckets filled and welded by several
// threads number every position as the index does one by one.
TEST(VerifyThreads, PositionsAreWeldedOnSeveralThreadsAsOneByOne) {
    std::vector<Vec3> points;
    for (int i = 0; i < 120000; ++i) {
        const int k = (i * 7919) % 50000;  // every position about twice, far apart in the list
        points.push_back({0.5 * (k % 211), 0.25 * (k / 211), k % 3 == 0 ? -0.0 : 1.5});
    }
    mesh_io::ExactVertexIndex index(4);
    std::vector<uint32_t> expected;
    for (const Vec3& p : points) expected.push_back(index.insert(p));
    for (const unsigned workers : {2u, 4u}) {
        const mesh_io::WeldedPositions w = mesh_io::weldExact(points, workers);
        EXPECT_EQ(w.index_of, expected) << workers << " threads";
        EXPECT_EQ(w.positions.size(), index.size());
    }
}

}  // namespace
}  // namespace tsf
