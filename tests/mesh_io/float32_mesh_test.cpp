// float32Mesh: the mesh as an STL or 3MF file holds it and a reader reads it.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/mesh_io/float32_mesh.h"

namespace tsf {
namespace {

TEST(Float32Mesh, EveryCoordinateIsRoundedAndVerticesThatMeetAreOne) {
    Mesh m;
    // Two vertices 1 nm apart at x = 120 mm round to one float32 there (its
    // spacing is 7.6 nm); the others stay apart.
    m.positions = {{120.370, 125.0927, 0.0}, {120.370001, 125.0927, 0.0}, {122.222, 124.0235, 0.0}, {129.63, 132.577, 2.741}};
    m.triangles = {{0, 2, 3}, {1, 2, 3}};
    const Mesh f = float32Mesh(m);
    ASSERT_EQ(f.positions.size(), 3u);
    for (const Vec3& p : f.positions) {
        EXPECT_EQ(p.x, double(static_cast<float>(p.x)));
        EXPECT_EQ(p.y, double(static_cast<float>(p.y)));
        EXPECT_EQ(p.z, double(static_cast<float>(p.z)));
    }
    // Rounded, not copied: 129.63 is not a float32.
    EXPECT_NE(f.positions[2].x, 129.63);
    EXPECT_NEAR(f.positions[2].x, 129.63, 1e-5);
    // Both triangles kept, now on the same corners.
    ASSERT_EQ(f.triangles.size(), 2u);
    EXPECT_EQ(f.triangles[0], f.triangles[1]);
}

}  // namespace
}  // namespace tsf
