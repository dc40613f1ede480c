#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "gen/util/error.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"

namespace tsf {
namespace {
using test::fieldFromRows;
using test::kNaN;
using test::smallParams;

TEST(ValueMapping, TransfersAreMonotoneAndInvertible) {
    for (Transfer t : {Transfer::Linear, Transfer::Sqrt, Transfer::Log}) {
        ValueMapping m{t, -5.0, 15.0, 20.0};
        EXPECT_DOUBLE_EQ(m.heightMm(-5.0), 0.0) << toString(t);
        EXPECT_NEAR(m.heightMm(15.0), 20.0, 1e-12) << toString(t);
        double prev = -1;
        for (double v = -5; v <= 15; v += 0.5) {
            const double h = m.heightMm(v);
            EXPECT_GT(h, prev) << toString(t) << " v=" << v;
            prev = h;
            EXPECT_NEAR(m.valueAt(h), v, 1e-9) << toString(t);
        }
        EXPECT_DOUBLE_EQ(m.heightMm(-100), 0.0);
        EXPECT_DOUBLE_EQ(m.heightMm(100), 20.0);
        EXPECT_DOUBLE_EQ(m.heightMm(NAN), 0.0);
    }
    // Hand-computed: linear 25% -> 5 mm; sqrt 25% -> 10 mm; log 1/99 -> log10(2)/2 * 20.
    EXPECT_DOUBLE_EQ((ValueMapping{Transfer::Linear, 0, 4, 20}.heightMm(1)), 5.0);
    EXPECT_DOUBLE_EQ((ValueMapping{Transfer::Sqrt, 0, 4, 20}.heightMm(1)), 10.0);
    EXPECT_NEAR((ValueMapping{Transfer::Log, 0, 99, 20}.heightMm(1)), 20 * std::log10(2.0) / 2, 1e-12);
}

TEST(Scene, FlatHeightsFollowTheValues) {
    const Scene s = buildScene(fieldFromRows({{0, 1, 2}, {3, 4, 5}}), smallParams(Bottom::Flat, Cull::None));
    ASSERT_EQ(s.keptCount(), 6u);
    EXPECT_EQ(s.floor_units, 2000);  // 2 mm base at 1 um steps
    // Value 5 is the maximum: 10 mm above the 2 mm base; value 1 -> 2 mm.
    EXPECT_EQ(s.top[s.keptAt(2, 1)], 12000);
    EXPECT_EQ(s.top[s.keptAt(1, 0)], 4000);
    EXPECT_EQ(s.top[s.keptAt(0, 0)], 2000);
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.bottom[k], 0);
}

TEST(Scene, MirroredPillarsHaveEqualThicknessAndNegatedBottoms) {
    const Scene s = buildScene(fieldFromRows({{0, 5, 0}, {1, 0, 2}}), smallParams(Bottom::Mirrored, Cull::None));
    // Largest neighbour step is 10 mm (0 next to 5); thickness = 10 + 2 mm base.
    EXPECT_EQ(s.mirror_thickness_units, 12000);
    for (size_t k = 0; k < s.keptCount(); ++k) {
        EXPECT_EQ(s.top[k] - s.bottom[k], 12000);
        EXPECT_EQ(s.bottom[k], std::llround(s.mapping.heightMm(s.value[k]) / 0.001));
    }
}

TEST(Scene, HullCullingDropsCellsOutsideTheHullOfNonEmptyCells) {
    // Non-empty cells in a small cluster; far corner cells must go.
    std::vector<std::vector<double>> rows(8, std::vector<double>(8, 0.0));
    rows[3][3] = 1; rows[3][5] = 2; rows[5][4] = 3; rows[4][4] = 1;
    const Scene s = buildScene(fieldFromRows(rows), smallParams());
    EXPECT_EQ(s.keptAt(0, 0), -1);
    EXPECT_EQ(s.keptAt(7, 7), -1);
    EXPECT_GE(s.keptAt(4, 4), 0);
    EXPECT_GE(s.keptAt(3, 3), 0);
    EXPECT_LT(s.keptCount(), 64u);
    EXPECT_EQ(s.cells_nonempty, 4);
}

TEST(Scene, DegenerateHullIsWidenedToOnePiece) {
    // Cells (0,0) and (2,1) are 5 lattice units apart in i and 3 in j: no
    // other centre lies on the segment between them and they are not
    // neighbours, so the thesis rule alone gives two islands.
    std::vector<std::vector<double>> rows(6, std::vector<double>(6, 0.0));
    rows[0][0] = 1;
    rows[1][2] = 1;
    const Scene s = buildScene(fieldFromRows(rows), smallParams());
    EXPECT_GT(s.keptCount(), 2u);
    EXPECT_FALSE(s.notes.empty());
}

TEST(Scene, NanCellsAreNoDataPitsBelowTheFloor) {
    const Scene s = buildScene(fieldFromRows({{1, kNaN, 1}, {1, 1, 1}}), smallParams(Bottom::Flat, Cull::None));
    const int32_t k = s.keptAt(1, 0);
    ASSERT_GE(k, 0);
    EXPECT_TRUE(std::isnan(s.value[k]));
    EXPECT_EQ(s.kind[k], CellKind::NoData);
    EXPECT_EQ(s.top[k], s.floor_units - s.nodata_pit_units);  // a pit: never read as the lowest value
    EXPECT_EQ(s.nodata_pit_units, 1000);                       // half the 2 mm base, at most 1 mm
    EXPECT_EQ(s.cells_nodata_kept, 1);
    EXPECT_EQ(s.cells_with_data, 5);
}

TEST(Scene, ConstantAndAllZeroFieldsAreDefined) {
    Scene s = buildScene(fieldFromRows({{7, 7}, {7, 7}}), smallParams());
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.top[k], 12000);  // full height: 7 > baseline 0
    s = buildScene(fieldFromRows({{0, 0}, {0, 0}}), smallParams());
    EXPECT_EQ(s.keptCount(), 4u);  // no hull: kept as a flat slab
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.top[k], 2000);
    EXPECT_FALSE(s.notes.empty());
    SceneParams min_base = smallParams();
    min_base.baseline_mode = BaselineMode::Min;
    s = buildScene(fieldFromRows({{-3, -3}}), min_base);
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.top[k], 2000);
}

