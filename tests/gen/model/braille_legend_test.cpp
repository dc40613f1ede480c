// Braille through liblouis and the legend's layout in millimetres. Expected
// cells are from the braille code itself (a = dot 1, b = dots 1-2, c = dots
// 1-4; number sign dots 3-4-5-6), not from the code under test.
#include <gtest/gtest.h>

#include <cmath>

#include "gen/model/features/braille.h"
#include "gen/model/features/legend/legend.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

constexpr uint8_t kDot1 = 0x01, kDot2 = 0x02, kDot3 = 0x04, kDot4 = 0x08, kDot5 = 0x10, kDot6 = 0x20;

TEST(Braille, LettersAndNumbersInUncontractedEnglish) {
    EXPECT_EQ(translateToBraille("abc", kDefaultBrailleTable),
              (std::vector<uint8_t>{kDot1, kDot1 | kDot2, kDot1 | kDot4}));
    // Digits: the number sign, then a-j.
    EXPECT_EQ(translateToBraille("12", kDefaultBrailleTable),
              (std::vector<uint8_t>{kDot3 | kDot4 | kDot5 | kDot6, kDot1, kDot1 | kDot2}));
    // A space is the empty cell; in Unified English Braille (the default)
    // a letter standing alone is the letter, where EBAE (en-us-g1.ctb)
    // puts the letter sign (dots 5-6) before it.
    EXPECT_EQ(kDefaultBrailleTable, std::string("en-ueb-g1.ctb"));
    EXPECT_EQ(translateToBraille("ab c", kDefaultBrailleTable), (std::vector<uint8_t>{kDot1, kDot1 | kDot2, 0, kDot1 | kDot4}));
    EXPECT_EQ(translateToBraille("ab c", "en-us-g1.ctb"),
              (std::vector<uint8_t>{kDot1, kDot1 | kDot2, 0, kDot5 | kDot6, kDot1 | kDot4}));
    // The decimal point: dots 2-5-6 in UEB, dots 4-6 in EBAE; the comma
    // inside a number (dot 2 in both) keeps one number sign.
    EXPECT_EQ(translateToBraille("1.5", kDefaultBrailleTable),
              (std::vector<uint8_t>{kDot3 | kDot4 | kDot5 | kDot6, kDot1, kDot2 | kDot5 | kDot6, kDot1 | kDot5}));
    EXPECT_EQ(translateToBraille("1.5", "en-us-g1.ctb"),
              (std::vector<uint8_t>{kDot3 | kDot4 | kDot5 | kDot6, kDot1, kDot4 | kDot6, kDot1 | kDot5}));
    for (const char* table : {kDefaultBrailleTable, "en-us-g1.ctb"})
        EXPECT_EQ(translateToBraille("15,000", table),
                  (std::vector<uint8_t>{kDot3 | kDot4 | kDot5 | kDot6, kDot1, kDot1 | kDot5, kDot2, kDot2 | kDot4 | kDot5,
                                        kDot2 | kDot4 | kDot5, kDot2 | kDot4 | kDot5}))
            << table;
    EXPECT_EQ(brailleUnicode({kDot1, kDot1 | kDot2, kDot1 | kDot4}), "\u2801\u2803\u2809");
    EXPECT_TRUE(translateToBraille("", kDefaultBrailleTable).empty());
}

TEST(Braille, AnyLiblouisTableByNameAndAClearErrorForAnUnknownOne) {
    // German uncontracted: a-umlaut is dots 3-4-5.
    EXPECT_EQ(translateToBraille("\xC3\xA4", "de-g0.utb"), (std::vector<uint8_t>{kDot3 | kDot4 | kDot5}));
    EXPECT_INPUT_ERROR(translateToBraille("abc", "no-such-table.ctb"), "no-such-table.ctb");
    EXPECT_INPUT_ERROR(translateToBraille("a\xFF", kDefaultBrailleTable), "not UTF-8");
}

TEST(Legend, DotCentresFollowTheStandardsSpacing) {
    LegendParams p;
    p.lines = {"ab", "cb"};
    p.margin_mm = 3.0;
    const LegendLayout l = layoutLegend(p);
    const BrailleStandard& s = kNlsSpec800;
    ASSERT_EQ(l.cells.size(), 2u);
    ASSERT_EQ(l.dots.size(), 1u + 2u + 2u + 2u);  // a: 1, b: 2, c: 2, b: 2
    const double r = s.dot_base_mm / 2;
    // Two cells wide, two lines deep, margins and dot radii around.
    EXPECT_NEAR(l.width_mm, 2 * 3.0 + 2 * r + s.cell_pitch_mm + s.dot_pitch_mm, 1e-9);
    EXPECT_NEAR(l.depth_mm, 2 * 3.0 + 2 * r + s.line_pitch_mm + 2 * s.dot_pitch_mm, 1e-9);
    // a: dot 1 at the north-west; b: dots 1 and 2 one cell east; c: dots 1 and 4 one line south; b.
    const double x0 = 3.0 + r, y0 = l.depth_mm - 3.0 - r;
    EXPECT_NEAR(l.dots[0].x_mm, x0, 1e-9);
    EXPECT_NEAR(l.dots[0].y_mm, y0, 1e-9);
    EXPECT_NEAR(l.dots[1].x_mm, x0 + s.cell_pitch_mm, 1e-9);
    EXPECT_NEAR(l.dots[2].y_mm, y0 - s.dot_pitch_mm, 1e-9);
    EXPECT_NEAR(l.dots[3].y_mm, y0 - s.line_pitch_mm, 1e-9);
    EXPECT_NEAR(l.dots[4].x_mm, x0 + s.dot_pitch_mm, 1e-9);
    // Every dot's base lies inside the legend with its margin.
    for (const LegendDot& d : l.dots) {
        EXPECT_GE(d.x_mm - r, 3.0 - 1e-9);
        EXPECT_LE(d.x_mm + r, l.width_mm - 3.0 + 1e-9);
        EXPECT_GE(d.y_mm - r, 3.0 - 1e-9);
        EXPECT_LE(d.y_mm + r, l.depth_mm - 3.0 + 1e-9);
        EXPECT_EQ(d.x_mm * 1000, std::round(d.x_mm * 1000));  // on the 1 um grid
    }
}

TEST(Legend, LongLinesBreakAtSpacesAndAnOverlongWordSaysWhatToChange) {
    LegendParams p;
    p.lines = {"abc def ghi"};
    p.max_cells = 7;
    const LegendLayout l = layoutLegend(p);
    EXPECT_EQ(l.text, (std::vector<std::string>{"abc def", "ghi"}));
    p.max_cells = 2;
    EXPECT_INPUT_ERROR(layoutLegend(p), "give a shorter --title or --units");
    // The unit is joined to its number by a no-break space: one line.
    EXPECT_EQ(legendRangeText(0, 27, "airports"), "0 to 27\u00A0airports");
    EXPECT_EQ(legendRangeText(0, 1.5e-5, ""), "0 to 0.000015");
    EXPECT_EQ(legendRangeText(0, 2.5e6, ""), "0 to 2,500,000");
    p.lines = {"142 to 537.3\u00A0m"};
    p.max_cells = 14;  // "142 to 537.3" fits; "537.3 m" must go whole to the next line
    const LegendLayout unit = layoutLegend(p);
    EXPECT_EQ(unit.text, (std::vector<std::string>{"142 to", "537.3 m"}));
    EXPECT_EQ(legendRangeText(-1.5, 2500.25, ""), "-1.5 to 2500");
}

}  // namespace
}  // namespace tsf
