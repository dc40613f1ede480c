// meshSceneParts: the model as parts (pillars, marks, legend), each a closed,
// outward 2-manifold body of its own, touching and never overlapping, whose
// volumes add up to the one-solid model's.
#include <gtest/gtest.h>

#include "gen/mesh/direct_mesher.h"
#include "gen/mesh/scene_parts.h"
#include "tests/support/fields.h"
#include "tests/support/mesh_invariants.h"
#include "verify/verify_parts.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/tab/orientation_tab.h"
#include "gen/model/features/legend/legend.h"

namespace tsf {
namespace {

// A wide flat region (value 5) the triangle fits on, a varied strip north of
// it, and a title and units for the legend; 4 mm cells, both marks on.
HexField partsField() {
    return test::fieldFromFunction(16, 12, [](int c, int r) { return r >= 4 ? 5.0 : double((c + r) % 4); });
}

Scene partsScene(bool legend, MarkPlace place = MarkPlace::Data) {
    const HexField f = partsField();
    SceneParams p = test::smallParams();
    p.pitch_mm = 4.0;
    p.marks = MarkParams{};
    p.marks.place = place;
    if (legend) {
        p.words.title = "Test";
        p.words.units = "m";
    }
    return buildScene(f, p);
}

size_t partIndex(const std::vector<MeshPart>& parts, const std::string& name) {
    for (size_t k = 0; k < parts.size(); ++k)
        if (parts[k].name == name) return k;
    return parts.size();
}

TEST(SceneParts, PillarsMarksAndLegendAreClosedBodiesThatAddUpToTheModel) {
    const Scene s = partsScene(/*legend=*/true);
    ASSERT_TRUE(s.marks.triangle.has_value());
    ASSERT_TRUE(s.marks.notch.has_value());
    ASSERT_TRUE(sceneLegend(s) != nullptr);
    const std::vector<MeshPart> parts = meshSceneParts(s);
    ASSERT_EQ(parts.size(), 3u);
    EXPECT_EQ(parts[0].name, "pillars");
    EXPECT_EQ(parts[1].name, "marks");
    EXPECT_EQ(parts[2].name, "legend");
    double sum = 0;
    for (const MeshPart& p : parts) {
        const test::Invariants inv = test::checkInvariants(p.mesh);
        EXPECT_TRUE(inv.closedManifold()) << p.name << ": " << inv.describe();
        EXPECT_GT(inv.volume, 0) << p.name;
        sum += inv.volume;
    }
    EXPECT_EQ(test::checkInvariants(parts[0].mesh).components, 1u);
    EXPECT_EQ(test::checkInvariants(parts[1].mesh).components, 1u);
    EXPECT_EQ(test::checkInvariants(parts[2].mesh).components, sceneLegend(s)->layout.dots.size());  // a dome per dot

    // The triangle: a right triangle of the Scene's legs, raised by its raise (mm^3).
    const OrientationTriangle& t = *s.marks.triangle;
    EXPECT_NEAR(test::checkInvariants(parts[1].mesh).volume, t.leg_x_mm * t.leg_y_mm / 2 * s.zMm(t.raise_units), 0.01);
    // It stands on the pillars: its lowest point is its region's top.
    EXPECT_DOUBLE_EQ(meshBounds(parts[1].mesh).min.z, s.zMm(s.top[size_t(t.anchor)]));

    const double whole = test::checkInvariants(meshScene(s)).volume;
    EXPECT_NEAR(sum, whole, 1e-6 * whole);

    VerifyOptions vo;
    vo.printability = false;
    const PartsVerifyReport r = verifyParts(parts, &s, vo);
    EXPECT_TRUE(r.passed()) << formatPartsReport(r);
    ASSERT_NE(r.assembly.find("parts_overlap"), nullptr);
    EXPECT_EQ(r.assembly.find("parts_overlap")->status, CheckStatus::Pass);
    EXPECT_EQ(r.assembly.find("values_read_back")->status, CheckStatus::Pass);
}

// The orientation tab (the default) is the marks part: a closed body touching
// the pillars' west walls, the parts adding up to the joined model.
TEST(SceneParts, TheOrientationTabIsTheMarksPart) {
    const Scene s = partsScene(/*legend=*/false, MarkPlace::Tab);
    ASSERT_TRUE(sceneTab(s) != nullptr);
    const std::vector<MeshPart> parts = meshSceneParts(s);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(parts[1].name, "marks");
    const test::Invariants inv = test::checkInvariants(parts[1].mesh);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    const OrientationTab& t = *sceneTab(s);
    // The plate (its outline's area times the floor) and the triangle on it (mm^3).
    const double triangle = (t.triangle[1].x_mm - t.triangle[0].x_mm) * (t.triangle[2].y_mm - t.triangle[0].y_mm) / 2 *
                            s.zMm(t.triangle_raise_units);
    EXPECT_NEAR(inv.volume, tabAreaMm2(t) * s.zMm(t.top_units) + triangle, 1e-6 * inv.volume);
    EXPECT_NEAR(test::checkInvariants(parts[0].mesh).volume + inv.volume, test::checkInvariants(meshScene(s)).volume, 1e-6 * inv.volume);
    VerifyOptions vo;
    vo.printability = false;
    const PartsVerifyReport r = verifyParts(parts, &s, vo);
    EXPECT_TRUE(r.passed()) << formatPartsReport(r);
}

TEST(SceneParts, WithoutALegendThereIsNoLegendPartAndMirroredModelsSplitToo) {
    const Scene s = partsScene(/*legend=*/false);
    const std::vector<MeshPart> parts = meshSceneParts(s);
    ASSERT_EQ(parts.size(), 2u);
    EXPECT_EQ(partIndex(parts, "legend"), parts.size());

    const HexField f = partsField();
    SceneParams p = test::smallParams(Bottom::Mirrored);
    p.pitch_mm = 4.0;
    p.marks = MarkParams{};  // on the tab, the triangle on both its faces
    const Scene m = buildScene(f, p);
    ASSERT_TRUE(sceneTab(m) != nullptr);
    EXPECT_TRUE(sceneTab(m)->under_triangle);
    const std::vector<MeshPart> mparts = meshSceneParts(m);
    ASSERT_EQ(mparts.size(), 2u);
    VerifyOptions vo;
    vo.printability = false;
    const PartsVerifyReport r = verifyParts(mparts, &m, vo);
    EXPECT_TRUE(r.passed()) << formatPartsReport(r);
    EXPECT_NEAR(test::checkInvariants(mparts[0].mesh).volume + test::checkInvariants(mparts[1].mesh).volume,
                test::checkInvariants(meshScene(m)).volume, 1e-3);
}

}  // namespace
}  // namespace tsf
