// analyzeTopology on hand-drawn meshes: each defect is found and named by the
// indices a person can look up, and the clean meshes are clean.
#include <gtest/gtest.h>

#include "tests/verify/verify_test_support.h"
#include "verify/mesh_topology.h"

namespace tsf {
namespace {

using vtest::box;

TEST(Topology, ClosedBoxIsAnOrientedClosedManifold) {
    const Mesh m = box({0, 0, 0}, {1, 2, 3});
    const MeshTopology t = analyzeTopology(m);
    EXPECT_TRUE(t.isClosedOrientedManifold());
    EXPECT_EQ(t.edge_count, 18u);  // 12 box edges + 6 face diagonals
    ASSERT_EQ(t.components.size(), 1u);
    EXPECT_DOUBLE_EQ(t.components[0].signed_volume_mm3, 6.0);
    EXPECT_EQ(t.unreferenced_vertices, 0u);
    EXPECT_EQ(t.duplicate_position_vertices, 0u);
}

TEST(Topology, RemovedTriangleLeavesThreeBorderEdges) {
    Mesh m = box({0, 0, 0}, {1, 1, 1});
    m.triangles.erase(m.triangles.begin() + 2);  // {4, 5, 6}, top
    const MeshTopology t = analyzeTopology(m);
    ASSERT_EQ(t.border_edges.size(), 3u);
    // The hole's rim is exactly the removed triangle's edges.
    std::vector<std::pair<uint32_t, uint32_t>> edges;
    for (const EdgeUse& e : t.border_edges) edges.push_back({e.a, e.b});
    EXPECT_EQ(edges, (std::vector<std::pair<uint32_t, uint32_t>>{{4, 5}, {4, 6}, {5, 6}}));
    EXPECT_TRUE(t.misoriented_edges.empty());
    EXPECT_FALSE(t.isClosedOrientedManifold());
}

TEST(Topology, FlippedTriangleDisagreesOnAllThreeEdges) {
    Mesh m = box({0, 0, 0}, {1, 1, 1});
    std::swap(m.triangles[7][1], m.triangles[7][2]);  // {1, 6, 5} -> {1, 5, 6}
    const MeshTopology t = analyzeTopology(m);
    ASSERT_EQ(t.misoriented_edges.size(), 3u);
    for (const EdgeUse& e : t.misoriented_edges) {
        ASSERT_EQ(e.triangles.size(), 2u);
        EXPECT_TRUE(e.triangles[0] == 7 || e.triangles[1] == 7);
    }
    EXPECT_TRUE(t.border_edges.empty());
    EXPECT_TRUE(t.nonmanifold_edges.empty());
}

TEST(Topology, DuplicatedTriangleMakesNonManifoldEdges) {
    Mesh m = box({0, 0, 0}, {1, 1, 1});
    m.triangles.push_back(m.triangles[4]);  // {0, 1, 5} again
    const MeshTopology t = analyzeTopology(m);
    ASSERT_EQ(t.nonmanifold_edges.size(), 3u);
    for (const EdgeUse& e : t.nonmanifold_edges) EXPECT_EQ(e.triangles.size(), 3u);
}

// Two boxes sharing exactly one corner vertex (index-shared): the vertex has
// two fans, the mesh has two components, yet every edge is fine.
TEST(Topology, BoxesTouchingAtAVertexPinchIt) {
    Mesh a = box({0, 0, 0}, {1, 1, 1});
    Mesh b = box({1, 1, 1}, {2, 2, 2});
    Mesh m = vtest::append(a, b);
    // b's vertex 0 is (1,1,1) = a's vertex 6: point b's uses at a's.
    for (size_t t = 12; t < m.triangles.size(); ++t)
        for (auto& v : m.triangles[t])
            if (v == 8) v = 6;
    const MeshTopology t = analyzeTopology(m);
    EXPECT_EQ(t.nonmanifold_vertices, std::vector<uint32_t>{6});
    EXPECT_TRUE(t.border_edges.empty());
    EXPECT_TRUE(t.nonmanifold_edges.empty());
    EXPECT_EQ(t.components.size(), 2u);
    EXPECT_EQ(t.unreferenced_vertices, 1u);  // b's own copy of the corner
    EXPECT_EQ(t.duplicate_position_vertices, 1u);
}

TEST(Topology, DisjointShellsAreTwoComponentsLargestFirst) {
    Mesh big = box({0, 0, 0}, {4, 4, 4});
    // A shell with more triangles but less volume comes first: order is by triangle count.
    Mesh small = box({10, 0, 0}, {11, 1, 1});
    Mesh m = vtest::append(small, big);
    m.triangles.erase(m.triangles.begin());  // small now has 11 triangles
    const MeshTopology t = analyzeTopology(m);
    ASSERT_EQ(t.components.size(), 2u);
    EXPECT_EQ(t.components[0].triangles.size(), 12u);
    EXPECT_EQ(t.components[1].triangles.size(), 11u);
    EXPECT_DOUBLE_EQ(t.components[0].bounds.max.x, 4.0);
    EXPECT_DOUBLE_EQ(t.components[1].bounds.min.x, 10.0);
}

TEST(Topology, RepeatedIndexAndOutOfRangeTrianglesAreListedNotUsed) {
    Mesh m = box({0, 0, 0}, {1, 1, 1});
    m.triangles.push_back({0, 0, 1});
    m.triangles.push_back({0, 1, 99});
    const MeshTopology t = analyzeTopology(m);
    EXPECT_EQ(t.index_degenerate_triangles, std::vector<uint32_t>{12});
    EXPECT_EQ(t.out_of_range_triangles, std::vector<uint32_t>{13});
    EXPECT_TRUE(t.border_edges.empty());  // neither contributes edges
    EXPECT_FALSE(t.isClosedOrientedManifold());
}

TEST(Topology, UnmergedVerticesOpenTheMeshAndAreCounted) {
    // A triangle soup: every triangle has its own three vertices.
    const Mesh b = box({0, 0, 0}, {1, 1, 1});
    Mesh soup;
    for (const auto& tri : b.triangles) {
        const uint32_t base = uint32_t(soup.positions.size());
        for (uint32_t v : tri) soup.positions.push_back(b.positions[v]);
        soup.triangles.push_back({base, base + 1, base + 2});
    }
    const MeshTopology t = analyzeTopology(soup);
    EXPECT_EQ(t.border_edges.size(), 36u);
    EXPECT_EQ(t.components.size(), 12u);
    EXPECT_EQ(t.duplicate_position_vertices, 36u - 8u);
}

TEST(Topology, NonFiniteVertexIsReported) {
    Mesh m = box({0, 0, 0}, {1, 1, 1});
    m.positions[3].y = NAN;
    const MeshTopology t = analyzeTopology(m);
    EXPECT_EQ(t.nonfinite_vertices, std::vector<uint32_t>{3});
    EXPECT_FALSE(t.isClosedOrientedManifold());
}

TEST(Topology, EmptyMeshHasNothing) {
    const MeshTopology t = analyzeTopology(Mesh{});
    EXPECT_EQ(t.edge_count, 0u);
    EXPECT_TRUE(t.components.empty());
    EXPECT_TRUE(t.isClosedOrientedManifold());  // vacuously; single_piece fails it (solid_checks)
}

}  // namespace
}  // namespace tsf