TEST(Scene, NegativeValuesUseTheMinimumAsBaseline) {
    const Scene s = buildScene(fieldFromRows({{-10, 0, 10}}), smallParams(Bottom::Flat, Cull::None));
    EXPECT_DOUBLE_EQ(s.mapping.baseline, -10);
    EXPECT_EQ(s.top[s.keptAt(1, 0)], 7000);  // halfway: 5 mm above the 2 mm base
}

TEST(Scene, TinyDifferencesSnapToEqualHeights) {
    const Scene s = buildScene(fieldFromRows({{1.0, 1.0 + 1e-12, 1.0 - 1e-12}}), smallParams(Bottom::Flat, Cull::None));
    EXPECT_EQ(s.top[0], s.top[1]);
    EXPECT_EQ(s.top[1], s.top[2]);
}

TEST(Scene, ValuesSpanningMoreThanTheLargestDoubleGetExactHeights) {
    // 1e308 - -1e308 overflows to inf: heights are computed on the halves.
    const Scene s = buildScene(fieldFromRows({{1e308, -1e308, 0}}), smallParams(Bottom::Flat, Cull::None));
    EXPECT_EQ(s.top[s.keptAt(0, 0)], 12000);  // full 10 mm above the 2 mm base
    EXPECT_EQ(s.top[s.keptAt(1, 0)], 2000);   // the baseline, at the floor
    EXPECT_EQ(s.top[s.keptAt(2, 0)], 7000);   // halfway
    EXPECT_DOUBLE_EQ(s.mapping.valueAt(5.0), 0.0);
    EXPECT_DOUBLE_EQ(s.mapping.valueAt(10.0), 1e308);
    const double big = std::numeric_limits<double>::max();
    const Scene m = buildScene(fieldFromRows({{big, -big}}), smallParams(Bottom::Flat, Cull::None));
    EXPECT_EQ(m.top[0], 12000);
    EXPECT_EQ(m.top[1], 2000);
    EXPECT_DOUBLE_EQ(m.mapping.valueAt(10.0), big);
}

