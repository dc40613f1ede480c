#include "gen/readers/point_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

PointColumns byName(const std::string& x, const std::string& y, const std::string& w = "") {
    PointColumns c;
    c.x.name = x;
    c.y.name = y;
    c.weight.name = w;
    return c;
}

PointColumns byIndex(int x, int y, int w = -1) {
    PointColumns c;
    c.x.index = x;
    c.y.index = y;
    c.weight.index = w;
    return c;
}

TEST(PointReader, ColumnsByNameWithQuotedTextColumns) {
    const std::string text =
        "name,iata,lon,lat\n"
        "\"Harstad/Narvik Airport, Evenes\",EVE,16.678101,68.491302\n"
        "\"Magdeburg \"\"City\"\" Airport\",,11.626389,52.073612\n";
    const PointTable t = parsePointsCsv(text, "a.csv", byName("lon", "lat"));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_EQ(t.x[0], 16.678101);
    EXPECT_EQ(t.y[0], 68.491302);
    EXPECT_EQ(t.x[1], 11.626389);
    EXPECT_EQ(t.x_name, "lon");
    EXPECT_EQ(t.y_name, "lat");
    EXPECT_FALSE(t.hasWeight());
}

TEST(PointReader, ColumnsByIndexWithAndWithoutHeader) {
    const PointTable with = parsePointsCsv("a;b;c\n1;2;3\n4;5;6\n", "p.csv", byIndex(2, 0));
    ASSERT_EQ(with.size(), 2u);
    EXPECT_EQ(with.x[0], 3.0);
    EXPECT_EQ(with.y[1], 4.0);
    EXPECT_EQ(with.x_name, "c");
    const PointTable without = parsePointsCsv("1 2\n3 4\n", "p.txt", byIndex(0, 1));
    ASSERT_EQ(without.size(), 2u);
    EXPECT_EQ(without.y[1], 4.0);
    EXPECT_EQ(without.x_name, "column 0");
}

TEST(PointReader, WeightsAndMissingWeights) {
    const PointTable t = parsePointsCsv("x,y,w\n0,0,2.5\n1,1,\n2,2,NA\n3,3,-1\n", "w.csv", byName("x", "y", "w"));
    ASSERT_EQ(t.weight.size(), 4u);
    EXPECT_EQ(t.weight[0], 2.5);
    EXPECT_TRUE(std::isnan(t.weight[1]));
    EXPECT_TRUE(std::isnan(t.weight[2]));
    EXPECT_EQ(t.weight[3], -1.0);
    EXPECT_EQ(t.missing_weights, 2);
    EXPECT_EQ(t.weight_name, "w");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("x,y,w\n0,0,heavy\n", "w.csv", byName("x", "y", "w")), 2, 5,
                          "weight (w): expected a number, found \"heavy\"");
}

TEST(PointReader, BadCoordinateNamesLineAndCharacterColumn) {
    // "Zürich" is 6 characters (7 bytes): "abc" starts at character 12.
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("name,x,y\nBern,7.4,46.9\nZürich,8.5,abc\n", "z.csv", byName("x", "y")), 3,
                          12, "y (y): expected a number, found \"abc\"");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("x,y\n1,2\n,3\n", "z.csv", byName("x", "y")), 3, 1,
                          "x (x) is empty; every point needs a position");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("x,y\n1,NaN\n", "z.csv", byName("x", "y")), 2, 3, "is \"NaN\"");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("x,y\n1,-inf\n", "z.csv", byName("x", "y")), 2, 3, "infinite");
}

TEST(PointReader, MissingColumnsAndFields) {
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("lon,lat\n1,2\n", "m.csv", byName("x", "lat")), 1, 0,
                          "no column named \"x\" for x in the header line; it has: \"lon\", \"lat\"");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("lon,lat,name\n1,2,a\n3\n", "m.csv", byName("lon", "lat")), 3, 0,
                          "line has 1 fields; y ('lat', index 1) is missing");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("1,2\n", "m.csv", byIndex(0, 5)), 1, 0, "y (column 5) is missing");
}

TEST(PointReader, EmptyAndHeaderOnlyFiles) {
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("", "e.csv", byIndex(0, 1)), 0, 0, "is empty");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("\r\n\r\n", "e.csv", byIndex(0, 1)), 0, 0, "is empty");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("lon,lat\n\n", "e.csv", byName("lon", "lat")), 1, 0, "no data lines");
    EXPECT_INPUT_ERROR_AT(parsePointsCsv("lon,lat\n", "e.csv", byIndex(0, 1)), 1, 0, "no data lines");
}

TEST(PointReader, ParsesColumnSpecs) {
    const PointColumns a = parsePointColumns("x=lon, y=lat, w=passengers");
    EXPECT_EQ(a.x.name, "lon");
    EXPECT_EQ(a.y.name, "lat");
    EXPECT_EQ(a.weight.name, "passengers");
    const PointColumns b = parsePointColumns("y=1,x=0");
    EXPECT_EQ(b.x.index, 0);
    EXPECT_EQ(b.y.index, 1);
    EXPECT_FALSE(b.weight.isSet());
    EXPECT_THROW(parsePointColumns("x=lon"), InputError);
    EXPECT_THROW(parsePointColumns("x=lon,y=lat,z=h"), InputError);
    EXPECT_THROW(parsePointColumns("x=lon,x=a,y=lat"), InputError);
    EXPECT_THROW(parsePointColumns("x=,y=lat"), InputError);
    EXPECT_THROW(parsePointColumns("lon,lat"), InputError);
}

TEST(PointReader, ReadsTheAirportExample) {
    const std::string path = test::sourcePath("examples/airports-europe.csv");
    const PointTable t = readPointsCsv(path, parsePointColumns("x=lon,y=lat"));
    // Independent count: lines of the file minus the header.
    std::ifstream in(path);
    int64_t lines = 0;
    for (std::string line; std::getline(in, line);) ++lines;
    EXPECT_EQ(int64_t(t.size()), lines - 1);
    EXPECT_GT(t.size(), 1000u);
    for (size_t k = 0; k < t.size(); ++k) {
        ASSERT_GE(t.x[k], -32.0);
        ASSERT_LE(t.x[k], 60.0);
        ASSERT_GE(t.y[k], 27.0);
        ASSERT_LE(t.y[k], 82.0);
    }
}

}  // namespace
}  // namespace tsf
