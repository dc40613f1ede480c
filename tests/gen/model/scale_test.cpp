// The tactile scale (gen/model/features/scale.h): the step tsf chooses, the levels and their
// heights (worked out here by hand from the value -> height rule), where the
// staircase stands, and the joined mesh: one closed solid whose volume is the
// pillars' plus the scale's boxes, computed without the mesher.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include <nlohmann/json.hpp>

#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/field/hex_grid.h"
#include "gen/model/features/scale.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "gen/model/scene_json.h"
#include "gen/model/features/legend/legend.h"
#include "tests/support/fields.h"
#include "tests/support/input_error.h"
#include "tests/support/mesh_invariants.h"

namespace tsf {
namespace {

ValueMapping linear(double lo, double hi, double height_mm, Transfer t = Transfer::Linear) {
    ValueMapping m;
    m.transfer = t;
    m.baseline = lo;
    m.value_max = hi;
    m.max_height_mm = height_mm;
    return m;
}

TEST(ScaleStep, SmallestNiceStepWithTreadsAtLeastOneMillimetreApartAndAtMostTenSteps) {
    // 0..5 over 12 mm: 0.5 per step rises 1.2 mm and makes 10 steps.
    EXPECT_DOUBLE_EQ(*chooseScaleStep(linear(0, 5, 12), 0.01), 0.5);
    // 0..27 over 20 mm: ten steps need >= 2.7, so 5 (3.7 mm each), five steps.
    EXPECT_DOUBLE_EQ(*chooseScaleStep(linear(0, 27, 20), 0.001), 5.0);
    // 0..100 over 5 mm: 10 rises 0.5 mm (too little), 20 rises exactly 1 mm.
    EXPECT_DOUBLE_EQ(*chooseScaleStep(linear(0, 100, 5), 0.001), 20.0);
    // log: h = 10 log10(1 + 99 t) mm; 10 and 20 rise 0.45 and 0.96 mm at the top, 50 rises 2.97 mm.
    EXPECT_DOUBLE_EQ(*chooseScaleStep(linear(0, 100, 20, Transfer::Log), 0.001), 50.0);
    // Small numbers: 0..0.03 over 20 mm: ten steps need >= 0.003, so 0.005.
    EXPECT_DOUBLE_EQ(*chooseScaleStep(linear(0, 0.03, 20), 0.001), 0.005);
}

TEST(ScaleStep, NoStepForAConstantFieldOrARangeLowerThanOneRiser) {
    EXPECT_FALSE(chooseScaleStep(linear(3, 3, 20), 0.001).has_value());
    EXPECT_FALSE(chooseScaleStep(linear(0, 10, 0.8), 0.001).has_value());
}

TEST(ScaleLevels, MultiplesAboveTheBaselineAtThePillarsSnappedHeights) {
    // Baseline 13, 13..53 over 20 mm: 0.5 mm per data unit; z steps of 0.25 mm.
    std::string why;
    const std::vector<ScaleLevel> l = scaleLevels(linear(13, 53, 20), 10, 0.25, kScaleMaxSteps, &why);
    EXPECT_EQ(why, "");
    ASSERT_EQ(l.size(), 4u);  // 20, 30, 40, 50
    EXPECT_DOUBLE_EQ(l[0].value, 20);
    EXPECT_DOUBLE_EQ(l[3].value, 50);
    // (20 - 13) * 0.5 = 3.5 mm = 14 steps of 0.25 mm; 8.5 mm = 34; 13.5 mm = 54; 18.5 mm = 74.
    EXPECT_EQ(l[0].height_units, 14);
    EXPECT_EQ(l[1].height_units, 34);
    EXPECT_EQ(l[2].height_units, 54);
    EXPECT_EQ(l[3].height_units, 74);
}

TEST(ScaleLevels, AFirstLevelTooCloseToTheFloorIsLeftOutAndCloseLevelsAreRefused) {
    std::string why;
    // 0.9..10.9 over 10 mm: 1 sits 0.1 mm above the floor, left out; 2..10 rise 1 mm each.
    const std::vector<ScaleLevel> l = scaleLevels(linear(0.9, 10.9, 10), 1, 0.001, kScaleMaxSteps, &why);
    EXPECT_EQ(why, "");
    ASSERT_EQ(l.size(), 9u);
    EXPECT_DOUBLE_EQ(l.front().value, 2);
    EXPECT_EQ(l.front().height_units, 1100);
    // 0.5 per step over 0..10 in 10 mm rises 0.5 mm: refused, with the levels named.
    scaleLevels(linear(0, 10, 10), 0.5, 0.001, kScaleMaxSteps, &why);
    EXPECT_NE(why.find("differ by 0.5 mm"), std::string::npos) << why;
    // Too many steps.
    scaleLevels(linear(0, 1000, 100), 1, 0.001, kScaleMaxSteps, &why);
    EXPECT_NE(why.find("at most 40"), std::string::npos) << why;
}

// A small terrain: 0..5 over 12 mm on a 2 mm base, 0.01 mm z steps.
SceneParams scaleParams() {
    SceneParams p = test::smallParams();
    p.max_height_mm = 12.0;
    p.z_snap_mm = 0.01;
    p.requests.set(ScaleRequest{1.0});
    return p;
}

HexField terrain() {
    return test::fieldFromRows({
        {0.0, 1.0, 2.5, 3.0, 1.5, 2.0},
        {1.0, 4.0, 2.0, 2.0, 0.5, 1.0},
        {2.0, 3.5, 5.0, 4.5, 1.0, 4.0},
        {0.5, 2.0, 1.0, 3.0, 2.0, 3.0},
        {0.5, 2.0, 1.0, 3.0, 2.0, 3.0},
        {0.0, 1.0, 2.5, 3.0, 1.5, 2.0},
    });
}

TEST(ScalePlacement, TreadsAtThePillarsHeightsEastOfEveryPillarTouchingTheEastWalls) {
    const Scene s = buildScene(terrain(), scaleParams());
    ASSERT_TRUE(sceneScale(s));
    const SceneScale& sc = *sceneScale(s);
    EXPECT_TRUE(sc.step_given);
    ASSERT_EQ(sc.steps.size(), 5u);
    // 1 data unit = 12 / 5 = 2.4 mm = 240 z steps, above the 2 mm (200 step) floor.
    for (size_t i = 0; i < 5; ++i) {
        EXPECT_DOUBLE_EQ(sc.steps[i].value, double(i + 1));
        EXPECT_EQ(sc.steps[i].top_units, 200 + 240 * int64_t(i + 1));
    }
    EXPECT_EQ(sc.foot_top_units, 200);
    // The pillar of value 4 (col 1, row 1) and the step for 4 have one top.
    EXPECT_EQ(s.top[size_t(s.keptAt(1, 1))], sc.steps[3].top_units);
    // Nothing of the model lies east of the foot's west face; treads at least 6.4 x 12.7 mm.
    for (size_t k = 0; k < s.keptCount(); ++k)
        for (int e = 0; e < 6; ++e) EXPECT_LE(s.point(hexCorner(s.grid, s.col[k], s.row[k], e), 0).x, sc.x0_mm);
    EXPECT_NEAR(sc.x1_mm - sc.xs_mm, 12.7, 1e-9);
    EXPECT_NEAR(sc.xs_mm - sc.x0_mm, 4.0, 1e-9);
    for (const ScaleStep& st : sc.steps) EXPECT_GE(st.y_north_mm - st.y_south_mm, 6.4 - 1e-9);
    // It touches the east wall of every odd (east-shifted) row's last cell inside its y range, at x0.
    ASSERT_FALSE(sc.contacts.empty());
    for (const int32_t k : sc.contacts) {
        EXPECT_EQ(s.col[size_t(k)], 5);
        EXPECT_EQ(s.row[size_t(k)] % 2, 1);
        const Vec3 a = s.point(hexCorner(s.grid, 5, s.row[size_t(k)], 0), 0);
        const Vec3 b = s.point(hexCorner(s.grid, 5, s.row[size_t(k)], 1), 0);
        EXPECT_DOUBLE_EQ(a.x, sc.x0_mm);
        EXPECT_DOUBLE_EQ(b.x, sc.x0_mm);
        EXPECT_GT(a.y, sc.y0_mm);
        EXPECT_LT(b.y, sc.y1_mm);
    }
}

TEST(ScaleMesh, JoinedModelIsOneClosedSolidOfThePillarsPlusTheScaleBoxes) {
    const Scene s = buildScene(terrain(), scaleParams());
    ASSERT_TRUE(sceneScale(s));
    const SceneScale& sc = *sceneScale(s);
    double boxes = (sc.x1_mm - sc.x0_mm) * (sc.y1_mm - sc.y0_mm) * s.zMm(sc.foot_top_units);
    for (const ScaleStep& st : sc.steps)
        boxes += (sc.x1_mm - sc.xs_mm) * (st.y_north_mm - st.y_south_mm) * s.zMm(st.top_units - sc.foot_top_units);
    // The notches between contacts, filled to the floor: quadrilaterals of
    // hexagon corners (the lower contact's upper-right and top, the upper's
    // bottom and lower-right), by the shoelace formula.
    ASSERT_EQ(sc.fillers.size() + 1, sc.contacts.size());
    ASSERT_GE(sc.contacts.size(), 2u);
    for (size_t n = 0; n + 1 < sc.contacts.size(); ++n) {
        const size_t lo = size_t(sc.contacts[n]), hi = size_t(sc.contacts[n + 1]);
        const Vec3 q[4] = {s.point(hexCorner(s.grid, s.col[lo], s.row[lo], 1), 0),
                           s.point(hexCorner(s.grid, s.col[hi], s.row[hi], 0), 0),
                           s.point(hexCorner(s.grid, s.col[hi], s.row[hi], 5), 0),
                           s.point(hexCorner(s.grid, s.col[lo], s.row[lo], 2), 0)};
        double area2 = 0;
        for (int k = 0; k < 4; ++k) area2 += q[k].x * q[(k + 1) % 4].y - q[(k + 1) % 4].x * q[k].y;
        EXPECT_GT(area2, 0);
        boxes += area2 / 2 * s.zMm(sc.foot_top_units);
    }

    const Mesh m = meshScene(s);
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(inv.euler, 2);
    EXPECT_NEAR(inv.volume, test::sceneVolume(s) + boxes, 1e-6 * inv.volume);

    // The scale alone is a closed body of its own (a part of a multi-part file).
    const JoinedBody body = meshScaleBody(s, /*joined=*/false);
    const test::Invariants own = test::checkInvariants(body.mesh);
    EXPECT_TRUE(own.closedManifold()) << own.describe();
    EXPECT_EQ(own.components, 1u);
    EXPECT_NEAR(own.volume, boxes, 1e-9 * boxes);
    // Every vertex on the 1 um grid and the z grid.
    for (const Vec3& p : m.positions) {
        EXPECT_NEAR(p.x * 1000, std::round(p.x * 1000), 1e-6);
        EXPECT_NEAR(p.y * 1000, std::round(p.y * 1000), 1e-6);
        EXPECT_NEAR(p.z / s.z_snap_mm, std::round(p.z / s.z_snap_mm), 1e-6);
    }
}

TEST(ScaleMesh, BesideTiltedTopsAndTheOrientationMarks) {
    SceneParams p = scaleParams();
    p.marks = MarkParams{};
    p.tilt = TiltSource::Gradient;
    p.steepness = 3.0;
    const Scene s = buildScene(terrain(), p);
    ASSERT_TRUE(sceneScale(s));
    const test::Invariants inv = test::checkInvariants(meshScene(s));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
}

TEST(ScalePlacement, KeepsClearOfTheBrailleLegend) {
    // Floor rows in the north (culled) under the legend, a tall terrain south of them.
    HexField f = test::fieldFromFunction(12, 16, [](int c, int r) { return r < 3 ? 0.0 : 1.0 + (c + r) % 5; });
    SceneParams p = scaleParams();
    p.pitch_mm = 6.0;
    p.words.title = "Depth";
    const Scene s = buildScene(f, p);
    ASSERT_TRUE(sceneLegend(s) != nullptr);
    ASSERT_TRUE(sceneScale(s));
    EXPECT_LE(sceneScale(s)->y1_mm + kScaleClearanceMm, sceneLegend(s)->plate_south_mm);
    const test::Invariants inv = test::checkInvariants(meshScene(s));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);

