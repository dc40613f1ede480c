// Orientation marks (notch, triangle) and faithful models: checked on the
// mesh and by the verifier, never by re-running the placement code.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/model/features/marks.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "gen/model/scene_json.h"
#include "tests/support/fields.h"
#include "tests/support/mesh_invariants.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {
using test::checkInvariants;
using test::fieldFromFunction;
using test::fieldFromRows;
using test::kNaN;

// The marks placed in the data (--marks-on data), which these tests are
// about; the orientation tab has its own (tests/gen/cli/orientation_tab_cli_test.cpp).
SceneParams params(double pitch, Bottom bottom = Bottom::Flat) {
    SceneParams p;
    p.marks.place = MarkPlace::Data;
    p.pitch_mm = pitch;
    p.max_height_mm = 10.0;
    p.base_mm = 2.0;
    p.bottom = bottom;
    return p;
}

// The mesh is one closed, outward solid, and the verifier reads every pillar
// back at its height (under the triangle: its height plus the mark's).
void expectSoundModel(const Scene& scene, const Mesh& mesh) {
    const test::Invariants inv = checkInvariants(mesh);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(inv.euler, 2);
    EXPECT_GT(inv.volume, 0);
    VerifyOptions vo;
    const VerifyReport r = verifyModel(mesh, &scene, vo);
    EXPECT_TRUE(r.passed()) << formatReport(r);
}

// Volume (mm^3) of the Scene's prisms, summed independently of any mesh.
double prismVolume(const Scene& s) {
    double v = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) v += hexArea(s.pitch_mm, s.y_scale) * s.zMm(s.top[k] - s.bottom[k]);
    return v;
}

// Height of the top surface at (x, y): the highest z of a triangle over that point.
double topAt(const Mesh& m, double x, double y) {
    double best = -INFINITY;
    for (const auto& t : m.triangles) {
        const Vec3 &a = m.positions[t[0]], &b = m.positions[t[1]], &c = m.positions[t[2]];
        const double d = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
        if (std::fabs(d) < 1e-12) continue;
        const double u = ((b.x - x) * (c.y - y) - (b.y - y) * (c.x - x)) / d;
        const double v = ((c.x - x) * (a.y - y) - (c.y - y) * (a.x - x)) / d;
        const double w = 1 - u - v;
        if (u < -1e-9 || v < -1e-9 || w < -1e-9) continue;
        best = std::max(best, u * a.z + v * b.z + w * c.z);
    }
    return best;
}

TEST(Notch, EveryDefaultModelHasOneAtTheSouthWestCornerAndItRemovesMaterial) {
    const HexField f = fieldFromFunction(6, 6, [](int c, int r) { return 1.0 + (c * 7 + r * 3) % 5; });
    const Scene scene = buildScene(f, params(10.0));
    ASSERT_TRUE(scene.marks.notch.has_value());
    EXPECT_NEAR(scene.marks.notch->depth_mm, 6.0, 1e-9);  // 10 mm cells leave room for the full depth
    const double ax = planarX(scene.marks.notch->apex, scene.pitch_mm);
    const double ay = planarY(scene.marks.notch->apex, scene.pitch_mm, scene.y_scale);
    EXPECT_LT(ax, 10.0);  // the south-west corner of a 60 x 46 mm model
    EXPECT_LT(ay, 10.0);
    const Mesh mesh = meshScene(scene);
    expectSoundModel(scene, mesh);
    // The cut is felt: at least (depth x opening) / 2 x height of material goes.
    EXPECT_LT(signedVolume(mesh), prismVolume(scene) - 0.5 * 6.0 * 6.0 * std::tan(M_PI / 6) * 2.0);
    // Nothing just inside the V, on its way from the apex to the mouth: a ray there meets nothing.
    const double mx = 0.5 * (planarX(scene.marks.notch->mouth_a, scene.pitch_mm) + planarX(scene.marks.notch->mouth_b, scene.pitch_mm));
    const double my = 0.5 * (planarY(scene.marks.notch->mouth_a, scene.pitch_mm, scene.y_scale) + planarY(scene.marks.notch->mouth_b, scene.pitch_mm, scene.y_scale));
    const double len = std::hypot(mx - ax, my - ay);
    EXPECT_EQ(topAt(mesh, ax + 0.5 * (mx - ax) / len, ay + 0.5 * (my - ay) / len), -INFINITY);
}

TEST(Notch, MirroredModelIsCutThroughBothHalves) {
    const HexField f = fieldFromFunction(5, 5, [](int c, int r) { return double((c + 2 * r) % 4); });
    const Scene scene = buildScene(f, params(9.0, Bottom::Mirrored));
    ASSERT_TRUE(scene.marks.notch.has_value());
    const Mesh mesh = meshScene(scene);
    expectSoundModel(scene, mesh);
    EXPECT_LT(signedVolume(mesh), prismVolume(scene) - 1.0);
}

