// formatForReader: numbers a screen reader says and braille embosses as
// one number each, never e-notation, never digits grouped by spaces.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>

#include "gen/util/number_format.h"

namespace tsf {
namespace {

TEST(FormatForReader, WholeNumbersGroupedByCommasFromTenThousand) {
    EXPECT_EQ(formatForReader(0), "0");
    EXPECT_EQ(formatForReader(7), "7");
    EXPECT_EQ(formatForReader(1680), "1680");
    EXPECT_EQ(formatForReader(15000), "15,000");
    EXPECT_EQ(formatForReader(1680000), "1,680,000");
    EXPECT_EQ(formatForReader(-1680000), "-1,680,000");
    EXPECT_EQ(formatForReader(1234567, 4), "1,235,000");  // four significant digits, the rest zeros
    EXPECT_EQ(formatForReader(40030000, 4), "40,030,000");
    EXPECT_EQ(formatForReader(123456789012345.0, 15), "123,456,789,012,345");
}

TEST(FormatForReader, FractionsWrittenOutWithoutTrailingZeros) {
    EXPECT_EQ(formatForReader(0.25), "0.25");
    EXPECT_EQ(formatForReader(193.75, 4), "193.8");
    EXPECT_EQ(formatForReader(2.0, 4), "2");
    EXPECT_EQ(formatForReader(1.5e-5, 4), "0.000015");
    EXPECT_EQ(formatForReader(-0.0001234, 3), "-0.000123");
    EXPECT_EQ(formatForReader(12345.678, 6), "12,345.7");
}

TEST(FormatForReader, BeyondWhatFixedDigitsCanSayAPowerOfTenInWords) {
    EXPECT_EQ(formatForReader(2.5e-9, 4), "2.5 times ten to the power of minus 9");
    EXPECT_EQ(formatForReader(1.797e308, 4), "1.797 times ten to the power of 308");
    EXPECT_EQ(formatForReader(9.9999e-7, 3), "1 times ten to the power of minus 6");  // rounding carries
    for (double v : {1e-300, 3.3e-7, 1e15, 6.02e23, -4.2e20}) {
        const std::string s = formatForReader(v, 4);
        EXPECT_FALSE(std::regex_search(s, std::regex(R"(\d[eE][+-]?\d)"))) << s;
        EXPECT_TRUE(s.find("times ten to the power of") != std::string::npos) << s;
    }
    EXPECT_EQ(formatForReader(NAN), "nan");
}

}  // namespace
}  // namespace tsf
