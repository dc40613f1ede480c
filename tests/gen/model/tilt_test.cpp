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
        if (bottom == Bottom::Mirrored) {
            // A mirrored model stands on the bed: give its bottoms room to
            // lean down, as buildScene does until tilted tops are resolved.
            constexpr int64_t kRoom = 5000;
            for (size_t k = 0; k < s.keptCount(); ++k) s.top[k] += kRoom, s.bottom[k] += kRoom;
            s.floor_units += kRoom;
        }
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

/// The steepest gradient (mm per mm) of the fan triangle of kept cell k
/// between corners e and e + 1 and the top's centre, from the drawn heights.
double fanGradient(const Scene& s, size_t k, int e) {
    const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
    auto xy = [&](const LatticePoint& p) {
        return std::array<double, 2>{double(p.i - c.i) * s.pitch_mm * 0.5, double(p.j - c.j) * s.pitch_mm / (2.0 * kSqrt3)};
    };
    const auto a = xy(hexCorner(s.grid, s.col[k], s.row[k], e)), b = xy(hexCorner(s.grid, s.col[k], s.row[k], (e + 1) % 6));
    const double za = s.zMm(cornerTop(s, k, e)) - s.zMm(s.top[k]), zb = s.zMm(cornerTop(s, k, (e + 1) % 6)) - s.zMm(s.top[k]);
    // The plane through (0, 0, 0), (a, za), (b, zb): z = gx x + gy y.
    const double det = a[0] * b[1] - a[1] * b[0];
    const double gx = (za * b[1] - zb * a[1]) / det, gy = (a[0] * zb - b[0] * za) / det;
    return std::hypot(gx, gy);
}

// A steep field leans no top more than --max-slope (every drawn fan
// triangle, after the corners' rounding to the z grid), and no corner rises
// more than a mark's height above the height range; the limited tops are
// counted and the model verifies.
TEST(Tilt, NoTopLeansMoreThanTheLimitOrRisesAboveTheRange) {
    for (const double limit : {kDefaultMaxSlopeDeg, 10.0, 45.0})
        for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
            SceneParams p = test::smallParams(bottom);
            p.tilt = TiltSource::Gradient;
            p.steepness = 50;
            p.max_slope_deg = limit;
            const Scene s = buildScene(cone(), p);
            EXPECT_GT(s.shapes.cells_slope_limited, 0) << limit;
            EXPECT_GT(s.shapes.cells_tilted, 40) << limit;
            const double max_gradient = std::tan(limit * M_PI / 180);
            const int64_t ceiling = s.floor_units + snapUnits(s.mapping.max_height_mm, s.z_snap_mm) +
                                    snapUnits(p.marks.triangle_height_mm, s.z_snap_mm);
            for (size_t k = 0; k < s.keptCount(); ++k) {
                if (!isShaped(s.shapes, k) || s.shapes.top_centre_dz[k] != 0) continue;
                for (int e = 0; e < 6; ++e) {
                    EXPECT_LE(fanGradient(s, k, e), max_gradient * (1 + 1e-9)) << "cell " << k << ", limit " << limit;
                    if (bottom == Bottom::Flat) EXPECT_LE(cornerTop(s, k, e), ceiling) << "cell " << k;
                }
            }
            expectVerified(s, "limited");
        }
}

TEST(Tilt, TheSlopeLimitIsCheckedAndFollowsThePrinter) {
    SceneParams p = test::smallParams();
    p.tilt = TiltSource::Gradient;
    for (const double bad : {0.0, -5.0, 61.0, double(NAN)}) {
        p.max_slope_deg = bad;
        EXPECT_THROW(buildScene(cone(), p), InputError) << bad;
    }
    // The default is the slope whose rim a 0.4 mm nozzle draws one 0.2 mm
    // layer down: atan(1/2).
    EXPECT_DOUBLE_EQ(maxSlopeDegFor(kDefaultSlopeNozzleMm, kDefaultSlopeLayerMm), kDefaultMaxSlopeDeg);
    EXPECT_NEAR(kDefaultMaxSlopeDeg, 26.565, 1e-3);
    EXPECT_NEAR(maxSlopeDegFor(0.4, 0.1), 14.036, 1e-3);
}

