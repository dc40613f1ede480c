// Feel what you print: the relief `tsf feel` renders is the relief `tsf gen`
// prints - one value -> height rule, the same cells, the same footprint.
#include <algorithm>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "gen/model/build_scene.h"
#include "gen/model/features/scale.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/model/scene.h"
#include "gen/model/features/legend/legend.h"
#include "haptics/field_mapping.h"
#include "haptics/force_model.h"
#include "haptics/height_grid.h"
#include "haptics/printed_relief.h"
#include "haptics/scale_space.h"
#include "tests/support/fields.h"

using namespace tsf;
using namespace tsf::haptics;
using tsf::test::fieldFromFunction;
using tsf::test::kNaN;

namespace {

/// A field that exercises the rule: values below the baseline and above
/// value max (both clamp, so they tie when printed), equal values, no-data
/// cells, and a sqrt transfer.
HexField ruleField() {
    std::mt19937 rng(5);
    std::uniform_int_distribution<int> v(-20, 140);
    return fieldFromFunction(14, 11, [&](int c, int r) {
        if ((c * 7 + r * 3) % 23 == 0) return kNaN;
        return double(v(rng) / 10 * 10);  // steps of 10: many equal values
    });
}

SceneParams ruleParams() {
    SceneParams p = tsf::test::smallParams(Bottom::Flat, Cull::None);
    p.transfer = Transfer::Sqrt;
    p.baseline_mode = BaselineMode::Value;
    p.baseline_value = 10.0;
    p.value_max = 100.0;
    p.z_snap_mm = 0.2;  // a printer's layers: snapping makes more ties
    return p;
}

/// Felt height (0..1 of the relief) at the centre of every kept cell.
std::vector<double> feltAtCentres(const Scene& scene, Interpolation interpolation) {
    ReliefInfo info;
    const HeightGrid grid = printedRelief(scene, &info);
    EXPECT_TRUE(info.exact_at_centres);
    const DeviceLimits limits;
    const ScaleSpace space = buildScaleSpace(grid, 1, ScaleSpaceKind::kGaussian, info.samples_per_pitch);
    const FieldMapping mapping = mapFieldToWorkspace(grid.cols, grid.rows, limits.workspace);
    ForceParams params;
    params.sampling.interpolation = interpolation;
    const ForceModel model = makeForceModel(space, mapping, params, limits, 1000.0);
    std::vector<double> felt;
    for (size_t k = 0; k < scene.keptCount(); ++k) {
        const GridPoint c = reliefCellCentre(scene, scene.col[k], scene.row[k], info);
        const haptics::Vec3 p = gridToDevice(mapping, c.gi, c.gj, 0.0);
        felt.push_back((surfaceAt(model, p, 0.0).height_y_m - mapping.floor_y_m) / mapping.relief_m);
    }
    return felt;
}

int sign(double d, double tie) { return d > tie ? 1 : d < -tie ? -1 : 0; }

/// Pairs (a, b) whose order differs between two height lists (ties count).
int orderMismatches(const std::vector<double>& a, const std::vector<double>& b, double tie_a, double tie_b) {
    int bad = 0;
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = i + 1; j < a.size(); ++j) bad += sign(a[i] - a[j], tie_a) != sign(b[i] - b[j], tie_b);
    return bad;
}

}  // namespace

TEST(PrintedRelief, FeltHeightOrderOfCellsEqualsThePrintedOrder) {
    const Scene scene = buildScene(ruleField(), ruleParams());
    // Printed: the pillars' tops as the mesher builds them (flat bottom:
    // height above the floor = top - floor, in snap units).
    std::vector<double> printed;
    for (size_t k = 0; k < scene.keptCount(); ++k) printed.push_back(double(scene.top[k] - scene.floor_units));
    for (Interpolation interp : {Interpolation::kBicubic, Interpolation::kBilinear}) {
        const std::vector<double> felt = feltAtCentres(scene, interp);
        EXPECT_EQ(orderMismatches(printed, felt, 0.5, 1e-6), 0);
        // Not just the order: the same heights, scaled to the device.
        for (size_t k = 0; k < felt.size(); ++k)
            EXPECT_NEAR(felt[k], printed[k] * scene.z_snap_mm / scene.mapping.max_height_mm, 1e-6) << "cell " << k;
    }
}

