// Mipmap and Gaussian scale-space levels against their definitions
// (thesis eq. 5.2 and L = g(t) * f with t = 4^n).
#include <cmath>
#include <numbers>

#include <gtest/gtest.h>

#include "haptics/scale_space.h"

using namespace tsf::haptics;

TEST(Mipmap, FourByFourAveragesTwoByTwoBlocks) {
    // rows south first
    const HeightGrid g = makeHeightGrid(4, 4, {0.0f, 0.2f, 0.4f, 0.4f,   //
                                               0.2f, 0.2f, 0.8f, 0.0f,   //
                                               1.0f, 1.0f, 0.0f, 0.0f,   //
                                               1.0f, 0.6f, 0.1f, 0.3f});
    const HeightGrid m = mipmapDown(g);
    ASSERT_EQ(m.cols, 2);
    ASSERT_EQ(m.rows, 2);
    EXPECT_NEAR(m.at(0, 0), (0.0 + 0.2 + 0.2 + 0.2) / 4, 1e-6);
    EXPECT_NEAR(m.at(1, 0), (0.4 + 0.4 + 0.8 + 0.0) / 4, 1e-6);
    EXPECT_NEAR(m.at(0, 1), (1.0 + 1.0 + 1.0 + 0.6) / 4, 1e-6);
    EXPECT_NEAR(m.at(1, 1), (0.0 + 0.0 + 0.1 + 0.3) / 4, 1e-6);
    const HeightGrid top = mipmapDown(m);
    ASSERT_EQ(top.cols, 1);
    EXPECT_NEAR(top.at(0, 0), (0.15 + 0.4 + 0.9 + 0.1) / 4, 1e-6);
    EXPECT_EQ(mipmapDown(top).cols, 1);  // 1 x 1 stays 1 x 1
}

TEST(Mipmap, OddSizeReplicatesTheLastRowAndColumn) {
    const HeightGrid g = makeHeightGrid(3, 1, {0.2f, 0.4f, 1.0f});
    const HeightGrid m = mipmapDown(g);
    ASSERT_EQ(m.cols, 2);
    ASSERT_EQ(m.rows, 1);
    EXPECT_NEAR(m.at(0, 0), 0.3, 1e-6);  // (0.2 + 0.4 + 0.2 + 0.4) / 4
    EXPECT_NEAR(m.at(1, 0), 1.0, 1e-6);  // edge cell with itself
}

TEST(Mipmap, LevelsAreSampledInBaseCoordinates) {
    // A linear ramp h = gi / 15: averaging keeps a ramp, and a level sampled
    // at base coordinate gi must give gi / 15 again (away from the border).
    std::vector<float> h;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) h.push_back(float(i) / 15.0f);
    const ScaleSpace s = buildScaleSpace(makeHeightGrid(16, 16, h), 4, ScaleSpaceKind::kMipmap);
    ASSERT_EQ(s.count(), 4);
    EXPECT_EQ(s.levels[3].grid.cols, 2);
    SamplingParams lin{Interpolation::kBilinear, false, 0.5};
    for (int level = 0; level < 4; ++level) {
        const double lo = (std::pow(2.0, level) - 1) / 2, hi = 15 - lo;  // outermost texel centres
        for (double gi = lo; gi <= hi; gi += 0.25) {
            const HeightSample v = sampleLevel(s, level, gi, 7.0, lin);
            EXPECT_NEAR(v.height, gi / 15.0, 1e-5) << "level " << level << " gi " << gi;
            EXPECT_NEAR(v.d_di, 1.0 / 15.0, 1e-5);
        }
    }
}

TEST(Gaussian, ImpulseBecomesTheSampledGaussianOfVarianceT) {
    const int n = 41, c = 20;
    std::vector<float> h(size_t(n * n), 0.0f);
    h[size_t(c * n + c)] = 1.0f;
    const ScaleSpace s = buildScaleSpace(makeHeightGrid(n, n, h), 3, ScaleSpaceKind::kGaussian);
    ASSERT_EQ(s.count(), 3);
    EXPECT_DOUBLE_EQ(s.levels[1].t_cells2, 4.0);
    EXPECT_DOUBLE_EQ(s.levels[2].t_cells2, 16.0);
    for (int level : {1, 2}) {
        const double t = s.levels[size_t(level)].t_cells2;
        const HeightGrid& g = s.levels[size_t(level)].grid;
        double mass = 0.0, var_x = 0.0;
        for (int j = 0; j < n; ++j)
            for (int i = 0; i < n; ++i) {
                const double v = g.at(i, j);
                mass += v;
                var_x += v * (i - c) * (i - c);
                // Continuous Gaussian density at the cell centre; at sigma >= 2
                // the sampled kernel differs from it by far less than 1e-4.
                const double r2 = double((i - c) * (i - c) + (j - c) * (j - c));
                const double expect = std::exp(-r2 / (2 * t)) / (2 * std::numbers::pi * t);
                EXPECT_NEAR(v, expect, 2e-4 * (1.0 / (2 * std::numbers::pi * t)) + 1e-6) << i << "," << j;
            }
        EXPECT_NEAR(mass, 1.0, 1e-4);
        EXPECT_NEAR(var_x / mass, t, 0.02 * t);
    }
}

