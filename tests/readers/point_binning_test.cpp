#include "gen/readers/point_binning.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>
#include <random>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

constexpr double kSqrt3Test = 1.7320508075688772;

PointTable makePoints(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& w = {}) {
    PointTable t;
    t.x = x;
    t.y = y;
    t.weight = w;
    t.source = "points";
    t.x_name = "x";
    t.y_name = "y";
    if (!w.empty()) t.weight_name = "w";
    return t;
}

double total(const HexField& f) {
    double s = 0.0;
    for (double v : f.values) s += v;
    return s;
}

// Independent check of the binning: every point must lie inside the hexagon
// (pointy-top, across-flats = pitch) of the cell it was counted in. Centres
// are computed from the layout's documented mapping, and the assignment by
// brute force (nearest centre over all cells), not with hexCellAt.
void expectBruteForceAgreement(const PointTable& pts, const BinOptions& opts) {
    const BinLayout layout = binLayout(pts, opts);
    const HexField f = binPoints(pts, opts);
    const HexGrid& g = layout.grid;
    ASSERT_EQ(f.grid.cols, g.cols);
    ASSERT_EQ(f.grid.rows, g.rows);
    std::vector<double> counts(size_t(g.cellCount()), 0.0);
    for (size_t k = 0; k < pts.size(); ++k) {
        const double u = (pts.x[k] - layout.x_min) / layout.pitch + layout.u_min;
        const double v = (pts.y[k] - layout.y_min) / layout.pitch + layout.v_min;
        double best = INFINITY;
        int64_t best_cell = -1;
        double best_dx = 0, best_dy = 0;
        for (int r = 0; r < g.rows; ++r)
            for (int c = 0; c < g.cols; ++c) {
                // Centre in pitches: x = col + 0.5 (+0.5 on odd rows from the north), y = (1.5 q + 1) / sqrt3.
                const double cx = c + 0.5 + 0.5 * (r % 2);
                const double cy = (1.5 * (g.rows - 1 - r) + 1.0) / kSqrt3Test;
                const double d2 = (u - cx) * (u - cx) + (v - cy) * (v - cy);
                if (d2 < best) {
                    best = d2;
                    best_cell = g.index(c, r);
                    best_dx = std::fabs(u - cx);
                    best_dy = std::fabs(v - cy);
                }
            }
        // Inside the hexagon, not merely nearest (pitch 1: |dx| <= 1/2, |dx|/2 + |dy| sqrt3/2 <= 1/2).
        ASSERT_LE(best_dx, 0.5 + 1e-12) << "point " << k;
        ASSERT_LE(best_dx / 2 + best_dy * kSqrt3Test / 2, 0.5 + 1e-12) << "point " << k;
        counts[size_t(best_cell)] += 1.0;
    }
    if (opts.aggregate == BinOptions::Aggregate::Count)
        for (size_t k = 0; k < counts.size(); ++k) EXPECT_EQ(f.values[k], counts[k]) << "cell " << k;
}

TEST(PointBinning, EveryPointCountedExactlyOnce) {
    std::mt19937 rng(11);
    std::normal_distribution<double> gx(10.0, 3.0), gy(-4.0, 1.0);
    std::vector<double> x, y;
    for (int k = 0; k < 3000; ++k) {
        x.push_back(gx(rng));
        y.push_back(gy(rng));
    }
    const PointTable pts = makePoints(x, y);
    for (int bins : {1, 2, 5, 17, 40}) {
        BinOptions opts;
        opts.hex_cols = bins;
        const HexField f = binPoints(pts, opts);
        EXPECT_EQ(total(f), 3000.0) << bins;
        EXPECT_EQ(f.grid.cols, bins) << "wider than tall: hex_cols columns";
        expectBruteForceAgreement(pts, opts);
    }
}

TEST(PointBinning, BinSizeIsThePitchInDataUnits) {
    const PointTable pts = makePoints({0, 10, 20, 33}, {0, 5, 1, 9});
    BinOptions opts;
    opts.bin_size = 2.5;
    const HexField f = binPoints(pts, opts);
    EXPECT_EQ(f.pitch_data, 2.5);
    EXPECT_EQ(total(f), 4.0);
    // 33 / 2.5 = 13.2 pitches wide: 13.2 + 0.5 -> 14 columns; 9 / 2.5 = 3.6 pitches deep.
    EXPECT_EQ(f.grid.cols, 14);
    EXPECT_GE(gridDepth(f.grid, 2.5, 1.0), 9.0);
    expectBruteForceAgreement(pts, opts);
}

