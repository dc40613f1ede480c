// Values read back: each kept cell's surfaces are measured by rays and turned
// back into data values; the tolerance is half a snap step plus the float32
// rounding of an STL coordinate.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/verify/verify_test_support.h"
#include "verify/column_grid.h"
#include "verify/readback.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {

ReadbackResult readBackModel(const Mesh& mesh, const Scene& scene, ReadbackOptions o = {}) {
    const ColumnGrid caster(mesh);
    return readBack(mesh, scene, caster, o);
}

const Check& findCheck(const ReadbackResult& r, const std::string& id) {
    for (const Check& c : r.checks)
        if (c.id == id) return c;
    ADD_FAILURE() << "no check " << id;
    return r.checks.front();
}

TEST(Readback, ExactMeshReadsBackEveryCellExactly) {
    for (Bottom b : {Bottom::Flat, Bottom::Mirrored}) {
        const vtest::Model m = vtest::smallModel(b);
        const ReadbackResult r = readBackModel(m.mesh, m.scene);
        EXPECT_EQ(r.figures.cells_checked, m.scene.keptCount());
        EXPECT_EQ(r.figures.surfaces_checked, 2 * m.scene.keptCount());
        EXPECT_EQ(r.figures.missed, 0u);
        EXPECT_EQ(r.figures.over_tolerance, 0u);
        EXPECT_LT(r.figures.max_error_mm, 1e-12);  // the mesher writes the Scene's z exactly
        EXPECT_EQ(findCheck(r, "values_read_back").status, CheckStatus::Pass);
        EXPECT_EQ(findCheck(r, "outside_cells_empty").status, CheckStatus::Pass);
        EXPECT_EQ(r.figures.outside_cells_checked, size_t(m.scene.grid.cellCount()) - m.scene.keptCount());
    }
}

TEST(Readback, ToleranceIsHalfAStepPlusFloat32Rounding) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat, 0.2);
    const ReadbackResult r = readBackModel(m.mesh, m.scene);
    const int64_t top = *std::max_element(m.scene.top.begin(), m.scene.top.end());
    EXPECT_DOUBLE_EQ(r.figures.height_step_tolerance_mm, 0.1);
    EXPECT_DOUBLE_EQ(r.figures.float32_rounding_mm, m.scene.zMm(top) * std::ldexp(1.0, -24));
    EXPECT_DOUBLE_EQ(r.figures.tolerance_mm, 0.1 + m.scene.zMm(top) * std::ldexp(1.0, -24));
}

TEST(Readback, Float32CoordinatesStillPass) {
    // What an STL file does to the mesh: every coordinate rounded to float.
    const vtest::Model m = vtest::smallModel(Bottom::Mirrored);
    Mesh stl = m.mesh;
    for (Vec3& p : stl.positions) p = {double(float(p.x)), double(float(p.y)), double(float(p.z))};
    const ReadbackResult r = readBackModel(stl, m.scene);
    EXPECT_EQ(r.figures.over_tolerance, 0u);
    EXPECT_GT(r.figures.max_error_mm, 0.0);  // the rounding is visible...
    EXPECT_LE(r.figures.max_error_mm, r.figures.float32_rounding_mm);  // ...and bounded as derived
}

TEST(Readback, OneSnapStepOffFailsWithALayerSnap) {
    // With the snap at a 0.2 mm layer, a pillar one layer too high is a
    // different height: it must fail, not hide inside a whole-step tolerance.
    const vtest::Model m = vtest::smallModel(Bottom::Flat, 0.2);
    Scene wrong = m.scene;
    const size_t k = vtest::keptIndex(m.scene, 4, 1);
    wrong.top[k] += 1;
    const ReadbackResult r = readBackModel(meshScene(wrong), m.scene);
    EXPECT_EQ(r.figures.over_tolerance, 1u);
    EXPECT_NEAR(r.figures.max_error_mm, 0.2, 1e-9);
    ASSERT_FALSE(r.figures.worst.empty());
    EXPECT_EQ(r.figures.worst[0].col, 4);
    EXPECT_EQ(r.figures.worst[0].row, 1);
    EXPECT_EQ(r.figures.worst[0].surface, "top");
    EXPECT_EQ(findCheck(r, "values_read_back").status, CheckStatus::Fail);
}

