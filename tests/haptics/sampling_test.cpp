// Height grid construction and height sampling: values read back, interpolation
// formulas checked against hand-computed numbers, border and degenerate cases.
#include <cmath>
#include <limits>
#include <random>

#include <gtest/gtest.h>

#include "gen/util/error.h"
#include "haptics/height_grid.h"
#include "haptics/height_sampling.h"

using namespace tsf::haptics;

namespace {

// 3 x 2 field, rows listed SOUTH first:
//   j=1 (north): 0.4 0.5 1.0
//   j=0 (south): 0.0 0.2 0.6
HeightGrid small() { return makeHeightGrid(3, 2, {0.0f, 0.2f, 0.6f, 0.4f, 0.5f, 1.0f}); }

constexpr double kTol = 1e-6;  // float storage, double arithmetic

}  // namespace

TEST(HeightGrid, RasterRowsFlipNanIsFloorAndValuesNormalise) {
    tsf::Raster r;
    r.cols = 2;
    r.rows = 2;
    r.source = "t.csv";
    const double nan = std::numeric_limits<double>::quiet_NaN();
    r.values = {10.0, 30.0,   // row 0 = north
                nan, 20.0};   // row 1 = south
    HeightGridInfo info;
    const HeightGrid g = heightGridFromRaster(r, &info);
    EXPECT_EQ(info.nodata_cells, 1);
    EXPECT_DOUBLE_EQ(info.min_value, 10.0);
    EXPECT_DOUBLE_EQ(info.max_value, 30.0);
    EXPECT_FLOAT_EQ(g.at(0, 1), 0.0f);  // north-west: 10 -> 0
    EXPECT_FLOAT_EQ(g.at(1, 1), 1.0f);  // north-east: 30 -> 1
    EXPECT_FLOAT_EQ(g.at(0, 0), 0.0f);  // south-west: no data -> floor
    EXPECT_FLOAT_EQ(g.at(1, 0), 0.5f);  // south-east: 20 -> 0.5
}

TEST(HeightGrid, FlatFieldIsAllZeroAndAllNanIsAnError) {
    tsf::Raster r;
    r.cols = 2;
    r.rows = 1;
    r.values = {5.0, 5.0};
    const HeightGrid g = heightGridFromRaster(r);
    EXPECT_FLOAT_EQ(g.at(0, 0), 0.0f);
    EXPECT_FLOAT_EQ(g.at(1, 0), 0.0f);
    r.values = {std::nan(""), std::nan("")};
    EXPECT_THROW(heightGridFromRaster(r), tsf::InputError);
    r.cols = 0;
    r.rows = 0;
    r.values.clear();
    EXPECT_THROW(heightGridFromRaster(r), tsf::InputError);
}

TEST(Bilinear, MatchesThesisEquation51ByHand) {
    const HeightGrid g = small();
    // Cell centres read back exactly.
    EXPECT_NEAR(sampleHeight(g, 2, 1, Interpolation::kBilinear).height, 1.0, kTol);
    EXPECT_NEAR(sampleHeight(g, 1, 0, Interpolation::kBilinear).height, 0.2, kTol);
    // (gi, gj) = (0.25, 0.5): u = 0.25, v = 0.5 in the cell with corners
    // T00 = 0.0, T10 = 0.2, T01 = 0.4, T11 = 0.5.
    const double u = 0.25, v = 0.5;
    const double expect = (1 - u) * (1 - v) * 0.0 + u * (1 - v) * 0.2 + (1 - u) * v * 0.4 + u * v * 0.5;
    const HeightSample s = sampleHeight(g, 0.25, 0.5, Interpolation::kBilinear);
    EXPECT_NEAR(s.height, expect, kTol);
    EXPECT_NEAR(s.d_di, (1 - v) * (0.2 - 0.0) + v * (0.5 - 0.4), kTol);
    EXPECT_NEAR(s.d_dj, (1 - u) * (0.4 - 0.0) + u * (0.5 - 0.2), kTol);
}

TEST(Bicubic, InterpolatesCellValuesAndReproducesLinearRampsInside) {
    const HeightGrid g = small();
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 3; ++i)
            EXPECT_NEAR(sampleHeight(g, i, j, Interpolation::kBicubic).height, g.at(i, j), kTol);
    // A linear ramp in i (8 columns): Catmull-Rom reproduces it exactly away
    // from the mirrored border cells, with slope 1/7 per cell.
    std::vector<float> h;
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 8; ++i) h.push_back(float(i) / 7.0f);
    const HeightGrid ramp = makeHeightGrid(8, 3, h);
    for (double gi = 1.0; gi <= 6.0; gi += 0.125) {
        const HeightSample s = sampleHeight(ramp, gi, 1.3, Interpolation::kBicubic);
        EXPECT_NEAR(s.height, gi / 7.0, kTol) << gi;
        EXPECT_NEAR(s.d_di, 1.0 / 7.0, kTol) << gi;
        EXPECT_NEAR(s.d_dj, 0.0, kTol) << gi;
    }
}