TEST(Notch, OnOneCellAndOnOneRow) {
    for (const auto& rows : {std::vector<std::vector<double>>{{5}}, std::vector<std::vector<double>>{{1, 2, 3, 4, 5}}}) {
        const Scene scene = buildScene(fieldFromRows(rows), params(20.0));
        ASSERT_TRUE(scene.marks.notch.has_value()) << rows[0].size();
        expectSoundModel(scene, meshScene(scene));
    }
}

TEST(Notch, TooSmallCellsLeaveItOutWithANote) {
    SceneParams p = params(1.0);
    const Scene scene = buildScene(fieldFromFunction(8, 8, [](int c, int) { return c; }), p);
    EXPECT_FALSE(scene.marks.notch.has_value());
    bool noted = false;
    for (const std::string& n : scene.notes) noted = noted || n.find("notch left out") != std::string::npos;
    EXPECT_TRUE(noted);
}

TEST(Notch, NeverRemovesAPillar) {
    // Small cells: the notch is shallower, and every pillar is still read back.
    for (double pitch : {2.5, 3.0, 3.7, 4.5, 6.0}) {
        const Scene scene = buildScene(fieldFromFunction(12, 10, [](int c, int r) { return 1.0 + (c + r) % 3; }), params(pitch));
        expectSoundModel(scene, meshScene(scene));
    }
}

// A field with a wide flat floor (value 0) and a ridge: the triangle goes on the floor.
HexField floorAndRidge() {
    HexField f = fieldFromFunction(14, 12, [](int c, int r) { return c >= 11 ? 5.0 + r % 3 : (c == 0 && r == 0 ? 1.0 : 0.0); });
    f.one_to_one = true;  // every 0 is a typed value and keeps its pillar
    return f;
}

TEST(Triangle, StandsOnTheLargestFlatRegionWithTheLongerLegEast) {
    const Scene scene = buildScene(floorAndRidge(), params(5.0));
    ASSERT_TRUE(scene.marks.triangle.has_value());
    const OrientationTriangle& t = *scene.marks.triangle;
    const double p = scene.pitch_mm;
    // Right angle at the south-west corner; x leg east, y leg north, x the longer.
    EXPECT_NEAR(planarY(t.east, p, scene.y_scale), planarY(t.corner, p, scene.y_scale), 1e-9);
    EXPECT_NEAR(planarX(t.north, p), planarX(t.corner, p), 1e-9);
    const double lx = planarX(t.east, p) - planarX(t.corner, p), ly = planarY(t.north, p, scene.y_scale) - planarY(t.corner, p, scene.y_scale);
    EXPECT_GT(lx, 0);
    EXPECT_GT(ly, 0);
    EXPECT_NEAR(ly / lx, kTriangleLegRatio, 1e-9);
    EXPECT_GE(lx, 12.7);
    EXPECT_EQ(scene.top[size_t(t.anchor)], scene.floor_units);  // on the floor, the largest flat region
    const Mesh mesh = meshScene(scene);
    expectSoundModel(scene, mesh);
    // Raised by 1 mm inside, not outside.
    const double cx = planarX(t.corner, p) + lx / 3, cy = planarY(t.corner, p, scene.y_scale) + ly / 3;
    EXPECT_NEAR(topAt(mesh, cx, cy), scene.zMm(scene.floor_units) + 1.0, 1e-6);
    EXPECT_NEAR(topAt(mesh, planarX(t.corner, p) - 0.5, planarY(t.corner, p, scene.y_scale) - 0.5), scene.zMm(scene.floor_units), 1e-6);
}

TEST(Triangle, MirroredModelKeepsItOnTopAndStaysSound) {
    const Scene scene = buildScene(floorAndRidge(), params(5.0, Bottom::Mirrored));
    ASSERT_TRUE(scene.marks.triangle.has_value());
    expectSoundModel(scene, meshScene(scene));
}

TEST(Triangle, InsideOneLargeCell) {
    // Big cells: the triangle fits inside one hexagon (a face with a hole).
    HexField f = fieldFromRows({{0, 0, 0}, {0, 3, 0}, {0, 0, 0}});
    f.one_to_one = true;
    const Scene scene = buildScene(f, params(40.0));
    ASSERT_TRUE(scene.marks.triangle.has_value());
    expectSoundModel(scene, meshScene(scene));
}

TEST(Triangle, ThatDoesNotFitIsLeftOutWithANote) {
    const Scene scene = buildScene(fieldFromFunction(6, 6, [](int c, int r) { return double((c * 3 + r * 5) % 7); }), params(4.0));
    EXPECT_FALSE(scene.marks.triangle.has_value());
    bool noted = false;
    for (const std::string& n : scene.notes) noted = noted || n.find("triangle left out") != std::string::npos;
    EXPECT_TRUE(noted);
    expectSoundModel(scene, meshScene(scene));
}

TEST(Marks, CanBeTurnedOff) {
    SceneParams p = params(5.0);
    p.marks.notch = false;
    p.marks.triangle = false;
    const Scene scene = buildScene(floorAndRidge(), p);
    EXPECT_FALSE(scene.marks.notch || scene.marks.triangle);
    EXPECT_TRUE(scene.faces.empty());
    const Mesh mesh = meshScene(scene);
    // Equal up to the 1 um rounding of the corners.
    EXPECT_NEAR(signedVolume(mesh), prismVolume(scene), 1e-4 * prismVolume(scene));
}

