// Exact surface comparison on hand-drawn meshes: re-triangulations and
// T-junctions are the same surface; a vertex moved by one unit in the last
// place is not, and only the planes touching it differ.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/verify/verify_test_support.h"
#include "verify/surface_chains.h"

namespace tsf {
namespace {

// The box of verify_test_support with its top face (z = hi.z) split into four
// triangles around its centre, and a vertex on the middle of the front top
// edge that only the top uses (a T-junction: the front face keeps the whole
// edge).
//
//        7---------6
//        |\       /|
//        | \  c  / |         top face seen from above, c = centre (8),
//        |  \   /  |         m = midpoint of edge 4-5 (9)
//        |   \ /   |
//        4----m----5
Mesh boxWithSplitTop(Vec3 lo, Vec3 hi) {
    Mesh m = vtest::box(lo, hi);
    m.positions.push_back({(lo.x + hi.x) / 2, (lo.y + hi.y) / 2, hi.z});  // 8: centre
    m.positions.push_back({(lo.x + hi.x) / 2, lo.y, hi.z});               // 9: on edge 4-5
    // Replace the top {4, 5, 6}, {4, 6, 7} by a fan around the centre.
    m.triangles[2] = {4, 9, 8};
    m.triangles[3] = {9, 5, 8};
    m.triangles.push_back({5, 6, 8});
    m.triangles.push_back({6, 7, 8});
    m.triangles.push_back({7, 4, 8});
    return m;
}

TEST(SurfaceChains, RetriangulatedFaceWithTJunctionIsTheSameSurface) {
    // Centre and midpoint are exact in binary (0, 1, 2, 0.5 ...).
    const Mesh a = vtest::box({0, 0, 0}, {2, 2, 1});
    const Mesh b = boxWithSplitTop({0, 0, 0}, {2, 2, 1});
    const ChainComparison c = compareSurfaceChains(a, b, 10);
    ASSERT_TRUE(c.compared) << c.note;
    EXPECT_TRUE(c.identical());
    EXPECT_EQ(c.planes, 6u);
    EXPECT_EQ(c.differing_planes, 0u);
    EXPECT_EQ(c.difference_point_count, 0u);
    EXPECT_LE(c.grid_bits, 61);  // small binary numbers: the 64-bit path
    for (uint8_t f : c.model_differs) EXPECT_EQ(f, 0);
    for (uint8_t f : c.reference_differs) EXPECT_EQ(f, 0);
}

TEST(SurfaceChains, OneUlpMoveIsADifferenceInTheThreePlanesAtThatCorner) {
    const Mesh a = vtest::box({0, 0, 0}, {2, 2, 1});
    Mesh b = a;
    b.positions[6].z = std::nextafter(1.0, 2.0);  // corner (2, 2, 1): top, right and back faces
    const ChainComparison c = compareSurfaceChains(a, b, 10);
    ASSERT_TRUE(c.compared);
    EXPECT_FALSE(c.identical());
    EXPECT_FALSE(c.samePointSet());
    // The moved corner tilts the triangles that use it out of their planes:
    // top {4,5,6} and {4,6,7}, right {1,6,5} and {1,2,6}, back {2,7,6} and
    // {2,3,7}. Their planes and the new tilted ones differ; the bottom, front
    // and left faces (which do not touch corner 6) do not.
    const std::vector<size_t> touching = {2, 3, 6, 7, 8, 9};
    for (size_t t = 0; t < a.triangles.size(); ++t) {
        const bool touches = std::find(touching.begin(), touching.end(), t) != touching.end();
        EXPECT_EQ(c.reference_differs[t], touches ? 1 : 0) << "triangle " << t;
    }
    // The model's triangles in those planes are flagged too (they now lack a partner).
    EXPECT_EQ(c.model_differs[0], 0);  // bottom
    EXPECT_EQ(c.model_differs[2], 1);  // top
    EXPECT_GT(c.difference_point_count, 0u);
    ASSERT_FALSE(c.difference_points.empty());
}

TEST(SurfaceChains, InsideOutCopyIsTheSamePointSetFacingTheOtherWay) {
    const Mesh a = boxWithSplitTop({0, 0, 0}, {2, 2, 1});
    Mesh b = vtest::box({0, 0, 0}, {2, 2, 1});
    for (auto& t : b.triangles) std::swap(t[1], t[2]);
    const ChainComparison c = compareSurfaceChains(a, b, 10);
    EXPECT_FALSE(c.identical());
    EXPECT_TRUE(c.samePointSet());
    EXPECT_EQ(c.opposite_planes, 6u);
}

TEST(SurfaceChains, TwoCubesSharingAFaceHaveTheSurfaceOfTheirUnion) {
    // Two unit cubes sharing a face, each closed, against the 2 x 1 x 1 box:
    // the shared face appears twice, facing opposite ways, and cancels as a
    // chain (the union's surface). The chains are equal, although the two
    // cubes are two pieces touching along a face.
    const Mesh two = vtest::append(vtest::box({0, 0, 0}, {1, 1, 1}), vtest::box({1, 0, 0}, {2, 1, 1}));
    const Mesh one = vtest::box({0, 0, 0}, {2, 1, 1});
    const ChainComparison c = compareSurfaceChains(two, one, 10);
    EXPECT_TRUE(c.identical());
    // A gap of one unit in the last place between them is a difference.
    const double gap = std::nextafter(1.0, 2.0);
    const Mesh apart = vtest::append(vtest::box({0, 0, 0}, {1, 1, 1}), vtest::box({gap, 0, 0}, {2, 1, 1}));
    EXPECT_FALSE(compareSurfaceChains(apart, one, 10).identical());
}

TEST(SurfaceChains, CoordinatesSpanningMoreThan61BitsUseTheWidePath) {
    // 1 + 2^-70 needs 71 bits next to 1: not on a 61-bit grid, fine on 125.
    const double tiny = std::ldexp(1.0, -70);
    const Mesh a = vtest::box({tiny, 0, 0}, {2, 2, 1});
    const Mesh b = boxWithSplitTop({tiny, 0, 0}, {2, 2, 1});
    const ChainComparison c = compareSurfaceChains(a, b, 10);
    ASSERT_TRUE(c.compared) << c.note;
    EXPECT_GT(c.grid_bits, 61);
    // The centre (tiny + 2) / 2 rounds: it is 2^-71 off the exact middle but
    // still on the top plane, z = 1; the midpoint of the front edge is too.
    EXPECT_TRUE(c.identical());

    // Raising the centre by one unit in the last place tilts the fan out of
    // z = 1: the top plane differs, and so do the tilted triangles' planes
    // (four: {4,9,8} and {9,5,8} share the line through 4, 9, 5 and the centre).
    Mesh moved = b;
    moved.positions[8].z = std::nextafter(1.0, 2.0);
    const ChainComparison d = compareSurfaceChains(a, moved, 10);
    EXPECT_TRUE(d.compared);
    EXPECT_EQ(d.differing_planes, 5u);
}

TEST(SurfaceChains, CoordinatesBeyond125BitsAreNotCompared) {
    const Mesh a = vtest::box({1e-300, 0, 0}, {2, 2, 1});
    const ChainComparison c = compareSurfaceChains(a, a, 10);
    EXPECT_FALSE(c.compared);
    EXPECT_FALSE(c.identical());
    EXPECT_NE(c.note.find("bits"), std::string::npos);
    for (uint8_t f : c.model_differs) EXPECT_EQ(f, 1);  // everything left to sampling
}

TEST(SurfaceChains, ZeroAreaTriangleIsLeftToTheCaller) {
    const Mesh a = vtest::box({0, 0, 0}, {2, 2, 1});
    Mesh b = a;
    b.positions.push_back({1, 1, 5});
    b.positions.push_back({1, 1, 6});
    b.positions.push_back({1, 1, 7});
    b.triangles.push_back({8, 9, 10});  // collinear: no area, no plane, but points off the box
    b.triangles.push_back({8, 9, 8});   // a repeated index: not a triangle at all
    const ChainComparison c = compareSurfaceChains(a, b, 10);
    // As chains the two are equal (a zero-area triangle adds nothing) ...
    EXPECT_TRUE(c.identical());
    // ... but the needle is left to the caller to measure.
    EXPECT_EQ(c.reference_differs[12], 1);
    EXPECT_EQ(c.reference_differs[13], 0);
    for (size_t t = 0; t < 12; ++t) EXPECT_EQ(c.reference_differs[t], 0);
}

}  // namespace
}  // namespace tsf
