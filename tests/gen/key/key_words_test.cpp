// The key's words (gen/key/): units spelled out from UDUNITS-style
// strings, where a set of cells lies in words, and text made fit for a
// screen reader (no arrows, "by" for dimensions, short lines).
#include <gtest/gtest.h>

#include <sstream>

#include "gen/key/places_in_words.h"
#include "gen/key/spoken_text.h"
#include "gen/key/unit_words.h"

namespace tsf {
namespace {

TEST(UnitWords, CommonUnitsSpelledOutTheFilesTextOtherwise) {
    struct Case {
        const char* units;
        const char* singular;
        const char* plural;
    };
    for (const Case& c : std::initializer_list<Case>{
             {"m", "metre", "metres"},
             {"degC", "degree Celsius", "degrees Celsius"},
             {"degree_C", "degree Celsius", "degrees Celsius"},
             {"K", "kelvin", "kelvin"},
             {"mm/day", "millimetre per day", "millimetres per day"},
             {"mm month-1", "millimetre per month", "millimetres per month"},
             {"kg m-2 s-1", "kilogram per square metre per second", "kilograms per square metre per second"},
             {"m s-1", "metre per second", "metres per second"},
             {"m^3/s", "cubic metre per second", "cubic metres per second"},
             {"m**2", "square metre", "square metres"},
             {"W m-2", "watt per square metre", "watts per square metre"},
             {"kW h", "kilowatt hour", "kilowatt hours"},
             {"%", "percent", "percent"},
             {"s-1", "per second", "per second"},
         }) {
        const UnitWords w = unitWords(c.units);
        EXPECT_TRUE(w.spelled) << c.units;
        EXPECT_EQ(w.singular, c.singular) << c.units;
        EXPECT_EQ(w.plural, c.plural) << c.units;
    }
    // Dimensionless and none: no words. Unknown terms: the text as given.
    EXPECT_EQ(unitWords("1").plural, "");
    EXPECT_EQ(unitWords("").plural, "");
    for (const char* kept : {"airports", "W/m^2/sr", "m-x", "0.001 m"}) {
        const UnitWords w = unitWords(kept);
        EXPECT_FALSE(w.spelled) << kept;
        EXPECT_EQ(w.plural, kept);
        EXPECT_EQ(w.singular, kept);
    }
}

TEST(PlacesInWords, BorderCornersRegionsAndScatter) {
    // A 10 x 8 grid, row 0 north.
    std::vector<std::pair<int32_t, int32_t>> ring;
    for (int c = 0; c < 10; ++c) ring.push_back({c, 0}), ring.push_back({c, 7});
    for (int r = 1; r < 7; ++r) ring.push_back({0, r}), ring.push_back({9, r});
    EXPECT_EQ(placesInWords(10, 8, ring), "around the border");
    std::vector<std::pair<int32_t, int32_t>> three_sides;
    for (const auto& p : ring)
        if (p.first != 9) three_sides.push_back(p);
    EXPECT_EQ(placesInWords(10, 8, three_sides), "along the north, south and west edges");
    EXPECT_EQ(placesInWords(10, 8, {{0, 0}}), "in the north-west corner");
    EXPECT_EQ(placesInWords(10, 8, {{9, 7}, {8, 6}}), "in the south-east corner");
    EXPECT_EQ(placesInWords(10, 8, {{5, 4}, {4, 3}, {5, 3}}), "in the centre");
    EXPECT_EQ(placesInWords(10, 8, {{5, 0}, {5, 1}, {4, 4}, {5, 4}}), "in the north and the centre");
    EXPECT_EQ(placesInWords(10, 8, {{0, 0}, {9, 0}, {0, 7}, {9, 7}, {5, 4}, {1, 4}}), "scattered across the model");
    EXPECT_EQ(placesInWords(10, 8, {}), "");
}

TEST(SpokenText, DimensionsByArrowsToAndShortLines) {
    EXPECT_EQ(spokenText("61 x 87 px -> 34 x 57 hexagons; gradient x 1; 419 mm^2; 5 mm^3"),
              "61 by 87 px to 34 by 57 hexagons; gradient x 1; 419 square mm; 5 cubic mm");
    // Clauses first, then a long clause's items; never inside an item.
    const std::string long_line = "  input     first clause of some length; " + std::string(30, 'a') + ", " +
                                  std::string(40, 'b') + ", " + std::string(20, 'c') + "; one item of words " +
                                  std::string(50, 'd') + "\nshort\n";
    const std::string wrapped = shortLines(long_line, 60, 12);
    EXPECT_EQ(wrapped, "  input     first clause of some length;\n"
                       "            " + std::string(30, 'a') + ",\n"
                       "            " + std::string(40, 'b') + ",\n"
                       "            " + std::string(20, 'c') + ";\n"
                       "            one item of words " + std::string(50, 'd') + "\nshort\n");
    EXPECT_EQ(wrapped.back(), '\n');
    std::string words;  // nothing lost
    for (char c : wrapped)
        if (c != ' ' && c != '\n') words += c;
    std::string want;
    for (char c : long_line)
        if (c != ' ' && c != '\n') want += c;
    EXPECT_EQ(words, want);
    // A place in brackets is one item: its two numbers stay on one line.
    const std::string place = "  legible   fails at 2 places ((76.0, 38.5) mm: " + std::string(40, 'e') +
                              ", over 12.8 square mm; (70.0, 41.5) mm: " + std::string(40, 'f') + ")\n";
    const std::string kept = shortLines(place, 60, 12);
    EXPECT_NE(kept.find("(76.0, 38.5) mm"), std::string::npos) << kept;
    EXPECT_NE(kept.find("(70.0, 41.5) mm"), std::string::npos) << kept;
}

}  // namespace
}  // namespace tsf