TEST(Marks, SurviveTheSceneSidecar) {
    const Scene scene = buildScene(floorAndRidge(), params(5.0));
    ASSERT_TRUE(scene.marks.notch && scene.marks.triangle);
    const Scene back = sceneFromJson(sceneToJson(scene));
    const Mesh a = meshScene(scene), b = meshScene(back);
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    EXPECT_EQ(a.positions, b.positions);
    EXPECT_EQ(a.triangles, b.triangles);
}

TEST(Marks, OlderSidecarWithAMarkThatDoesNotFitIsAnInputError) {
    // Up to version 4 a sidecar holds the marks alone and reading builds
    // their faces again; since version 5 it holds the faces as built and
    // the verifier's marks read-back judges them against the mesh.
    nlohmann::json j = sceneToJson(buildScene(floorAndRidge(), params(5.0)));
    j["version"] = 4;
    j.erase("faces");
    for (auto& c : j["cells"]) c.erase("fan");
    EXPECT_NO_THROW(sceneFromJson(j));
    j["marks"]["notch"]["apex"] = {1000.0, 1000.0};  // a V across the whole model
    EXPECT_THROW(sceneFromJson(j), InputError);
}

// Awkward fields: every one a single closed solid that reads back.
TEST(FaithfulModels, AwkwardFieldsAreSoundSolids) {
    const std::vector<std::pair<const char*, HexField>> fields = {
        {"1x1", fieldFromRows({{3}})},
        {"1xN", fieldFromRows({{1, 2, 3, 4, 5, 6}})},
        {"Nx1", fieldFromRows({{1}, {2}, {3}, {4}})},
        {"one non-zero", fieldFromFunction(7, 7, [](int c, int r) { return c == 3 && r == 3 ? 4.0 : 0.0; })},
        {"all zero", fieldFromFunction(5, 5, [](int, int) { return 0.0; })},
        {"constant", fieldFromFunction(5, 5, [](int, int) { return 7.0; })},
        {"checkerboard", fieldFromFunction(8, 8, [](int c, int r) { return double((c + r) % 2); })},
        {"no data inside", fieldFromRows({{1, 2, 3}, {4, kNaN, 6}, {7, 8, 9}})},
    };
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored})
        for (const auto& [name, f] : fields) {
            SCOPED_TRACE(std::string(name) + (bottom == Bottom::Mirrored ? " mirrored" : " flat"));
            const Scene scene = buildScene(f, params(12.0, bottom));
            expectSoundModel(scene, meshScene(scene));
        }
}

TEST(FaithfulModels, NoDataIsAPitBelowTheFloorNotTheLowestValue) {
    for (Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        HexField f = fieldFromRows({{0, 2, 3}, {4, kNaN, 6}, {7, 8, 0}});
        f.one_to_one = true;
        const Scene s = buildScene(f, params(12.0, bottom));
        const int32_t hole = s.keptAt(1, 1), zero = s.keptAt(0, 0);
        ASSERT_GE(hole, 0);
        EXPECT_EQ(s.kind[size_t(hole)], CellKind::NoData);
        EXPECT_EQ(s.kind[size_t(zero)], CellKind::Data);
        // 2 mm base: the pit is 1 mm deep, below the lowest value's top.
        EXPECT_EQ(s.top[size_t(zero)] - s.top[size_t(hole)], 1000);
        if (bottom == Bottom::Mirrored) EXPECT_EQ(s.bottom[size_t(hole)] - s.bottom[size_t(zero)], 1000);
        expectSoundModel(s, meshScene(s));
    }
}

TEST(FaithfulModels, TypedZerosKeepTheirPillars) {
    // 16 values, zeros on the outside: 16 pillars, each at its own value.
    HexField f = fieldFromRows({{0, 0, 0, 0}, {0, 5, 6, 0}, {0, 7, 8, 0}, {0, 0, 0, 0}});
    f.one_to_one = true;
    const Scene s = buildScene(f, params(10.0));
    EXPECT_EQ(s.keptCount(), 16u);
    EXPECT_TRUE(s.one_to_one);
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.value[k], f.at(s.col[k], s.row[k]));
}

TEST(FaithfulModels, CellAndBoxThatDisagreeAreAnError) {
    SceneParams p = params(10.0);
    p.fit_width_mm = 50;
    p.fit_box_given = true;
    EXPECT_THROW(buildScene(fieldFromFunction(10, 3, [](int, int) { return 1.0; }), p), InputError);
    p.fit_width_mm = 200;
    EXPECT_NO_THROW(buildScene(fieldFromFunction(10, 3, [](int, int) { return 1.0; }), p));
}

TEST(FaithfulModels, CellsBelowTheTactileMinimumAreNoted) {
    const Scene s = buildScene(fieldFromFunction(4, 4, [](int c, int) { return c; }), params(2.0));
    bool noted = false;
    for (const std::string& n : s.notes) noted = noted || n.find("fingertip") != std::string::npos;
    EXPECT_TRUE(noted);
}

}  // namespace
}  // namespace tsf