// The bundled airports with --tilt points: tops that were 5 um blades and
// 1 um gaps (and reached 36.7 mm on a 20 mm range) now verify with no wall
// or gap under the nozzle, no sharp point or knife edge, and most tops
// above the floor still lean; --layer and --nozzle set the limit for the
// printer, --max-slope overrides it.
TEST(Tilt, AirportsPointTiltsPrintAndRead) {
    const auto dir = test::scratchDir("tilt_airports_print");
    const std::string in = test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat --tilt points --json";
    const test::RunResult r = test::runTsf("gen " + in + " -o " + (dir / "eu.stl").string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.out);
    for (const char* id : {"wall_thickness", "gap_width", "tactile_sharp_points", "tactile_knife_edges"}) {
        bool found = false;
        for (const auto& c : j["verify"]["checks"])
            if (c["id"] == id) {
                found = true;
                EXPECT_EQ(c["status"], "pass") << id << ": " << c.dump();
            }
        EXPECT_TRUE(found) << id;
    }
    const auto& tilt = j["scene"]["tilt"];
    EXPECT_NEAR(tilt["max_slope_deg"].get<double>(), kDefaultMaxSlopeDeg, 1e-9);
    EXPECT_GT(tilt["cells_slope_limited"].get<int>(), 0);
    EXPECT_GT(tilt["cells_tilted"].get<int>(), j["scene"]["cells"]["nonempty"].get<int>() / 2);  // of 311 above the floor
    EXPECT_LE(j["mesh"]["bounds_mm"][1][2].get<double>(), 2.0 + 20.0 + 1.0 + 1e-9);  // base + range + a mark's height
    // The printer sets the limit; --max-slope overrides it.
    const auto fine = nlohmann::json::parse(
        test::runTsf("gen " + in + " --layer 0.1 -o " + (dir / "fine.stl").string(), dir).out);
    EXPECT_NEAR(fine["scene"]["tilt"]["max_slope_deg"].get<double>(), maxSlopeDegFor(0.4, 0.1), 1e-9);
    const auto chosen = nlohmann::json::parse(
        test::runTsf("gen " + in + " --layer 0.1 --max-slope 10 -o " + (dir / "chosen.stl").string(), dir).out);
    EXPECT_EQ(chosen["scene"]["tilt"]["max_slope_deg"].get<double>(), 10.0);
    // Steeper than the printer draws: the rims would not print.
    const test::RunResult steep = test::runTsf("gen " + in + " --layer 0.1 --max-slope 20 -o " + (dir / "steep.stl").string(), dir);
    EXPECT_EQ(steep.exit_code, 2) << steep.output;
    EXPECT_NE(steep.err.find("--max-slope (at most 14 degrees"), std::string::npos) << steep.err;
}

// A model whose walls would not print (pillars 0.3 mm across, thinner than
// the nozzle) is refused: exit 2, the walls' widths and places, nothing
// written; --keep-unprintable writes it.
TEST(Tilt, AModelWithWallsThinnerThanTheNozzleIsRefusedUnlessKept) {
    const auto dir = test::scratchDir("unprintable");
    test::writeText(dir / "board.csv", "0,1\n1,0\n0,1\n");
    const std::string out = (dir / "board.stl").string();
    const std::string args = "gen " + (dir / "board.csv").string() + " --cell 0.3 -o " + out;
    const test::RunResult refused = test::runTsf(args, dir);
    EXPECT_EQ(refused.exit_code, 2) << refused.output;
    EXPECT_NE(refused.err.find("walls thinner than the 0.4 mm nozzle"), std::string::npos) << refused.err;
    EXPECT_NE(refused.err.find("--keep-unprintable"), std::string::npos) << refused.err;
    EXPECT_FALSE(std::filesystem::exists(out));
    const test::RunResult kept = test::runTsf(args + " --keep-unprintable", dir);
    EXPECT_EQ(kept.exit_code, 0) << kept.output;
    EXPECT_NE(kept.out.find("warn      walls at least a nozzle wide"), std::string::npos) << kept.out;
    EXPECT_TRUE(std::filesystem::exists(out));
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
