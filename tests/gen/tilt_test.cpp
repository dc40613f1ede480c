// Tilted tops and structural dimples (gen/model/features/tilt.h, gen/model/features/top_shapes.h): the
// regression planes, the clamp, crossing tops, mirrored bottoms read back
// from below, and every mesh verified (closed, 2-manifold, outward, no
// self-intersection, heights and tilts read back).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "gen/field/bin_regression.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "gen/model/scene_json.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "verify/verify_model.h"
#include "gen/model/features/tilt.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {
namespace {
using test::fieldFromFunction;

BinMoments moments(std::initializer_list<std::array<double, 3>> points) {
    BinMoments m;
    for (const auto& p : points) m.add(p[0], p[1], p[2]);
    return m;
}

TEST(BinRegression, FewerThanThreePointsOrCollinearPointsGiveNoPlane) {
    EXPECT_FALSE(densityRelativeSlope(moments({{0.1, 0.1, 0}})));
    EXPECT_FALSE(densityRelativeSlope(moments({{0.1, 0.1, 0}, {-0.2, 0.1, 0}})));
    EXPECT_FALSE(weightSlope(moments({{0.1, 0.1, 1}, {-0.2, 0.1, 2}})));
    // Three and four points on one line (y = 2x).
    EXPECT_FALSE(densityRelativeSlope(moments({{0.0, 0.0, 0}, {0.1, 0.2, 0}, {0.2, 0.4, 0}})));
    EXPECT_FALSE(weightSlope(moments({{0.0, 0.0, 1}, {0.1, 0.2, 2}, {0.2, 0.4, 3}, {-0.1, -0.2, 4}})));
    EXPECT_TRUE(densityRelativeSlope(moments({{0.0, 0.0, 0}, {0.1, 0.2, 0}, {0.2, 0.1, 0}})));
}

TEST(BinRegression, WeightPlaneIsRecoveredExactly) {
    // w = 2 + 3 dx - dy at four points not on a line.
    auto w = [](double x, double y) { return 2 + 3 * x - y; };
    const auto g = weightSlope(moments({{0.1, 0.0, w(0.1, 0.0)}, {-0.2, 0.1, w(-0.2, 0.1)}, {0.0, -0.3, w(0.0, -0.3)},
                                        {0.2, 0.2, w(0.2, 0.2)}}));
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->x, 3.0, 1e-12);
    EXPECT_NEAR(g->y, -1.0, 1e-12);
}

TEST(BinRegression, DensityLeansTowardsWhereThePointsCrowd) {
    // Symmetric about the centre: level.
    const auto level = densityRelativeSlope(moments({{0.2, 0, 0}, {-0.2, 0, 0}, {0, 0.2, 0}, {0, -0.2, 0}}));
    ASSERT_TRUE(level);
    EXPECT_NEAR(level->x, 0.0, 1e-15);
    EXPECT_NEAR(level->y, 0.0, 1e-15);
    // Mean offset (0.1, -0.05) pitches: A / J = 14.4 per pitch (side 1/sqrt 3).
    const auto g = densityRelativeSlope(moments({{0.3, 0.0, 0}, {0.1, -0.15, 0}, {-0.1, 0.0, 0}}));
    ASSERT_TRUE(g);
    EXPECT_NEAR(g->x, 14.4 * 0.1, 1e-12);
    EXPECT_NEAR(g->y, 14.4 * -0.05, 1e-12);
}

// A cone: every top tilts, neighbours cross on the flanks at large steepness.
HexField cone() {
    return fieldFromFunction(9, 9, [](int c, int r) { return 10.0 - std::hypot(c - 4.0, (r - 4.0) * 0.866); });
}

void expectVerified(const Scene& s, const char* what) {
    const Mesh mesh = meshScene(s);
    const test::Invariants inv = test::checkInvariants(mesh);
    EXPECT_TRUE(inv.closedManifold()) << what;
    VerifyOptions vo;
    const VerifyReport r = verifyModel(mesh, &s, vo);
    EXPECT_TRUE(r.passed()) << what << "\n" << formatReport(r);
    if (s.shapes.cells_tilted > 0) {
        ASSERT_TRUE(r.tilt) << what;
        EXPECT_EQ(r.tilt->cells_checked, size_t(s.shapes.cells_tilted)) << what;
        EXPECT_LE(r.tilt->max_error_top, r.tilt->max_tolerance) << what;
    }
}