TEST(PrintedRelief, ARawMinMaxNormalisationWouldFeelADifferentOrder) {
    // The planted defect: what feel did before (min..max of the values, no
    // baseline, no value max, no transfer, no snap) breaks the order, so the
    // test above can fail.
    const HexField field = ruleField();
    const Scene scene = buildScene(field, ruleParams());
    double lo = INFINITY, hi = -INFINITY;
    for (double v : field.values)
        if (std::isfinite(v)) lo = std::min(lo, v), hi = std::max(hi, v);
    std::vector<double> printed, raw;
    for (size_t k = 0; k < scene.keptCount(); ++k) {
        printed.push_back(double(scene.top[k] - scene.floor_units));
        const double v = scene.value[k];
        raw.push_back(std::isfinite(v) ? (v - lo) / (hi - lo) : 0.0);
    }
    EXPECT_GT(orderMismatches(printed, raw, 0.5, 1e-9), 0);
}

TEST(PrintedRelief, CulledCellsAreTheFloorNoDataCellsArePitsAndTheFootprintKeepsTheModelsShape) {
    // A diagonal band of data in a field of zeros: the hull culls the corners.
    const HexField field = fieldFromFunction(12, 9, [](int c, int r) {
        if (c == 6 && r == 4) return kNaN;
        return std::abs(c - r - 2) <= 1 ? 50.0 : 0.0;
    });
    const Scene scene = buildScene(field, tsf::test::smallParams());
    ASSERT_LT(scene.keptCount(), size_t(12 * 9));
    ReliefInfo info;
    const HeightGrid grid = printedRelief(scene, &info);
    EXPECT_EQ(info.samples_per_pitch, kReliefSamplesPerPitch);
    EXPECT_NEAR(info.sample_mm, scene.pitch_mm / kReliefSamplesPerPitch, 1e-12);
    // The grid covers the printed model's bounding box.
    EXPECT_NEAR(grid.cols * info.sample_mm, gridWidth(scene.grid, scene.pitch_mm), info.sample_mm);
    EXPECT_NEAR(grid.rows * info.sample_mm, gridDepth(scene.grid, scene.pitch_mm, scene.y_scale), info.sample_mm);
    // Every sample is the height of the kept cell it lies in, or the floor;
    // a cell without data is the pit the print has (1 mm of the 10 mm relief).
    for (int32_t j = 0; j < grid.rows; ++j)
        for (int32_t i = 0; i < grid.cols; ++i) {
            int32_t c = 0, r = 0;
            float expect = 0.0f;
            if (hexCellAt(scene.grid, (i + 0.5) / info.samples_per_pitch, (j + 0.5) / info.samples_per_pitch, c, r)) {
                const int32_t k = scene.keptAt(c, r);
                if (k >= 0 && std::isfinite(scene.value[size_t(k)])) expect = float(scene.value[size_t(k)] / 50.0);
                if (k >= 0 && !std::isfinite(scene.value[size_t(k)])) expect = float(-1.0 / 10.0);
            }
            ASSERT_EQ(grid.at(i, j), expect) << i << " " << j;
        }
}

TEST(PrintedRelief, VeryWideFieldsAreSampledMoreCoarselyAndSaySo) {
    const HexField field = fieldFromFunction(400, 3, [](int c, int) { return double(c % 7); });
    SceneParams p = tsf::test::smallParams(Bottom::Flat, Cull::None);
    p.pitch_mm = 1.0;
    const Scene scene = buildScene(field, p);
    ReliefInfo info;
    const HeightGrid grid = printedRelief(scene, &info);
    EXPECT_LE(grid.cols, kMaxReliefSamples);
    EXPECT_LT(info.samples_per_pitch, kReliefSamplesPerPitch);
    EXPECT_FALSE(info.exact_at_centres);
}

