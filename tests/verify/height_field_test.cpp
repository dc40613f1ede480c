// rasteriseTop: the same top as rays straight down from above (the tree's
// watertight test) at every sample, on flat, mirrored and tilted models, with
// samples on the lattice's corners and edges; nothing where nothing is.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "tests/support/fields.h"
#include "tests/verify/verify_test_support.h"
#include "verify/height_field.h"
#include "verify/triangle_bvh.h"

namespace tsf {
namespace {

void expectSameTopAsRays(const Mesh& mesh, double step, const std::string& what) {
    const Bounds b = meshBounds(mesh);
    TopHeightField f;
    f.step = step;
    f.x0 = b.min.x - 2;
    f.y0 = b.min.y - 2;
    f.nx = int(std::ceil((b.max.x - b.min.x + 4) / step)) + 1;
    f.ny = int(std::ceil((b.max.y - b.min.y + 4) / step)) + 1;
    rasteriseTop(mesh, f);
    const TriangleBvh tree(mesh);
    size_t covered = 0, empty = 0;
    for (int j = 0; j < f.ny; ++j)
        for (int i = 0; i < f.nx; ++i) {
            const auto hit = tree.firstHit({f.x0 + i * f.step, f.y0 + j * f.step, b.max.z + 1}, {0, 0, -1});
            if (!hit) {
                EXPECT_EQ(f.at(i, j), -INFINITY) << what << " at sample " << i << ", " << j;
                ++empty;
                continue;
            }
            ++covered;
            EXPECT_NEAR(f.at(i, j), hit->point_mm.z, 1e-9) << what << " at sample " << i << ", " << j;
        }
    EXPECT_GT(covered, 100u) << what;  // not vacuous
    EXPECT_GT(empty, 10u) << what;
}

TEST(TopHeightField, SameTopAsRaysFromAbove) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const vtest::Model m = vtest::smallModel(bottom);
        // A step of a quarter pitch puts samples on centres, corners and edges.
        expectSameTopAsRays(m.mesh, m.scene.pitch_mm / 4, bottom == Bottom::Flat ? "flat" : "mirrored");
        expectSameTopAsRays(m.mesh, 0.37, bottom == Bottom::Flat ? "flat, 0.37 mm" : "mirrored, 0.37 mm");
    }
    SceneParams p = vtest::smallFieldParams(Bottom::Flat, 0.01);
    p.pitch_mm = 4.0;
    p.tilt = TiltSource::Gradient;
    const Scene tilted = buildScene(test::fieldFromFunction(14, 12, [](int c, int r) { return 1.0 + 0.4 * c + 0.1 * r * r; }), p);
    expectSameTopAsRays(meshScene(tilted), 0.5, "tilted");
}

TEST(TopHeightField, NothingToRasterise) {
    TopHeightField f;
    f.nx = 3;
    f.ny = 2;
    f.step = 1;
    rasteriseTop(Mesh{}, f);
    ASSERT_EQ(f.z.size(), 6u);
    for (double z : f.z) EXPECT_EQ(z, -INFINITY);
    // A vertical triangle has no shadow: nothing is over any sample.
    Mesh wall;
    wall.positions = {{0, 0, 0}, {2, 0, 0}, {1, 0, 3}};
    wall.triangles = {{0, 1, 2}};
    rasteriseTop(wall, f);
    for (double z : f.z) EXPECT_EQ(z, -INFINITY);
}

}  // namespace
}  // namespace tsf