TEST(Tilt, GradientTopsReadTheirValueAtTheCentreAndVerify) {
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        SceneParams p = test::smallParams(bottom);
        p.tilt = TiltSource::Gradient;
        const Scene s = buildScene(cone(), p);
        EXPECT_GT(s.shapes.cells_tilted, 40);
        // The top of a cone leans away from the peak: a cell east of it falls to the east.
        const int32_t east = s.keptAt(6, 4);
        ASSERT_GE(east, 0);
        EXPECT_LT(s.shapes.slope_x[size_t(east)], 0);
        expectVerified(s, bottom == Bottom::Flat ? "flat" : "mirrored");
    }
}

TEST(Tilt, CrossingTopsAreSplitAtTheCrossingAndVerify) {
    // Two rows of equal height whose tops lean opposite ways: every shared
    // edge between them crosses.
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        Scene s = buildScene(fieldFromFunction(6, 2, [](int, int) { return 5.0; }), test::smallParams(bottom));
        std::vector<PlaneSlope> slopes(s.keptCount());
        for (size_t k = 0; k < s.keptCount(); ++k) slopes[k] = {s.col[k] % 2 ? 0.3 : -0.3, s.col[k] % 2 ? -0.2 : 0.2};
        resolveTopShapes(s, slopes, 1.0, {});
        int64_t crossings = 0;
        for (int64_t id : s.shapes.crossing_top) crossings += id >= 0;
        EXPECT_GT(crossings, 0);
        // Every crossing point keeps kMinCrossingMm from both ends of its edge.
        expectVerified(s, "crossing");
    }
}

TEST(Tilt, AShapedSceneTheMesherCannotBuildIsRefused) {
    Scene s = buildScene(fieldFromFunction(6, 2, [](int, int) { return 5.0; }), test::smallParams());
    std::vector<PlaneSlope> slopes(s.keptCount());
    for (size_t k = 0; k < s.keptCount(); ++k) slopes[k] = {s.col[k] % 2 ? 0.3 : -0.3, s.col[k] % 2 ? -0.2 : 0.2};
    resolveTopShapes(s, slopes, 1.0, {});
    Scene no_crossing = s;
    std::fill(no_crossing.shapes.crossing_top.begin(), no_crossing.shapes.crossing_top.end(), -1);
    EXPECT_THROW(meshScene(no_crossing), InputError);
    Scene through_floor = s;
    through_floor.shapes.top_dz[0][0] = -int32_t(through_floor.top[0]);  // a corner down to z = 0
    EXPECT_THROW(meshScene(through_floor), InputError);
    Scene short_lists = s;
    short_lists.shapes.slope_x.pop_back();
    EXPECT_THROW(meshScene(short_lists), InputError);
}

TEST(Tilt, ExtremeSlopesAreClampedAtTheFloorAndStillVerify) {
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        SceneParams p = test::smallParams(bottom);
        p.tilt = TiltSource::Gradient;
        p.steepness = 1000;
        const Scene s = buildScene(cone(), p);
        EXPECT_GT(s.shapes.cells_clamped, 0);
        bool noted = false;
        for (const auto& n : s.notes) noted = noted || n.find("tilt:") == 0;
        EXPECT_TRUE(noted);
        // No corner below the floor (flat: the base; mirrored: z = 0).
        for (size_t k = 0; k < s.keptCount(); ++k)
            for (int e = 0; e < 6; ++e) {
                if (bottom == Bottom::Flat) EXPECT_GE(cornerTop(s, k, e), s.floor_units - s.nodata_pit_units);
                else EXPECT_GE(cornerBottom(s, k, e), 0);
            }
        expectVerified(s, "extreme");
    }
}

TEST(Tilt, MirroredBottomTellsTheSameSlopeFromBelow) {
    SceneParams p = test::smallParams(Bottom::Mirrored);
    p.tilt = TiltSource::Gradient;
    const Scene s = buildScene(cone(), p);
    const VerifyReport r = verifyModel(meshScene(s), &s, VerifyOptions{});
    ASSERT_TRUE(r.tilt);
    EXPECT_TRUE(r.passed()) << formatReport(r);
    EXPECT_LE(r.tilt->max_error_bottom, r.tilt->max_tolerance);
    EXPECT_LE(r.tilt->max_top_bottom, 2 * r.tilt->max_tolerance);
    EXPECT_GT(r.tilt->max_slope, 0.1);  // the test measures real slopes, not level tops
}

