#include "gen/field/resample.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "tests/support/input_error.h"

namespace tsf {
namespace {

constexpr double kSqrt3Test = 1.7320508075688772;

Raster makeRaster(int32_t cols, int32_t rows, double fill = 0.0) {
    Raster r;
    r.cols = cols;
    r.rows = rows;
    r.values.assign(size_t(cols) * size_t(rows), fill);
    r.source = "test";
    return r;
}

// The layout as documented in resample.h, recomputed here from the text:
// pitch p, rows R, and hexagon centres in pixel coordinates (x east, y down).
struct ExpectedLayout {
    int cols = 0, rows = 0;
    double p = 0.0;
    double x0 = 0.0, y_bottom = 0.0;  // pixel position of the grid's bounding-box lower-left corner
    // Hexagon centres per hex_grid.h: rows counted from the north, odd rows
    // shifted east by half a pitch; rows p sqrt3/2 apart, the southmost row's
    // centre one circumradius (p / sqrt3) above the bounding box's bottom.
    double centreX(int col, int row) const { return x0 + (col + 0.5 + 0.5 * (row % 2)) * p; }
    double centreY(int row) const { return y_bottom - ((rows - 1 - row) * 1.5 + 1.0) * p / kSqrt3Test; }
};

ExpectedLayout expectedLayout(int raster_cols, int raster_rows, int hex_cols) {
    ExpectedLayout e;
    e.cols = hex_cols;
    const double p1 = double(raster_cols) / hex_cols;
    if (std::round(raster_rows / (p1 * kSqrt3Test / 2)) <= 1) {
        e.p = p1;
        e.rows = 1;
    } else {
        e.p = raster_cols / (hex_cols + 0.5);
        e.rows = int(std::max(1.0, std::round(raster_rows / (e.p * kSqrt3Test / 2))));
    }
    // Bounding box: width = (C + 0.5) p with two or more rows, C p with one;
    // depth = (R - 1) * row spacing + 2 * circumradius.
    const double width = (e.rows > 1 ? hex_cols + 0.5 : hex_cols) * e.p;
    const double depth = (e.rows - 1) * e.p * kSqrt3Test / 2 + 2 * e.p / kSqrt3Test;
    e.x0 = (raster_cols - width) / 2;
    e.y_bottom = (raster_rows + depth) / 2;
    return e;
}

// Pointy-top hexagon of pitch p (across flats) centred at (cx, cy): inside test.
bool inHexagon(double x, double y, double cx, double cy, double p, double margin) {
    const double dx = std::fabs(x - cx), dy = std::fabs(y - cy);
    return dx <= p / 2 - margin && dx / 2 + dy * kSqrt3Test / 2 <= p / 2 - margin;
}

TEST(Resample, ConstantRasterGivesTheConstantEverywhere) {
    for (auto method : {ResampleOptions::Method::Mean, ResampleOptions::Method::Nearest, ResampleOptions::Method::Bilinear}) {
        for (int hex_cols : {0, 1, 7, 40}) {
            const Raster r = makeRaster(37, 23, 4.25);
            const HexField f = resampleRaster(r, {hex_cols, method});
            ASSERT_GT(f.values.size(), 0u);
            for (double v : f.values) ASSERT_EQ(v, 4.25) << resampleMethodName(method) << " " << hex_cols;
        }
    }
}

TEST(Resample, KeepsTheAspectRatio) {
    struct Case { int cols, rows, hex_cols; };
    for (const Case c : {Case{100, 50, 0}, Case{61, 87, 0}, Case{61, 87, 20}, Case{300, 20, 37}, Case{7, 200, 7},
                         Case{1000, 1000, 50}, Case{2, 3, 5}}) {
        const HexField f = resampleRaster(makeRaster(c.cols, c.rows), {c.hex_cols});
        const double p = f.pitch_data;  // cell_size 1: pixels
        const int hex_cols = c.hex_cols > 0 ? c.hex_cols : std::min(c.cols, 1000);
        EXPECT_EQ(f.grid.cols, hex_cols);
        // Width: the hexagons span exactly the raster's width.
        EXPECT_NEAR(gridWidth(f.grid, p), double(c.cols), 1e-9 * c.cols) << c.cols << "x" << c.rows;
        // Depth: rows of hexagons (p sqrt3/2 apart) cover the raster's height within one hex row.
        const double rows_span = f.grid.rows * p * kSqrt3Test / 2;
        EXPECT_LE(std::fabs(rows_span - c.rows), p * kSqrt3Test / 2) << c.cols << "x" << c.rows;
        // Hence the width/depth ratio matches the raster's within one cell's worth.
        const double ratio_hex = gridWidth(f.grid, p) / rows_span;
        const double ratio_raster = double(c.cols) / c.rows;
        EXPECT_NEAR(ratio_hex, ratio_raster, ratio_raster / std::max(1, f.grid.rows - 1) + 1e-12);
    }
}

TEST(Resample, OneByOneRasterGivesOneHexagon) {
    Raster r = makeRaster(1, 1, 9.5);
    r.cell_size = 30.0;
    for (auto method : {ResampleOptions::Method::Mean, ResampleOptions::Method::Nearest, ResampleOptions::Method::Bilinear}) {
        const HexField f = resampleRaster(r, {0, method});
        EXPECT_EQ(f.grid.cols, 1);
        EXPECT_EQ(f.grid.rows, 1);
        ASSERT_EQ(f.values.size(), 1u);
        EXPECT_EQ(f.values[0], 9.5);
        EXPECT_EQ(f.pitch_data, 30.0);  // one pixel, in data units
    }
}

TEST(Resample, StripOfPixelsGivesOneRowOfHexagons) {
    Raster r = makeRaster(10, 1);
    for (int k = 0; k < 10; ++k) r.values[size_t(k)] = k;
    const HexField f = resampleRaster(r);
    EXPECT_EQ(f.grid.rows, 1);
    EXPECT_EQ(f.grid.cols, 10);
    for (int k = 0; k < 10; ++k) EXPECT_EQ(f.at(k, 0), double(k));
}

TEST(Resample, SingleValidPixelSurvivesAndNaNStaysNaN) {
    Raster r = makeRaster(50, 50, NAN);
    r.at(20, 31) = 7.0;
    // Coarse: every hexagon holds many pixel centres, exactly one holds the valid one.
    const HexField coarse = resampleRaster(r, {10});
    int finite = 0;
    for (double v : coarse.values)
        if (!std::isnan(v)) {
            ++finite;
            EXPECT_EQ(v, 7.0);
        }
    EXPECT_EQ(finite, 1);
    // Fine (about one hexagon per pixel): the value survives; hexagons without a
    // pixel centre take the pixel under their centre, so it may appear twice.
    const HexField fine = resampleRaster(r);
    finite = 0;
    for (double v : fine.values)
        if (!std::isnan(v)) {
            ++finite;
            EXPECT_EQ(v, 7.0);
        }
    EXPECT_GE(finite, 1);
    EXPECT_LE(finite, 2);
}

TEST(Resample, NaNRegionStaysNaNAndValidRegionStaysValid) {
    // Left half no data, right half 1.
    Raster r = makeRaster(60, 40, 1.0);
    for (int y = 0; y < 40; ++y)
        for (int x = 0; x < 30; ++x) r.at(x, y) = NAN;
    for (auto method : {ResampleOptions::Method::Mean, ResampleOptions::Method::Nearest, ResampleOptions::Method::Bilinear}) {
        const HexField f = resampleRaster(r, {15, method});
        const ExpectedLayout e = expectedLayout(60, 40, 15);
        ASSERT_EQ(f.grid.rows, e.rows);
        for (int row = 0; row < f.grid.rows; ++row)
            for (int col = 0; col < f.grid.cols; ++col) {
                const double x = e.centreX(col, row);
                const double v = f.at(col, row);
                if (x + e.p < 30.0) EXPECT_TRUE(std::isnan(v)) << resampleMethodName(method) << " " << col << "," << row;
                if (x - e.p > 30.0) EXPECT_EQ(v, 1.0) << resampleMethodName(method) << " " << col << "," << row;
            }
    }
}

TEST(Resample, MeanMatchesABruteForceOverPixelCentres) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> value(-5.0, 5.0);
    const int W = 45, H = 31, C = 9;
    Raster r = makeRaster(W, H);
    for (double& v : r.values) v = value(rng);
    for (int k = 0; k < 40; ++k) r.values[size_t(rng() % r.values.size())] = NAN;
    const HexField f = resampleRaster(r, {C});
    const ExpectedLayout e = expectedLayout(W, H, C);
    ASSERT_EQ(f.grid.cols, C);
    ASSERT_EQ(f.grid.rows, e.rows);
    EXPECT_NEAR(f.pitch_data, e.p, 1e-12);
    const double kBoundary = 1e-9;  // pixels this close to a hexagon edge could go either way
    int compared = 0;
    for (int row = 0; row < e.rows; ++row)
        for (int col = 0; col < C; ++col) {
            const double cx = e.centreX(col, row);
            const double cy = e.centreY(row);
            double sum = 0.0;
            int n = 0;
            bool ambiguous = false;
            for (int y = 0; y < H; ++y)
                for (int x = 0; x < W; ++x) {
                    const double px = x + 0.5, py = y + 0.5;
                    const bool in = inHexagon(px, py, cx, cy, e.p, 0.0);
                    if (in != inHexagon(px, py, cx, cy, e.p, kBoundary)) ambiguous = true;
                    if (in && !std::isnan(r.at(x, y))) {
                        sum += r.at(x, y);
                        ++n;
                    }
                }
            if (ambiguous) continue;
            ++compared;
            if (n == 0) EXPECT_TRUE(std::isnan(f.at(col, row)));
            else EXPECT_NEAR(f.at(col, row), sum / n, 1e-12) << col << "," << row;
        }
    EXPECT_GT(compared, C * e.rows / 2);
}

TEST(Resample, NearestAndBilinearOnALinearRamp) {
    // v = 2 x + 3 y at pixel centres: bilinear reproduces it exactly inside the
    // raster, nearest gives the pixel under the hexagon centre.
    const int W = 30, H = 20, C = 12;
    Raster r = makeRaster(W, H);
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) r.at(x, y) = 2.0 * (x + 0.5) + 3.0 * (y + 0.5);
    const HexField bil = resampleRaster(r, {C, ResampleOptions::Method::Bilinear});
    const HexField near = resampleRaster(r, {C, ResampleOptions::Method::Nearest});
    const ExpectedLayout e = expectedLayout(W, H, C);
    for (int row = 0; row < e.rows; ++row)
        for (int col = 0; col < C; ++col) {
            const double cx = e.centreX(col, row);
            const double cy = e.centreY(row);
            const double ux = std::clamp(cx, 0.5, W - 0.5), uy = std::clamp(cy, 0.5, H - 0.5);
            EXPECT_NEAR(bil.at(col, row), 2.0 * ux + 3.0 * uy, 1e-9) << col << "," << row;
            const int px = std::clamp(int(std::floor(cx)), 0, W - 1), py = std::clamp(int(std::floor(cy)), 0, H - 1);
            EXPECT_EQ(near.at(col, row), r.at(px, py)) << col << "," << row;
        }
}

