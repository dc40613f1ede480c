// The box every check starts from (meshBounds): a NaN coordinate never bounds
// a model, and a tie between -0 and +0 keeps the later vertex's zero, as the
// library's fmin/fmax did before the loop was made plain comparisons.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gen/geometry/mesh.h"

namespace tsf {
namespace {

TEST(MeshBounds, ABoxOfThreePoints) {
    Mesh m;
    m.positions = {{1.0, -2.0, 3.0}, {-4.0, 5.0, 0.5}, {2.0, 0.0, -6.0}};
    const Bounds b = meshBounds(m);
    EXPECT_EQ(b.min.x, -4.0);
    EXPECT_EQ(b.min.y, -2.0);
    EXPECT_EQ(b.min.z, -6.0);
    EXPECT_EQ(b.max.x, 2.0);
    EXPECT_EQ(b.max.y, 5.0);
    EXPECT_EQ(b.max.z, 3.0);
}

TEST(MeshBounds, ANaNCoordinateIsSkipped) {
    const double nan = std::numeric_limits<double>::quiet_NaN();
    Mesh m;
    m.positions = {{nan, 1.0, 2.0}, {3.0, nan, -1.0}, {-1.0, 4.0, nan}};
    const Bounds b = meshBounds(m);
    EXPECT_EQ(b.min.x, -1.0);
    EXPECT_EQ(b.max.x, 3.0);
    EXPECT_EQ(b.min.y, 1.0);
    EXPECT_EQ(b.max.y, 4.0);
    EXPECT_EQ(b.min.z, -1.0);
    EXPECT_EQ(b.max.z, 2.0);
}

TEST(MeshBounds, NoPointsLeaveTheEmptyBox) {
    const double inf = std::numeric_limits<double>::infinity();
    const Bounds b = meshBounds(Mesh{});
    EXPECT_EQ(b.min.x, inf);
    EXPECT_EQ(b.max.z, -inf);
}

TEST(MeshBounds, ATieOfZerosTakesTheLaterVertex) {
    Mesh m;
    m.positions = {{0.0, -0.0, 0.0}, {-0.0, 0.0, 0.0}};
    const Bounds b = meshBounds(m);
    EXPECT_TRUE(std::signbit(b.min.x));   // -0 came second
    EXPECT_FALSE(std::signbit(b.min.y));  // +0 came second
    EXPECT_TRUE(std::signbit(b.max.x));
    EXPECT_FALSE(std::signbit(b.max.y));
}

}  // namespace
}  // namespace tsf