TEST(Gaussian, ConstantStaysConstantAndRampStaysRampInside) {
    const HeightGrid flat = makeHeightGrid(9, 7, std::vector<float>(63, 0.6f));
    const HeightGrid b = gaussianBlur(flat, 16.0);
    for (float v : b.heights) EXPECT_NEAR(v, 0.6f, 1e-6);
    std::vector<float> h;
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 60; ++i) h.push_back(float(i) / 59.0f);
    const HeightGrid r = gaussianBlur(makeHeightGrid(60, 5, h), 4.0);
    for (int i = 10; i < 50; ++i) EXPECT_NEAR(r.at(i, 2), i / 59.0, 1e-5);  // symmetric kernel keeps a line
}

TEST(Gaussian, CascadeMatchesDirectBlurFromTheBase) {
    std::vector<float> h(48 * 40);
    for (size_t k = 0; k < h.size(); ++k) h[k] = float(0.5 + 0.5 * std::sin(0.37 * double(k % 48)) * std::cos(0.21 * double(k / 48)));
    const HeightGrid base = makeHeightGrid(48, 40, h);
    const ScaleSpace s = buildScaleSpace(base, 3, ScaleSpaceKind::kGaussian);
    const HeightGrid direct = gaussianBlur(base, 16.0, 8.0);
    double worst = 0.0;
    for (size_t k = 0; k < h.size(); ++k) worst = std::max(worst, double(std::abs(direct.heights[k] - s.levels[2].grid.heights[k])));
    EXPECT_LT(worst, 2e-3);  // semigroup holds up to kernel sampling and truncation
}

TEST(ScaleSample, EquationFourNineInterpolatesLinearlyBetweenLevels) {
    const HeightGrid g = makeHeightGrid(4, 4, {0, 0, 0, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 0, 0, 0});
    const ScaleSpace s = buildScaleSpace(g, 3, ScaleSpaceKind::kMipmap);
    const SamplingParams sp{Interpolation::kBilinear, false, 0.5};
    const double a = sampleLevel(s, 0, 1.2, 1.7, sp).height;
    const double b = sampleLevel(s, 1, 1.2, 1.7, sp).height;
    EXPECT_NEAR(sampleScale(s, 0.3, 1.2, 1.7, sp).height, 0.7 * a + 0.3 * b, 1e-12);
    EXPECT_NEAR(sampleScale(s, -4.0, 1.2, 1.7, sp).height, a, 1e-12);           // clamped below
    EXPECT_NEAR(sampleScale(s, std::nan(""), 1.2, 1.7, sp).height, a, 1e-12);   // NaN -> level 0
    EXPECT_NEAR(sampleScale(s, 99.0, 1.2, 1.7, sp).height, sampleLevel(s, 2, 1.2, 1.7, sp).height, 1e-12);
}

TEST(ScaleSpace, LevelsCountDataCellsWhenACellHasManySamples) {
    // The printed relief samples each hexagon 6 times across: level n still
    // smooths over about 2^n cells, not 2^n samples.
    const HeightGrid g = makeHeightGrid(48, 48, std::vector<float>(48 * 48, 0.5f));
    const ScaleSpace gau = buildScaleSpace(g, 3, ScaleSpaceKind::kGaussian, 6.0);
    EXPECT_DOUBLE_EQ(gau.levels[1].t_cells2, 4.0 * 36.0);
    EXPECT_DOUBLE_EQ(gau.levels[2].t_cells2, 16.0 * 36.0);
    const ScaleSpace mip = buildScaleSpace(g, 3, ScaleSpaceKind::kMipmap, 6.0);
    EXPECT_DOUBLE_EQ(mip.levels[1].base_cells_per_texel, 16.0);  // the first power of two >= 2 * 6
    EXPECT_DOUBLE_EQ(mip.levels[2].base_cells_per_texel, 32.0);  // >= 4 * 6
    EXPECT_EQ(mip.levels[2].grid.cols, 2);
}