TEST(Resample, BilinearIsNaNNextToNoData) {
    Raster r = makeRaster(20, 20, 1.0);
    r.at(10, 10) = NAN;
    const HexField f = resampleRaster(r, {0, ResampleOptions::Method::Bilinear});
    const ExpectedLayout e = expectedLayout(20, 20, 20);
    ASSERT_EQ(f.grid.rows, e.rows);
    // Exactly the hexagon centres less than one pixel from the NaN pixel's
    // centre (10.5, 10.5) in x and in y give that pixel a non-zero weight.
    int expected_nan = 0;
    for (int row = 0; row < e.rows; ++row)
        for (int col = 0; col < e.cols; ++col) {
            const bool near_nan = std::fabs(e.centreX(col, row) - 10.5) < 1.0 && std::fabs(e.centreY(row) - 10.5) < 1.0;
            expected_nan += near_nan ? 1 : 0;
            EXPECT_EQ(std::isnan(f.at(col, row)), near_nan) << col << "," << row;
            if (!near_nan) EXPECT_NEAR(f.at(col, row), 1.0, 1e-12);
        }
    EXPECT_GE(expected_nan, 1);
}

TEST(Resample, RecordsHowAndPitchInDataUnits) {
    Raster r = makeRaster(61, 87, 100.0);
    r.cell_size = 10.0;
    r.source = "volcano.asc";
    const HexField f = resampleRaster(r, {20});
    EXPECT_EQ(f.source, "volcano.asc");
    EXPECT_NEAR(f.pitch_data, 10.0 * 61 / 20.5, 1e-9);
    EXPECT_NE(f.how.find("mean"), std::string::npos);
    EXPECT_NE(f.how.find("61 x 87 px"), std::string::npos);
}

