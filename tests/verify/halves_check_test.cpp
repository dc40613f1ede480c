// The halves checked as a pair (verify/halves_check.h) and the overhang
// check (verify/overhang.h): a good pair passes; a symmetric pin layout, a
// half that is not the model's, or a piece that overhangs is caught.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/halves.h"
#include "gen/mesh/halves_mesh.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "verify/halves_check.h"
#include "verify/overhang.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

Scene hillWithHalves() {
    const HexField f = test::fieldFromFunction(12, 10, [](int c, int r) { return 1.0 + std::sin(c * 0.5) + std::cos(r * 0.6); });
    SceneParams p = test::smallParams(Bottom::Mirrored);
    p.pitch_mm = 6.0;
    p.halves = true;
    return buildScene(f, p);
}

CheckStatus statusOf(const HalvesCheckResult& r, const std::string& id) {
    for (const Check& c : r.checks)
        if (c.id == id) return c.status;
    ADD_FAILURE() << "no check " << id;
    return CheckStatus::Skipped;
}

TEST(HalvesCheck, TheHalvesJoinedAreTheWholeModelLessTheHoles) {
    const Scene s = hillWithHalves();
    const HalvesCheckResult r = checkHalves(s, meshScene(s), meshHalf(s, HalfKind::Upper), meshHalf(s, HalfKind::Lower));
    EXPECT_TRUE(r.passed());
    EXPECT_EQ(statusOf(r, "halves_one_way"), CheckStatus::Pass);
    EXPECT_EQ(statusOf(r, "halves_volume"), CheckStatus::Pass);
    EXPECT_EQ(statusOf(r, "halves_surface"), CheckStatus::Pass);
    EXPECT_GT(r.figures.holes_volume_mm3, 0);
    EXPECT_GT(r.figures.samples, 1000u);
}

TEST(HalvesCheck, EachHalfReadsBackAgainstItsScene) {
    const Scene s = hillWithHalves();
    VerifyOptions vo;
    const VerifyReport up = verifyModel(meshHalf(s, HalfKind::Upper), nullptr, vo);
    EXPECT_TRUE(up.passed());
    const Scene upper = halfScene(s, HalfKind::Upper), lower = halfScene(s, HalfKind::Lower);
    const VerifyReport ru = verifyModel(meshHalf(s, HalfKind::Upper), &upper, vo);
    EXPECT_TRUE(ru.passed()) << formatReport(ru);
    const VerifyReport rl = verifyModel(turnLowerHalf(meshHalf(s, HalfKind::Lower), s), &lower, vo);
    EXPECT_TRUE(rl.passed()) << formatReport(rl);
    ASSERT_NE(rl.find("overhang"), nullptr);
    EXPECT_EQ(rl.find("overhang")->status, CheckStatus::Pass);
    // Read against the other half's Scene the heights are wrong: the read-back sees which half it is.
    const VerifyReport wrong = verifyModel(meshHalf(s, HalfKind::Upper), &lower, vo);
    EXPECT_FALSE(wrong.passed());
}

TEST(HalvesCheck, PlantedSymmetricLayoutIsCaught) {
    Scene s = hillWithHalves();
    // Three holes in an isosceles triangle: reflected about its axis, the halves would still go together.
    SceneHalves& h = *s.halves;
    const int32_t c0 = 3, r0 = 3;
    const int32_t cells[3][2] = {{c0, r0}, {c0 + 6, r0}, {c0 + 3, r0 + 4}};
    h.hole_cells.clear();
    h.hole_centres.clear();
    for (const auto& cr : cells) {
        h.hole_cells.push_back(s.keptAt(cr[0], cr[1]));
        h.hole_centres.push_back(hexCentre(s.grid, cr[0], cr[1]));
    }
    const HalvesCheckResult r = checkHalves(s, meshScene(s), meshHalf(s, HalfKind::Upper), meshHalf(s, HalfKind::Lower));
    EXPECT_EQ(statusOf(r, "halves_one_way"), CheckStatus::Fail);
    EXPECT_EQ(statusOf(r, "halves_volume"), CheckStatus::Pass);
    EXPECT_FALSE(r.passed());
}

TEST(HalvesCheck, PlantedWrongHalfIsCaught) {
    const Scene s = hillWithHalves();
    Mesh upper = meshHalf(s, HalfKind::Upper);
    // Raise the highest vertex by 0.1 mm: a pillar top that is not the model's.
    size_t top = 0;
    for (size_t v = 0; v < upper.positions.size(); ++v)
        if (upper.positions[v].z > upper.positions[top].z) top = v;
    upper.positions[top].z += 0.1;
    const HalvesCheckResult r = checkHalves(s, meshScene(s), upper, meshHalf(s, HalfKind::Lower));
    EXPECT_EQ(statusOf(r, "halves_surface"), CheckStatus::Fail);
    EXPECT_EQ(statusOf(r, "halves_volume"), CheckStatus::Fail);
}

TEST(Overhang, APieceTurnedTheWrongWayOverhangs) {
    const Scene s = hillWithHalves();
    Mesh upper = meshHalf(s, HalfKind::Upper);
    EXPECT_EQ(measureOverhang(upper).area_mm2, 0.0);
    // Upside down (a half turn about x): the cut face is now on top, the pillar tops hang.
    for (Vec3& p : upper.positions) p = {p.x, -p.y, -p.z};
    const OverhangFigures f = measureOverhang(upper);
    EXPECT_GT(f.area_mm2, 0.0);
    EXPECT_GT(f.max_height_mm, 0.0);
    VerifyOptions vo;
    const VerifyReport r = verifyModel(upper, nullptr, vo);
    ASSERT_NE(r.find("overhang"), nullptr);
    EXPECT_EQ(r.find("overhang")->status, CheckStatus::Warn);
}

TEST(Overhang, OnACubeOnlyTheBedFacesDownAndALiftedCeilingOverhangs) {
    // A unit cube: only its bottom faces down, and it lies on the bed.
    Mesh cube;
    cube.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};
    cube.triangles = {{0, 2, 1}, {0, 3, 2}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                      {1, 2, 6}, {1, 6, 5}, {2, 3, 7}, {2, 7, 6}, {3, 0, 4}, {3, 4, 7}};
    EXPECT_EQ(measureOverhang(cube).triangles, 0u);
    // Lifted on one edge by 1 mm everywhere but the bed: a ceiling at z = 1 above a bed at z = 0.
    Mesh lifted = cube;
    for (Vec3& p : lifted.positions) p.z += 1;
    lifted.positions.push_back({0, 0, 0});  // an unused point on the bed moves the bed down
    EXPECT_EQ(measureOverhang(lifted).triangles, 2u);
    EXPECT_NEAR(measureOverhang(lifted).area_mm2, 1.0, 1e-12);
    EXPECT_NEAR(measureOverhang(lifted).max_height_mm, 1.0, 1e-12);
}

}  // namespace
}  // namespace tsf