TEST(PointBinning, SinglePointAndIdenticalPoints) {
    const HexField one = binPoints(makePoints({3.5}, {-2.0}));
    EXPECT_EQ(one.grid.cols, 1);
    EXPECT_EQ(one.grid.rows, 1);
    EXPECT_EQ(one.values, std::vector<double>{1.0});
    const HexField same = binPoints(makePoints(std::vector<double>(1000, 3.0), std::vector<double>(1000, 4.0)));
    EXPECT_EQ(same.grid.cellCount(), 1);
    EXPECT_EQ(same.values[0], 1000.0);
    BinOptions sized;
    sized.bin_size = 0.01;
    EXPECT_EQ(binPoints(makePoints({7, 7}, {7, 7}), sized).grid.cellCount(), 1);
}

TEST(PointBinning, CollinearPoints) {
    std::vector<double> line, zeros(100, 5.0);
    for (int k = 0; k < 100; ++k) line.push_back(k * 0.37);
    BinOptions opts;
    opts.hex_cols = 12;
    const HexField horizontal = binPoints(makePoints(line, zeros), opts);
    EXPECT_EQ(horizontal.grid.rows, 1);
    EXPECT_EQ(horizontal.grid.cols, 12);
    EXPECT_EQ(total(horizontal), 100.0);
    expectBruteForceAgreement(makePoints(line, zeros), opts);

    const HexField vertical = binPoints(makePoints(zeros, line), opts);
    EXPECT_EQ(vertical.grid.cols, 1);
    EXPECT_GE(vertical.grid.rows, 12);
    EXPECT_EQ(total(vertical), 100.0);
    expectBruteForceAgreement(makePoints(zeros, line), opts);

    std::vector<double> diag_y;
    for (double v : line) diag_y.push_back(-2.0 * v);
    EXPECT_EQ(total(binPoints(makePoints(line, diag_y), opts)), 100.0);
    expectBruteForceAgreement(makePoints(line, diag_y), opts);
}

TEST(PointBinning, LargeOffsetsAndTinySpreadsGiveTheSameField) {
    // The same pattern at the origin, offset by 1e9, and scaled down to a
    // 1e-12 spread must bin identically: binning depends only on shape.
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> d(0.0, 1000.0);
    std::vector<double> x, y, xo, yo, xs, ys;
    for (int k = 0; k < 500; ++k) {
        const double a = std::round(d(rng)), b = std::round(d(rng)) * 0.5;  // exactly representable
        x.push_back(a);
        y.push_back(b);
        xo.push_back(a + 1e9);
        yo.push_back(b - 1e9);
        xs.push_back(a * 1e-15);
        ys.push_back(b * 1e-15);
    }
    BinOptions opts;
    opts.hex_cols = 25;
    const HexField base = binPoints(makePoints(x, y), opts);
    const HexField offset = binPoints(makePoints(xo, yo), opts);
    const HexField tiny = binPoints(makePoints(xs, ys), opts);
    EXPECT_EQ(total(base), 500.0);
    EXPECT_EQ(base.grid.cols, offset.grid.cols);
    EXPECT_EQ(base.grid.rows, offset.grid.rows);
    EXPECT_EQ(base.values, offset.values);
    EXPECT_EQ(base.grid.rows, tiny.grid.rows);
    EXPECT_EQ(base.values, tiny.values);
    EXPECT_NEAR(tiny.pitch_data / base.pitch_data, 1e-15, 1e-24);
    expectBruteForceAgreement(makePoints(xo, yo), opts);
}

TEST(PointBinning, SumAndMeanOfWeights) {
    // Bin size 1 on a horizontal line: 11 columns, one row; points at 0 and 0.1
    // share the first cell, 10 is in the last.
    const PointTable pts = makePoints({0.0, 0.1, 0.05, 10.0}, {0, 0, 0, 0}, {1.0, 2.0, NAN, 5.0});
    BinOptions opts;
    opts.bin_size = 1.0;
    opts.aggregate = BinOptions::Aggregate::Count;
    const HexField count = binPoints(pts, opts);
    ASSERT_EQ(count.grid.cols, 11);
    ASSERT_EQ(count.grid.rows, 1);
    EXPECT_EQ(count.at(0, 0), 3.0);  // Count ignores weights, NaN included
    EXPECT_EQ(count.at(10, 0), 1.0);
    EXPECT_EQ(count.at(5, 0), 0.0);
    opts.aggregate = BinOptions::Aggregate::Sum;
    const HexField sum = binPoints(pts, opts);
    EXPECT_EQ(sum.at(0, 0), 3.0);
    EXPECT_EQ(sum.at(10, 0), 5.0);
    EXPECT_EQ(sum.at(5, 0), 0.0);
    opts.aggregate = BinOptions::Aggregate::Mean;
    const HexField mean = binPoints(pts, opts);
    EXPECT_EQ(mean.at(0, 0), 1.5);
    EXPECT_EQ(mean.at(10, 0), 5.0);
    EXPECT_TRUE(std::isnan(mean.at(5, 0)));  // no points: no data
    EXPECT_NE(mean.how.find("mean of w"), std::string::npos);
}