    // Too short a model for five steps below the legend: refused, saying what to change.
    HexField low = test::fieldFromFunction(12, 5, [](int c, int r) { return r < 3 ? 0.0 : 1.0 + (c + r) % 5; });
    const InputError e = test::catchInputError([&] { buildScene(low, p); });
    EXPECT_NE(std::string(e.what()).find("braille legend"), std::string::npos) << e.what();
    // No step fits, down to two: it says so rather than asking for a larger one.
    EXPECT_NE(std::string(e.what()).find("no --scale-step fits"), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).find("larger --scale-step"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("Leave out --title/--units (the plate north of the pillars) or --scale"), std::string::npos)
        << e.what();
}

TEST(ScalePlacement, RefusedOnAMirroredModelAFlatFieldAndTooFineASteps) {
    SceneParams p = scaleParams();
    p.bottom = Bottom::Mirrored;
    EXPECT_NE(std::string(test::catchInputError([&] { buildScene(terrain(), p); }).what()).find("--mirror"),
              std::string::npos);
    p = scaleParams();
    p.baseline_mode = BaselineMode::Min;  // every value at the baseline: one height
    const HexField flat = test::fieldFromFunction(4, 4, [](int, int) { return 2.0; });
    EXPECT_NE(std::string(test::catchInputError([&] { buildScene(flat, p); }).what()).find("nothing to measure"),
              std::string::npos);
    p = scaleParams();
    p.requests.set(ScaleRequest{0.1});  // 0.24 mm apart
    const InputError e = test::catchInputError([&] { buildScene(terrain(), p); });
    EXPECT_NE(std::string(e.what()).find("--scale-step 0.5"), std::string::npos) << e.what();
}

TEST(ScaleSidecar, RecordedAsPlacedAndReadAsRecorded) {
    const Scene s = buildScene(terrain(), scaleParams());
    ASSERT_TRUE(sceneScale(s));
    nlohmann::json j = sceneToJson(s);
    const Scene back = sceneFromJson(j);
    ASSERT_TRUE(sceneScale(back));
    EXPECT_EQ(sceneScale(back)->steps.size(), sceneScale(s)->steps.size());
    EXPECT_EQ(sceneScale(back)->contacts, sceneScale(s)->contacts);
    EXPECT_EQ(sceneScale(back)->fillers, sceneScale(s)->fillers);
    EXPECT_EQ(sceneScale(back)->steps.back().top_units, sceneScale(s)->steps.back().top_units);
    EXPECT_EQ(meshScene(back).triangles.size(), meshScene(s).triangles.size());
    // Reading places nothing: a tread recorded one step higher is read as
    // recorded (the verifier's read-back then tells it from the mesh).
    j["scale"]["steps"][0][1] = j["scale"]["steps"][0][1].get<int64_t>() + 1;
    const Scene moved = sceneFromJson(j);
    ASSERT_TRUE(sceneScale(moved));
    EXPECT_EQ(sceneScale(moved)->steps[0].top_units, sceneScale(s)->steps[0].top_units + 1);
}


// An outline whose east side reaches its easternmost line in two rows only
// (a spur at its south end, as a projected map's corner has): there the
// foot would touch one pillar wall, a joint a hand snaps. The foot steps
// back west to the line where a run of rows ends and stands against them.
HexField spurField() {
    return test::fieldFromFunction(12, 20, [](int c, int r) {
        if (c == 11) return r == 18 || r == 19 ? 3.0 : test::kNaN;
        return 1.0 + (c + r) % 4;
    });
}

TEST(ScalePlacement, StepsBackFromASpurToTheLongestRunOfTheEastSide) {
    const Scene s = buildScene(spurField(), scaleParams());
    ASSERT_TRUE(sceneScale(s));
    const SceneScale& sc = *sceneScale(s);
    int64_t i_east = INT64_MIN;
    for (size_t k = 0; k < s.keptCount(); ++k) i_east = std::max(i_east, hexCentre(s.grid, s.col[k], s.row[k]).i + 1);
    // The spur's line holds one contact; the line one cell west, a run of rows.
    EXPECT_EQ(sc.x0_i, i_east - 2);
    EXPECT_GE(sc.contacts.size(), 3u);
    for (const int32_t k : sc.contacts) EXPECT_EQ(s.col[size_t(k)], 10);
    // Every kept cell beside the foot lies west of it; none overlaps it.
    for (size_t k = 0; k < s.keptCount(); ++k)
        for (int e = 0; e < 6; ++e) {
            const Vec3 p = s.point(hexCorner(s.grid, s.col[k], s.row[k], e), 0);
            if (p.y > sc.y0_mm && p.y < sc.y1_mm) EXPECT_LE(p.x, sc.x0_mm) << "cell " << s.col[k] << "," << s.row[k];
        }
    const test::Invariants inv = test::checkInvariants(meshScene(s));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(inv.duplicate_positions, 0u);
    // The sidecar keeps it.
    const Scene back = sceneFromJson(sceneToJson(s));
    ASSERT_TRUE(sceneScale(back));
    EXPECT_EQ(sceneScale(back)->contacts, sc.contacts);
    EXPECT_EQ(sceneScale(back)->fillers, sc.fillers);
}

// A bay six cells deep in the east side, left open by concave culling:
// the run that holds the staircase spans it, touching the rows north and
// south of it, and the foot's west face stands free across the bay (no
// filler there, -1). Still one closed solid (the bay a hole down to the
// bed that the foot closes into a ring), and the scale alone is one.
TEST(ScalePlacement, StandsFreeAcrossABayBetweenTwoContacts) {
    const HexField f = test::fieldFromFunction(10, 14, [](int c, int r) {
        return r >= 4 && r <= 9 && c >= 2 ? test::kNaN : 1.0 + (c + 2 * r) % 9;
    });
    SceneParams p = scaleParams();
    p.cull = Cull::Concave;
    p.requests.set(ScaleRequest{});
    const Scene s = buildScene(f, p);
    ASSERT_TRUE(sceneScale(s));
    const SceneScale& sc = *sceneScale(s);
    ASSERT_EQ(sc.fillers.size() + 1, sc.contacts.size());
    ASSERT_NE(std::find(sc.fillers.begin(), sc.fillers.end(), -1), sc.fillers.end());
    // Contacts on both sides of the bay (rows 4..9).
    bool north = false, south = false;
    for (const int32_t k : sc.contacts) {
        north = north || s.row[size_t(k)] < 4;
        south = south || s.row[size_t(k)] > 9;
    }
    EXPECT_TRUE(north && south);
    const test::Invariants inv = test::checkInvariants(meshScene(s));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    // The foot closes a ring around each bay it spans: a hole down to the
    // bed, one handle (genus 1) per gap.
    const long gaps = long(std::count(sc.fillers.begin(), sc.fillers.end(), -1));
    EXPECT_EQ(inv.euler, 2 - 2 * gaps);
    EXPECT_EQ(inv.duplicate_positions, 0u);
    const test::Invariants own = test::checkInvariants(meshScaleBody(s, /*joined=*/false).mesh);
    EXPECT_TRUE(own.closedManifold()) << own.describe();
    EXPECT_EQ(own.components, 1u);
    const Scene back = sceneFromJson(sceneToJson(s));
    ASSERT_TRUE(sceneScale(back));
    EXPECT_EQ(sceneScale(back)->fillers, sc.fillers);
}

}  // namespace
}  // namespace tsf