TEST(Tilt, AWrongBottomFailsTheReadback) {
    // The figure 6.7 failure planted: bottoms tilted the other way.
    SceneParams p = test::smallParams(Bottom::Mirrored);
    p.tilt = TiltSource::Gradient;
    Scene s = buildScene(cone(), p);
    Scene wrong = s;
    for (auto& dz : wrong.shapes.bottom_dz)
        for (auto& d : dz) d = -d;
    buildTopShapeGeometry(wrong);
    const VerifyReport r = verifyModel(meshScene(wrong), &s, VerifyOptions{});
    ASSERT_TRUE(r.tilt);
    EXPECT_GT(r.tilt->max_error_bottom, r.tilt->max_tolerance);
    EXPECT_FALSE(r.passed());
}

TEST(Tilt, SidecarRoundTripsTheShapes) {
    SceneParams p = test::smallParams(Bottom::Mirrored);
    p.tilt = TiltSource::Gradient;
    p.structural_texture = true;
    const Scene s = buildScene(cone(), p);
    const Scene back = sceneFromJson(sceneToJson(s));
    EXPECT_EQ(back.shapes.top_dz, s.shapes.top_dz);
    EXPECT_EQ(back.shapes.extra_z, s.shapes.extra_z);
    EXPECT_EQ(signedVolume(meshScene(back)), signedVolume(meshScene(s)));
}

// Islands of data in an empty field, not one value per cell (as binned points).
HexField binnedIslands() {
    HexField f = fieldFromFunction(14, 14, [](int c, int r) {
        const bool island = (c < 3 && r < 3) || (c > 10 && r > 10) || (c > 10 && r < 3);
        return island ? 1.0 + (c + r) % 3 : 0.0;
    });
    return test::asBinnedPoints(f);
}

TEST(StructuralTexture, OnlyCellsKeptToConnectAreDimpled) {
    for (Cull cull : {Cull::Hull, Cull::Concave})
        for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
            SceneParams p = test::smallParams(bottom, cull);
            p.structural_texture = true;
            const Scene s = buildScene(binnedIslands(), p);
            EXPECT_GT(s.shapes.cells_textured, 0);
            for (size_t k = 0; k < s.keptCount(); ++k) {
                const bool empty = s.value[k] == 0.0;
                EXPECT_EQ(bool(isStructural(s.shapes, k)), empty) << s.col[k] << "," << s.row[k];
                if (empty) {
                    EXPECT_LT(centreTop(s, k), s.top[k]);  // the dimple
                    if (bottom == Bottom::Mirrored) EXPECT_GT(centreBottom(s, k), s.bottom[k]);
                }
            }
            expectVerified(s, "texture");
        }
    // A raster's cells all hold values: a 0 is data, never textured, whether
    // one value per cell or resampled.
    SceneParams p = test::smallParams();
    p.structural_texture = true;
    HexField raster = binnedIslands();
    raster.moments.clear();
    for (bool one_to_one : {true, false}) {
        raster.one_to_one = one_to_one;
        EXPECT_EQ(buildScene(raster, p).shapes.cells_textured, 0);
    }
}

TEST(Tilt, AirportsRegressionPlanesMirroredVerifyFromBothFaces) {
    const auto dir = test::scratchDir("tilt_airports");
    const test::RunResult r = test::runTsf("gen " + test::sourcePath("examples/airports-europe.csv") +
                                           " --points x=lon,y=lat --tilt points --mirror --json -o " +
                                           (dir / "eu.stl").string(),
                                           dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_GT(j["scene"]["tilt"]["cells_tilted"].get<int>(), 100);
    const auto& t = j["verify"]["tilt"];
    EXPECT_EQ(t["over_tolerance"].get<int>(), 0);
    EXPECT_LE(t["max_error_top"].get<double>(), t["max_tolerance"].get<double>());
    EXPECT_LE(t["max_error_bottom"].get<double>(), t["max_tolerance"].get<double>());
    EXPECT_TRUE(j["verify"]["passed"].get<bool>());
}

}  // namespace
}  // namespace tsf