// Where each hexagon lies in the data's coordinates (gen/field/data_place.h),
// from the layout recomputed above: a resampled hexagon stands for its
// centre; one pillar per value for its pixel's centre; squared pixels
// keep the raster's extent.
TEST(Resample, EachHexagonSaysWhereItLiesInTheData) {
    Raster r = makeRaster(61, 87, 1.0);
    r.place = {.known = true, .x_west = 1000, .dx = 10, .y_north = 2000, .dy = 10, .axes = {"easting", "northing", "metres"}};
    const HexField f = resampleRaster(r, {.hex_cols = 34});
    const ExpectedLayout e = expectedLayout(61, 87, 34);
    ASSERT_TRUE(f.place.known);
    EXPECT_EQ(f.place.axes.x, "easting");
    EXPECT_EQ(f.place.axes.unit, "metres");
    for (const auto& [c, row] : std::vector<std::pair<int, int>>{{0, 0}, {4, 0}, {4, 1}, {33, 48}, {10, e.rows - 1}}) {
        EXPECT_NEAR(f.place.x(c, row), 1000 + 10 * e.centreX(c, row), 1e-9) << c << " " << row;
        EXPECT_NEAR(f.place.y(row), 2000 - 10 * e.centreY(row), 1e-9) << row;
    }

    const HexField one = rasterOneToOne(r);
    ASSERT_TRUE(one.place.known);
    EXPECT_DOUBLE_EQ(one.place.x(0, 0), 1005);
    EXPECT_DOUBLE_EQ(one.place.x(60, 1), 1605);  // odd rows stand for their own pixels
    EXPECT_DOUBLE_EQ(one.place.y(86), 2000 - 865);

    // Rows twice as far apart on the ground: squared by repeating rows, the
    // same extent in twice the rows, each half as tall in the data.
    Raster tall = makeRaster(4, 3, 1.0);
    tall.row_aspect = 2.0;
    tall.place = {.known = true, .x_west = 0, .dx = 1, .y_north = 30, .dy = 10, .axes = {}};
    const Raster square = squarePixels(tall);
    ASSERT_EQ(square.rows, 6);
    EXPECT_DOUBLE_EQ(square.place.dy, 5);
    EXPECT_DOUBLE_EQ(square.place.dx, 1);
    EXPECT_DOUBLE_EQ(rasterOneToOne(square).place.y(5), 2.5);

    EXPECT_FALSE(resampleRaster(makeRaster(10, 10), {.hex_cols = 5}).place.known);  // a picture has no coordinates
}

TEST(Resample, LimitsAndBadOptions) {
    EXPECT_THROW(resampleRaster(makeRaster(10, 10), {-1}), InputError);
    EXPECT_THROW(resampleRaster(makeRaster(10, 10), {kMaxResampleCols + 1}), InputError);
    EXPECT_THROW(resampleRaster(Raster{}, {}), InputError);
    Raster short_of_values = makeRaster(10, 10);
    short_of_values.values.pop_back();
    EXPECT_THROW(resampleRaster(short_of_values, {}), InputError);
    // Default columns are capped.
    const ResampleLayout wide = resampleLayout(5000, 10, 0);
    EXPECT_EQ(wide.grid.cols, kMaxResampleCols);
    // A very tall thin raster at many columns exceeds the cell cap.
    EXPECT_THROW(resampleLayout(20, 20000, 1000), InputError);
    EXPECT_EQ(parseResampleMethod("bilinear"), ResampleOptions::Method::Bilinear);
    EXPECT_THROW(parseResampleMethod("cubic"), InputError);
}

}  // namespace
}  // namespace tsf