TEST(Readback, ValuesReadBackWithinTheHeightQuantisation) {
    // Independent bound: a height within half a snap step of the exact
    // height maps to a value within that step times the transfer's slope.
    for (Transfer tr : {Transfer::Linear, Transfer::Sqrt, Transfer::Log}) {
        SceneParams p = vtest::smallFieldParams(Bottom::Mirrored, 0.01);
        p.transfer = tr;
        const Scene s = buildScene(vtest::smallField(), p);
        const ReadbackResult r = readBackModel(meshScene(s), s);
        const ValueMapping& map = s.mapping;
        // The largest allowed quantisation error over all cells (slope is
        // largest at the low end for sqrt, at the high end for log).
        double worst_bound = 0;
        const double half = s.z_snap_mm / 2;
        for (double h = 0; h <= map.max_height_mm + half; h += half / 4)
            worst_bound = std::max({worst_bound, std::fabs(map.valueAt(h + half) - map.valueAt(h)),
                                    std::fabs(map.valueAt(h) - map.valueAt(h - half))});
        EXPECT_LE(r.figures.max_value_error, worst_bound * 1.000001) << toString(tr);
        EXPECT_GT(r.figures.max_value_error, 0.0) << toString(tr);  // quantisation is real and reported
        EXPECT_EQ(r.figures.over_tolerance, 0u);
    }
}

TEST(Readback, CellWithoutDataIsComparedByHeightOnly) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    ReadbackOptions o;
    o.max_offenders = 1000;  // keep every surface in the list
    const ReadbackResult r = readBackModel(m.mesh, m.scene, o);
    bool seen = false;
    for (const CellReadback& c : r.figures.worst) {
        if (c.col != 3 || c.row != 2 || c.surface != "top") continue;
        seen = true;
        EXPECT_TRUE(std::isnan(c.value));
        EXPECT_TRUE(std::isnan(c.value_read));
        EXPECT_TRUE(std::isnan(c.value_error));
        EXPECT_DOUBLE_EQ(c.measured_mm, m.scene.zMm(m.scene.floor_units - m.scene.nodata_pit_units));  // a pit
    }
    EXPECT_TRUE(seen);
}

TEST(Readback, MaterialOutsideTheKeptCellsIsFound) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    ASSERT_LT(m.scene.keptAt(0, 0), 0) << "the fixture's empty corner should be culled";
    const Vec3 c = m.scene.point(hexCentre(m.scene.grid, 0, 0), 0);
    const Mesh extra = vtest::append(m.mesh, vtest::box({c.x - 1, c.y - 1, 0}, {c.x + 1, c.y + 1, 3}));
    const ReadbackResult r = readBackModel(extra, m.scene);
    const Check& out = findCheck(r, "outside_cells_empty");
    EXPECT_EQ(out.status, CheckStatus::Fail);
    EXPECT_EQ(out.count, 1);
    ASSERT_EQ(out.worst.size(), 1u);
    EXPECT_NEAR(out.worst[0].at_mm.x, c.x, 1e-9);
    EXPECT_NEAR(out.worst[0].at_mm.z, 3.0, 1e-12);
    EXPECT_NE(out.worst[0].detail.find("col 0, row 0"), std::string::npos);
}

TEST(Readback, MeshInTheWrongPlaceMissesEveryRay) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh moved = m.mesh;
    for (Vec3& p : moved.positions) p.x += 1000;
    const ReadbackResult r = readBackModel(moved, m.scene);
    EXPECT_EQ(r.figures.missed, 2 * m.scene.keptCount());
    EXPECT_TRUE(std::isnan(r.figures.worst.at(0).measured_mm));
    EXPECT_EQ(findCheck(r, "values_read_back").status, CheckStatus::Fail);
}

TEST(Readback, EmptySceneHasNothingToCheck) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Scene empty;
    const ReadbackResult r = readBackModel(m.mesh, empty);
    EXPECT_EQ(r.figures.cells_checked, 0u);
    EXPECT_EQ(findCheck(r, "values_read_back").status, CheckStatus::Pass);
}

}  // namespace
}  // namespace tsf