TEST(PrintedRelief, SweepLinesRunAlongEveryRowInsideItsCells) {
    const HexField field = fieldFromFunction(12, 9, [](int c, int r) { return double(c + r); });
    const Scene scene = buildScene(field, tsf::test::smallParams(Bottom::Flat, Cull::None));
    ReliefInfo info;
    const HeightGrid grid = printedRelief(scene, &info);
    const DeviceLimits limits;
    const FieldMapping m = mapFieldToWorkspace(grid.cols, grid.rows, limits.workspace);
    const std::vector<SweepLine> lines = reliefRowLines(scene, info, m);
    ASSERT_EQ(lines.size(), 9u);
    const double pitch_m = m.cell_m * info.samples_per_pitch;
    for (size_t r = 0; r < lines.size(); ++r) {
        const SweepLine& l = lines[r];
        // Its ends lie over the row's first and last cells.
        for (double x : {l.x_west_m, l.x_east_m}) {
            const GridPoint g = deviceToGrid(m, haptics::Vec3(x, 0.0, l.z_m));
            int32_t c = -1, row = -1;
            ASSERT_TRUE(hexCellAt(scene.grid, (g.gi + 0.5) / info.samples_per_pitch, (g.gj + 0.5) / info.samples_per_pitch,
                                  c, row));
            EXPECT_EQ(row, int32_t(r));
            EXPECT_TRUE(c == 0 || c == 11);
        }
        EXPECT_NEAR(l.x_east_m - l.x_west_m, (11 + 0.9) * pitch_m, 1e-9);
        if (r > 0) EXPECT_NEAR(l.z_m - lines[r - 1].z_m, pitch_m * std::sqrt(3.0) / 2.0, 1e-9);  // north to south
    }
}

