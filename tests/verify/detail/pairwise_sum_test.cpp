// detail::pairwiseSum: the bits of the level-by-level pairwise sum of a
// list, for any count of terms and of workers.
#include "verify/detail/pairwise_sum.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <vector>

#include <gtest/gtest.h>

namespace tsf::detail {
namespace {

// The order the sum must keep, written out on a list: (0 + 1), (2 + 3), ...
// level by level, an odd last term carried to the next level.
double levelByLevel(std::vector<double> terms) {
    if (terms.empty()) return 0.0;
    while (terms.size() > 1) {
        const size_t half = terms.size() / 2;
        for (size_t i = 0; i < half; ++i) terms[i] = terms[2 * i] + terms[2 * i + 1];
        if (terms.size() % 2) terms[half] = terms.back();
        terms.resize(half + terms.size() % 2);
    }
    return terms[0];
}

uint64_t bitsOf(double d) {
    uint64_t u;
    std::memcpy(&u, &d, sizeof u);
    return u;
}

// Terms of many magnitudes and both signs: a different order of adding
// them changes the last bits.
std::vector<double> mixedTerms(size_t n, unsigned seed) {
    std::mt19937_64 rng(seed);
    std::uniform_real_distribution<double> mantissa(-1.0, 1.0);
    std::uniform_int_distribution<int> exponent(-30, 30);
    std::vector<double> t(n);
    for (double& x : t) x = std::ldexp(mantissa(rng), exponent(rng));
    return t;
}

TEST(PairwiseSum, EveryCountHasTheBitsOfTheLevelByLevelSum) {
    constexpr size_t kBlock = size_t(1) << 14;  // pairwise_sum.h's block
    std::vector<size_t> counts;
    for (size_t n = 0; n <= 300; ++n) counts.push_back(n);
    for (size_t around : {kBlock, 2 * kBlock, 3 * kBlock, 4 * kBlock, 7 * kBlock})
        for (size_t d = 0; d <= 3; ++d) {
            counts.push_back(around - d);
            counts.push_back(around + d);
        }
    counts.push_back(5 * kBlock + 12345);
    for (size_t n : counts) {
        const std::vector<double> t = mixedTerms(n, unsigned(n));
        const double expected = levelByLevel(t);
        for (unsigned workers : {1u, 2u, 3u}) {
            const double got = pairwiseSum<double>(n, workers, [&](size_t k) { return t[k]; });
            ASSERT_EQ(bitsOf(got), bitsOf(expected)) << n << " terms, " << workers << " workers";
        }
    }
}

TEST(PairwiseSum, ADifferentOrderWouldShowInTheBits) {
    // The test above can fail: a running sum of the same terms differs.
    const size_t n = 3 * (size_t(1) << 14) + 77;
    const std::vector<double> t = mixedTerms(n, 7);
    double running = 0;
    for (double x : t) running += x;
    EXPECT_NE(bitsOf(running), bitsOf(levelByLevel(t)));
}

TEST(PairwiseSum, IntegersSumExactly) {
    const size_t n = 100003;
    EXPECT_EQ(pairwiseSum<double>(n, 2, [](size_t k) { return double(k); }), double(n) * double(n - 1) / 2);
    EXPECT_EQ(pairwiseSum<double>(0, 2, [](size_t) { return 1.0; }), 0.0);
    EXPECT_EQ(pairwiseSum<double>(1, 2, [](size_t) { return 2.5; }), 2.5);
}

}  // namespace
}  // namespace tsf::detail
