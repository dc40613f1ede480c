// The feature registry (gen/model/feature_registry.h): its features in the
// order they are placed, phase by phase, and the lists that read each phase
// where its features stood: the orientation tab, placed with the marks,
// comes first among the bodies, last among the bed widths, and is read
// back in the marks' own set.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gen/model/attachments.h"
#include "gen/model/build_scene.h"
#include "gen/model/feature_registry.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/legend/legend.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/model/scene_scale.h"
#include "gen/util/error.h"
#include "tests/support/fields.h"
#include "verify/tactile.h"

namespace tsf {
namespace {

// A 20 x 12 raster of a gentle hill, every value above the floor: room
// for the tab west of the pillars and the scale east of them.
HexField hill() {
    return test::fieldFromFunction(20, 12, [](int c, int r) { return 5.0 + std::sin(0.3 * c) + std::cos(0.4 * r); });
}

// The marks on the tab (the default) and the tactile scale.
SceneParams tabAndScale() {
    SceneParams p = test::smallParams();
    p.marks = MarkParams{};
    p.pitch_mm = 3.0;
    p.requests.set(ScaleRequest{});
    return p;
}

TEST(FeatureRegistry, TheTexturesAreDecidedFirstThenTheLegendThenTheTabWithTheMarksThenTheFeaturesBesideThePillars) {
    const std::vector<const Feature*>& all = features();
    ASSERT_GE(all.size(), 3u);
    EXPECT_STREQ(all[0]->name, "class_textures");
    EXPECT_EQ(all[0]->phase, FeaturePhase::Frame);
    EXPECT_STREQ(all[1]->name, "legend");
    EXPECT_EQ(all[1]->phase, FeaturePhase::BeforeMarks);
    EXPECT_STREQ(all[2]->name, "marks.tab");
    EXPECT_EQ(all[2]->phase, FeaturePhase::Marks);
    // The phases split the registry in its own order, as buildScene places
    // them: Frame, UnderTops, BeforeMarks, then Marks, then Beside; a tile
    // (UnderTops) is last in the registry.
    EXPECT_EQ(featuresOf({FeaturePhase::Frame, FeaturePhase::BeforeMarks, FeaturePhase::Marks, FeaturePhase::Beside,
                          FeaturePhase::UnderTops}),
              all);
    EXPECT_EQ(featuresOf({FeaturePhase::Marks}).size(), 1u);
    EXPECT_EQ(featuresOf({FeaturePhase::Frame}).size(), 1u);
    ASSERT_EQ(featuresOf({FeaturePhase::UnderTops}).size(), 1u);
    EXPECT_STREQ(featuresOf({FeaturePhase::UnderTops})[0]->name, "tile");
    // Asked in another order, phase by phase in that order.
    const std::vector<const Feature*> marks_first =
        featuresOf({FeaturePhase::Marks, FeaturePhase::BeforeMarks, FeaturePhase::Beside});
    ASSERT_EQ(marks_first.size(), all.size() - 2);
    EXPECT_STREQ(marks_first[0]->name, "marks.tab");
    EXPECT_STREQ(marks_first[1]->name, "legend");
}

TEST(FeatureRegistry, TheTabComesFirstAmongTheBodiesAndIsReadBackWithTheMarks) {
    const Scene s = buildScene(hill(), tabAndScale());
    ASSERT_TRUE(sceneTab(s) != nullptr) << (s.notes.empty() ? "" : s.notes.back());
    ASSERT_TRUE(s.features.get<SceneScale>());

    std::vector<std::string> parts;
    for (const Attachment& a : sceneAttachments(s, Assembly::OnePiece)) parts.push_back(a.part);
    EXPECT_EQ(parts, (std::vector<std::string>{"marks", "scale"}));

    // One set named "marks", last, holding the tab's places and no mark in
    // the data (there is none on a tab).
    const std::vector<ProbeSet> sets = sceneProbes(s);
    std::vector<std::string> names;
    for (const ProbeSet& set : sets) names.push_back(set.name);
    ASSERT_EQ(names, (std::vector<std::string>{"scale", "marks"}));
    EXPECT_EQ(sets.back().title, kMarkProbesTitle);
    ASSERT_FALSE(sets.back().probes.empty());
    EXPECT_EQ(sets.back().probes.front().what, "the orientation tab's top");
    for (const SurfaceProbe& p : sets.back().probes) EXPECT_NE(p.what, "inside the orientation notch") << "a notch in the data";

    // Its box is the first, west of every pillar.
    const std::vector<BoxMm> boxes = attachmentBoxes(s);
    ASSERT_EQ(boxes.size(), 2u);
    EXPECT_LT(boxes[0].x1, boxes[1].x0);
    EXPECT_DOUBLE_EQ(boxes[0].x0, sceneTab(s)->x_west_mm);
}

TEST(FeatureRegistry, TheTabsBedWidthComesAfterTheFeaturesBesideThePillars) {
    std::vector<std::string> what;
    for (const SideWidth& w : attachmentSideWidths(tabAndScale())) what.push_back(w.what);
    EXPECT_EQ(what, (std::vector<std::string>{"the tactile scale", "the orientation tab"}));

    // The marks in the data: no tab, no width for it, and the marks read
    // back in the data.
    SceneParams in_data = tabAndScale();
    in_data.marks.place = MarkPlace::Data;
    what.clear();
    for (const SideWidth& w : attachmentSideWidths(in_data)) what.push_back(w.what);
    EXPECT_EQ(what, (std::vector<std::string>{"the tactile scale"}));
}

// A feature that measures heights (the scale) is refused, before it is
// placed, where a feature of the frame stands every value at one height
// (a class map's textures), with that feature's reason; with the classes
// given an order they stand at heights and the scale stands.
TEST(FeatureRegistry, AFeatureThatMeasuresHeightsIsRefusedWhereAFeatureStandsEveryValueAtOneHeight) {
    HexField classes = test::fieldFromFunction(10, 6, [](int c, int r) { return c < 5 ? 41.0 : r < 2 ? 90.0 : 11.0; });
    classes.input.categorical = true;
    SceneParams p = tabAndScale();
    try {
        buildScene(classes, p);
        ADD_FAILURE() << "the scale was placed on a class map at one height";
    } catch (const InputError& e) {
        EXPECT_EQ(std::string(e.what()).rfind("--scale measures heights, and a class map has one height", 0), 0u)
            << e.what();
    }
    const Scene plain = buildScene(classes, test::smallParams());
    ASSERT_TRUE(featureOneHeight(plain));
    EXPECT_TRUE(featureTopShaping(plain)) << "its classes are told apart by their tops";
    EXPECT_FALSE(featureClassMarks(plain).empty());

    // Ordered classes (ranks, one even step each): the heights are the
    // value mapping's, nothing is said instead of them, the scale stands.
    HexField ordered = test::fieldFromFunction(10, 6, [](int c, int r) { return c < 5 ? 1.0 : r < 2 ? 2.0 : 3.0; });
    ordered.input.categorical = true;
    ordered.input.class_order = {41, 90, 11};
    const Scene measured = buildScene(ordered, p);
    EXPECT_FALSE(featureOneHeight(measured));
    EXPECT_FALSE(featureTopShaping(measured));
    EXPECT_TRUE(featureClassMarks(measured).empty());
    EXPECT_TRUE(sceneMeasures(measured));
}

// The features' thresholds join the tactile check's table after the rows
// of the check they belong to.
TEST(FeatureRegistry, TheFeaturesThresholdsFollowTheRowsOfTheirCheck) {
    const std::vector<FeatureThreshold> own = featureThresholds();
    ASSERT_FALSE(own.empty());
    const std::vector<TactileThreshold>& table = tactileThresholds();
    for (const FeatureThreshold& f : own) {
        size_t at = table.size();
        for (size_t i = 0; i < table.size(); ++i)
            if (std::string(table[i].what) == f.what) at = i;
        ASSERT_LT(at, table.size()) << f.what;
        EXPECT_STREQ(table[at].id, f.check);
        EXPECT_EQ(table[at].value, f.value);
        EXPECT_STREQ(table[at - 1].id, f.check) << f.what << " follows a row of another check";
    }
}

// The tactile check proves the braille a feature prints from its
// BrailleClaim, without naming the legend: one claim with a title, its
// dots the legend's and the first on the plate's top; none without one.
TEST(FeatureRegistry, TheBrailleAFeaturePrintsIsCheckedFromItsClaim) {
    SceneParams p = test::smallParams();
    p.pitch_mm = 3.0;
    p.words.title = "Hill";
    const Scene titled = buildScene(hill(), p);
    const SceneLegend* legend = sceneLegend(titled);
    ASSERT_NE(legend, nullptr);
    const std::vector<BrailleClaim> claims = featureBraille(titled);
    ASSERT_EQ(claims.size(), 1u);
    const BrailleClaim& b = claims[0];
    ASSERT_FALSE(legend->layout.dots.empty());
    EXPECT_EQ(b.dots, legend->layout.dots.size());
    EXPECT_STREQ(b.standard.name, legend->layout.standard.name);
    EXPECT_EQ(b.standard.dot_height_mm, legend->layout.standard.dot_height_mm);
    EXPECT_DOUBLE_EQ(b.first_dot_mm.x, legend->layout.dots[0].x_mm + legend->x0_mm);
    EXPECT_DOUBLE_EQ(b.first_dot_mm.y, legend->layout.dots[0].y_mm + legend->y0_mm);
    EXPECT_DOUBLE_EQ(b.first_dot_mm.z, titled.zMm(legend->plate_top_units));

    TactileOptions o;
    o.layer_mm = 0.2;
    const TactileResult r = checkTactile(meshScene(titled), &titled, o);
    size_t braille_checks = 0;
    for (const Check& c : r.checks)
        if (c.id == "tactile_braille") {
            ++braille_checks;
            EXPECT_EQ(c.note.rfind(std::to_string(legend->layout.dots.size()) + " dots ", 0), 0u) << c.note;
        }
    EXPECT_EQ(braille_checks, 1u);

    SceneParams plain = p;
    plain.words.title.clear();
    const Scene untitled = buildScene(hill(), plain);
    EXPECT_TRUE(featureBraille(untitled).empty());
    for (const Check& c : checkTactile(meshScene(untitled), &untitled, o).checks) EXPECT_NE(c.id, "tactile_braille");
}

}  // namespace
}  // namespace tsf