// Speed is measured in bench/, never here.
TEST(PointBinning, AMillionPointsAllCounted) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> d(-180.0, 180.0);
    std::vector<double> x(1'000'000), y(1'000'000);
    for (size_t k = 0; k < x.size(); ++k) {
        x[k] = d(rng);
        y[k] = d(rng) * 0.5;
    }
    const PointTable pts = makePoints(x, y);
    BinOptions opts;
    opts.hex_cols = 200;
    const HexField f = binPoints(pts, opts);
    EXPECT_EQ(total(f), 1e6);
    EXPECT_EQ(f.grid.cols, 200);
}

TEST(PointBinning, BadOptions) {
    const PointTable pts = makePoints({0, 1}, {0, 1});
    BinOptions opts;
    opts.aggregate = BinOptions::Aggregate::Sum;
    EXPECT_THROW(binPoints(pts, opts), InputError);  // no weight column
    opts = {};
    opts.bin_size = -1.0;
    EXPECT_THROW(binPoints(pts, opts), InputError);
    opts.bin_size = NAN;
    EXPECT_THROW(binPoints(pts, opts), InputError);
    opts.bin_size = 1e-6;  // a million x a million hexagons
    EXPECT_THROW(binPoints(pts, opts), InputError);
    opts = {};
    opts.hex_cols = -3;
    EXPECT_THROW(binPoints(pts, opts), InputError);
    EXPECT_THROW(binPoints(makePoints({}, {}), {}), InputError);
    EXPECT_THROW(binPoints(makePoints({-1e308, 1e308}, {0, 0}), {}), InputError);
    EXPECT_THROW(binPoints(makePoints({0, INFINITY}, {0, 0}), {}), InputError);
    EXPECT_THROW(binPoints(makePoints({0, 1, 2}, {0, 1}), {}), InputError);  // columns of different lengths
    EXPECT_THROW(binPoints(makePoints({0, 1}, {0, 1}, {1}), {}), InputError);
    EXPECT_EQ(parseAggregate("mean"), BinOptions::Aggregate::Mean);
    EXPECT_THROW(parseAggregate("median"), InputError);
}

TEST(PointBinning, AirportExampleBinsEveryAirport) {
    const PointTable pts = readPointsCsv(test::sourcePath("examples/airports-europe.csv"), parsePointColumns("x=lon,y=lat"));
    const HexField f = binPoints(pts, {});
    EXPECT_EQ(total(f), double(pts.size()));
    EXPECT_EQ(f.grid.cols, kDefaultPointBins);
    EXPECT_NE(f.how.find("count of points"), std::string::npos);
    expectBruteForceAgreement(pts, {});
}

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

// Each hexagon says where its centre lies in the points' own x and y: every
// hexagon that holds points has one within its circumradius (pitch / sqrt 3).
TEST(PointBinning, EachHexagonSaysWhereItsCentreLiesInThePointsCoordinates) {
    PointTable pts = makePoints({0, 10, 0, 10, 5, 2.5}, {0, 0, 10, 10, 5, 7.5});
    pts.x_name = "east";
    pts.y_name = "north";
    BinOptions o;
    o.hex_cols = 6;
    const HexField f = binPoints(pts, o);
    ASSERT_TRUE(f.place.known);
    EXPECT_EQ(f.place.axes.x, "east");
    EXPECT_EQ(f.place.axes.y, "north");
    int held = 0;
    for (int32_t r = 0; r < f.grid.rows; ++r)
        for (int32_t c = 0; c < f.grid.cols; ++c) {
            if (!(f.at(c, r) > 0)) continue;
            ++held;
            double nearest = 1e300;
            for (size_t k = 0; k < pts.size(); ++k)
                nearest = std::min(nearest, std::hypot(pts.x[k] - f.place.x(c, r), pts.y[k] - f.place.y(r)));
            EXPECT_LE(nearest, f.pitch_data / std::sqrt(3.0) + 1e-9) << c << ", " << r;
        }
    EXPECT_GE(held, 5);
}

}  // namespace
}  // namespace tsf