namespace {

// The relief of a tilted top leans as printed: on a ramp rising east, inside
// one cell the samples east of its centre stand higher than those west of it,
// by the slope the Scene drew; a structural cell's dimple is lowest at its centre.
TEST(PrintedRelief, TiltedTopsAndDimplesAreFeltAsPrinted) {
    SceneParams p = tsf::test::smallParams(Bottom::Flat, Cull::None);
    p.tilt = TiltSource::Gradient;
    const Scene s = buildScene(fieldFromFunction(9, 7, [](int c, int) { return 1.0 + c; }), p);
    ReliefInfo info;
    const HeightGrid g = printedRelief(s, &info);
    const int32_t k = s.keptAt(4, 3);
    ASSERT_GE(k, 0);
    const double slope = s.shapes.slope_x[size_t(k)];
    ASSERT_GT(slope, 0.1);
    const GridPoint c = reliefCellCentre(s, 4, 3, info);
    const int32_t i = int32_t(std::lround(c.gi)), j = int32_t(std::lround(c.gj));
    const double rise = (g.at(i + 2, j) - g.at(i - 2, j)) * s.mapping.max_height_mm;  // mm over 4 samples
    EXPECT_NEAR(rise, slope * 4 * info.sample_mm, 1e-3);

    // Structural cells: empty cells among islands, not one value per cell.
    const HexField f = tsf::test::asBinnedPoints(
        fieldFromFunction(9, 7, [](int col, int row) { return (col < 2 || col > 6) && row < 3 ? 5.0 : 0.0; }));
    SceneParams q = tsf::test::smallParams(Bottom::Flat, Cull::Hull);
    q.structural_texture = true;
    const Scene d = buildScene(f, q);
    const HeightGrid h = printedRelief(d, &info);
    const int32_t m = d.keptAt(4, 1);
    ASSERT_GE(m, 0);
    ASSERT_TRUE(isStructural(d.shapes, size_t(m)));
    const GridPoint e = reliefCellCentre(d, 4, 1, info);
    const int32_t ei = int32_t(std::lround(e.gi)), ej = int32_t(std::lround(e.gj));
    EXPECT_LT(h.at(ei, ej), h.at(ei + 2, ej));
    EXPECT_LT(h.at(ei, ej), 0.0);  // below the floor at the centre
}

// The orientation tab west of the grid's box is felt too: the relief grows
// west by whole samples, every cell keeps its sample, and the triangle on
// the tab stands its raise above the floor.
TEST(PrintedRelief, TheOrientationTabIsFeltWestOfThePillars) {
    SceneParams p = tsf::test::smallParams(Bottom::Flat, Cull::None);
    p.pitch_mm = 4.0;
    p.marks = MarkParams{};
    const Scene s = buildScene(fieldFromFunction(10, 8, [](int c, int r) { return 2.0 + (c + r) % 3; }), p);
    ASSERT_TRUE(sceneTab(s) != nullptr);
    ReliefInfo info;
    const HeightGrid h = printedRelief(s, &info);
    EXPECT_GT(info.origin_i, 0);
    EXPECT_NEAR(info.origin_i * info.sample_mm, -sceneTab(s)->x_west_mm, info.sample_mm);
    // Every cell is still felt at its centre.
    for (size_t k = 0; k < s.keptCount(); ++k) {
        const GridPoint c = reliefCellCentre(s, s.col[k], s.row[k], info);
        EXPECT_FLOAT_EQ(h.at(int32_t(std::lround(c.gi)), int32_t(std::lround(c.gj))),
                        float(s.zMm(s.top[k] - s.floor_units) / s.mapping.max_height_mm));
    }
    const OrientationTab& t = *sceneTab(s);
    const double cx = (t.triangle[0].x_mm + t.triangle[1].x_mm + t.triangle[2].x_mm) / 3;
    const double cy = (t.triangle[0].y_mm + t.triangle[1].y_mm + t.triangle[2].y_mm) / 3;
    const auto i = int32_t(std::floor(cx / info.sample_mm)) + info.origin_i, j = int32_t(std::floor(cy / info.sample_mm)) + info.origin_j;
    EXPECT_NEAR(h.at(i, j), s.zMm(t.triangle_raise_units) / s.mapping.max_height_mm, 1e-6);
    // Beside the triangle, on the tab: the floor.
    EXPECT_NEAR(h.at(info.origin_i - 2, j), 0.0, 1e-6);
}

TEST(PrintedRelief, TheMarksTheLegendAndTheScaleAreFeltAsPrinted) {
    // A plateau wide enough for the triangle, with a braille legend and a scale.
    SceneParams p = tsf::test::smallParams(Bottom::Flat, Cull::None);
    p.pitch_mm = 4.0;
    p.words.title = "Hi";
    p.requests.set(ScaleRequest{});
    p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;  // the marks on the pillars, where the relief is felt
    const Scene s = buildScene(fieldFromFunction(16, 26, [](int c, int r) { return c < 8 && r > 15 ? 10.0 : 2.0 + c % 3; }), p);
    ASSERT_TRUE(s.marks.triangle);
    ASSERT_TRUE(sceneLegend(s));
    ASSERT_TRUE(sceneScale(s));
    ReliefInfo info;
    const HeightGrid g = printedRelief(s, &info);
    const double side = info.sample_mm, max_mm = s.mapping.max_height_mm;
    auto feltAt = [&](double x_mm, double y_mm) {
        const auto i = int32_t(std::floor(x_mm / side)), j = int32_t(std::floor(y_mm / side));
        EXPECT_TRUE(i >= 0 && i < g.cols && j >= 0 && j < g.rows) << x_mm << ", " << y_mm;
        return double(g.at(std::clamp(i, 0, g.cols - 1), std::clamp(j, 0, g.rows - 1))) * max_mm;  // mm above the floor
    };
    // The triangle stands on its region by its own height, felt where it is.
    const OrientationTriangle& t = *s.marks.triangle;
    const tsf::Vec3 centroid = s.point(PlanarPoint{(t.corner.i + t.east.i + t.north.i) / 3, (t.corner.j + t.east.j + t.north.j) / 3}, 0);
    const double region = s.zMm(s.top[size_t(t.anchor)] - s.floor_units);
    EXPECT_NEAR(feltAt(centroid.x, centroid.y), region + s.zMm(t.raise_units), 1e-4);
    // Every braille dot stands above the plate (the floor): felt near its apex.
    for (const LegendDot& d : sceneLegend(s)->layout.dots)
        EXPECT_GT(feltAt(d.x_mm + sceneLegend(s)->x0_mm, d.y_mm + sceneLegend(s)->y0_mm), 0.5 * sceneLegend(s)->layout.standard.dot_height_mm);
    // Each tread of the scale at its height above the floor.
    const SceneScale& sc = *sceneScale(s);
    for (const ScaleStep& st : sc.steps)
        EXPECT_NEAR(feltAt(0.5 * (sc.xs_mm + sc.x1_mm), 0.5 * (st.y_south_mm + st.y_north_mm)),
                    s.zMm(st.top_units - s.floor_units), 1e-4);
}

}  // namespace