TEST(Scene, ContradictoryValueOptionsAreErrors) {
    SceneParams p = smallParams();
    p.value_max = 0.0;  // at the baseline (0: no value is negative)
    EXPECT_THROW(buildScene(fieldFromRows({{1, 2}}), p), InputError);
    p.baseline_mode = BaselineMode::Value;
    p.baseline_value = 5.0;
    p.value_max = 4.0;  // below it
    EXPECT_THROW(buildScene(fieldFromRows({{1, 9}}), p), InputError);
    p.value_max.reset();  // the largest value, 2, is below the baseline
    EXPECT_THROW(buildScene(fieldFromRows({{1, 2}}), p), InputError);
    p.baseline_mode = BaselineMode::Zero;
    EXPECT_THROW(buildScene(fieldFromRows({{-1, -2}}), p), InputError);
    p.baseline_mode = BaselineMode::Value;
    p.baseline_value = 2.0;  // a constant field at the baseline stays a defined flat slab
    EXPECT_NO_THROW(buildScene(fieldFromRows({{2, 2}}), p));
}

TEST(Scene, AMirroredFlatFieldWithoutDataCellsKeepsThemOneStepThick) {
    // The slab of a flat field is only the base thick; a pit from both faces
    // of half the base each used to leave a cell with bottom == top.
    const Scene s = buildScene(fieldFromRows({{kNaN, 0}, {0, 0}}), smallParams(Bottom::Mirrored, Cull::None));
    const int32_t pit = s.keptAt(0, 0);
    ASSERT_GE(pit, 0);
    EXPECT_EQ(s.kind[size_t(pit)], CellKind::NoData);
    EXPECT_EQ(s.top[size_t(pit)] - s.bottom[size_t(pit)], 2);  // 2000 - 2 * 999 units
    EXPECT_EQ(s.nodata_pit_units, 999);
}

TEST(Scene, FitsTheGridIntoTheRequestedBox) {
    SceneParams p = smallParams();
    p.pitch_mm = 0;
    p.fit_width_mm = 100;
    p.fit_depth_mm = 50;
    const Scene s = buildScene(test::fieldFromFunction(20, 20, [](int c, int r) { return c + r; }), p);
    EXPECT_LE(gridWidth(s.grid, s.pitch_mm), 100 + 1e-9);
    EXPECT_LE(gridDepth(s.grid, s.pitch_mm, s.y_scale), 50 + 1e-9);
    EXPECT_NEAR(gridDepth(s.grid, s.pitch_mm, s.y_scale), 50, 1e-9);  // depth is the binding side here
}

TEST(Scene, RejectsBadParametersAndEmptyFields) {
    SceneParams p = smallParams();
    p.base_mm = 0;
    EXPECT_THROW(buildScene(fieldFromRows({{1}}), p), InputError);
    p = smallParams();
    p.z_snap_mm = -1;
    EXPECT_THROW(buildScene(fieldFromRows({{1}}), p), InputError);
    p = smallParams();
    p.pitch_mm = NAN;
    EXPECT_THROW(buildScene(fieldFromRows({{1}}), p), InputError);
    EXPECT_THROW(buildScene(fieldFromRows({{kNaN, kNaN}}), smallParams()), InputError);
    EXPECT_THROW(buildScene(HexField{}, smallParams()), InputError);
    EXPECT_THROW(buildScene(fieldFromRows({{1, INFINITY}}), smallParams()), InputError);
}

}  // namespace
}  // namespace tsf