TEST(Bicubic, GradientIsContinuousAcrossCellBordersBilinearIsNot) {
    // A bump: the slope changes from cell to cell.
    const HeightGrid g = makeHeightGrid(5, 5, {0, 0, 0, 0, 0,  0, .2f, .5f, .2f, 0,  0, .5f, 1, .5f, 0,
                                               0, .2f, .5f, .2f, 0,  0, 0, 0, 0, 0});
    const double eps = 1e-7;
    double worst_cubic = 0.0, worst_linear = 0.0;
    for (int border = 1; border <= 3; ++border)
        for (double gj = 0.1; gj < 4.0; gj += 0.37) {
            const HeightSample a = sampleHeight(g, border - eps, gj, Interpolation::kBicubic);
            const HeightSample b = sampleHeight(g, border + eps, gj, Interpolation::kBicubic);
            worst_cubic = std::max(worst_cubic, std::abs(a.d_di - b.d_di));
            const HeightSample c = sampleHeight(g, border - eps, gj, Interpolation::kBilinear);
            const HeightSample d = sampleHeight(g, border + eps, gj, Interpolation::kBilinear);
            worst_linear = std::max(worst_linear, std::abs(c.d_di - d.d_di));
        }
    EXPECT_LT(worst_cubic, 1e-5);
    EXPECT_GT(worst_linear, 0.1);  // the ridge the bicubic mode removes
}

TEST(Gradient, AnalyticAgreesWithCentralDifferences) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> val(0.0f, 1.0f);
    std::vector<float> h(6 * 5);
    for (float& x : h) x = val(rng);
    const HeightGrid g = makeHeightGrid(6, 5, h);
    std::uniform_real_distribution<double> pos(0.2, 3.8);
    for (int k = 0; k < 200; ++k) {
        const double gi = pos(rng), gj = pos(rng);
        const HeightSample a = sampleHeight(g, gi, gj, Interpolation::kBicubic);
        const HeightSample c = sampleHeightCentral(g, gi, gj, Interpolation::kBicubic, 1e-4);
        EXPECT_NEAR(a.d_di, c.d_di, 1e-4);
        EXPECT_NEAR(a.d_dj, c.d_dj, 1e-4);
        EXPECT_NEAR(a.height, c.height, 1e-12);
    }
}

TEST(Border, OutsideIsClampedFlatAndContinuous) {
    const HeightGrid g = small();
    for (Interpolation m : {Interpolation::kBilinear, Interpolation::kBicubic}) {
        const HeightSample far = sampleHeight(g, 50.0, -50.0, m);
        EXPECT_NEAR(far.height, g.at(2, 0), kTol);
        EXPECT_EQ(far.d_di, 0.0);
        EXPECT_EQ(far.d_dj, 0.0);
        // Height continuous across the outermost centre line.
        EXPECT_NEAR(sampleHeight(g, -1e-9, 0.7, m).height, sampleHeight(g, 1e-9, 0.7, m).height, 1e-6);
    }
    // Bicubic: the slope across the border goes to zero at the last centre.
    EXPECT_NEAR(sampleHeight(g, 1e-9, 0.5, Interpolation::kBicubic).d_di, 0.0, 1e-6);
}

TEST(Degenerate, OneByOneAndOneRowFieldsAreFiniteAndConstantAlongOneCellAxes) {
    const HeightGrid one = makeHeightGrid(1, 1, {0.7f});
    const HeightGrid row = makeHeightGrid(4, 1, {0.0f, 1.0f, 0.0f, 1.0f});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> pos(-5.0, 9.0);
    for (int k = 0; k < 500; ++k) {
        const double gi = pos(rng), gj = pos(rng);
        for (Interpolation m : {Interpolation::kBilinear, Interpolation::kBicubic}) {
            const HeightSample a = sampleHeight(one, gi, gj, m);
            EXPECT_NEAR(a.height, 0.7, kTol);
            EXPECT_EQ(a.d_di, 0.0);
            EXPECT_EQ(a.d_dj, 0.0);
            const HeightSample b = sampleHeight(row, gi, gj, m);
            EXPECT_TRUE(std::isfinite(b.height) && std::isfinite(b.d_di));
            EXPECT_EQ(b.d_dj, 0.0);
        }
    }
    const HeightSample n = sampleHeight(row, std::nan(""), std::nan(""), Interpolation::kBicubic);
    EXPECT_TRUE(std::isfinite(n.height) && std::isfinite(n.d_di) && std::isfinite(n.d_dj));
}
