// Grid CSV as spreadsheets and pandas write it: no-data placeholders, decimal
// commas with semicolons, a row-index column, and the facts tsf reports.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "gen/readers/csv_grid_reader.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

TEST(CsvDialect, PlaceholdersAreNoData) {
    const Raster r = parseCsvGrid("1,N/A,3\nNA,-,n/a\n", "p.csv");
    ASSERT_EQ(r.cols, 3);
    EXPECT_EQ(r.at(0, 0), 1.0);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    EXPECT_TRUE(std::isnan(r.at(0, 1)));
    EXPECT_TRUE(std::isnan(r.at(1, 1)));
    EXPECT_TRUE(std::isnan(r.at(2, 1)));
    // A minus sign is only no data alone: "-2" is a number, "--" is not one.
    EXPECT_EQ(parseCsvGrid("-2,1\n", "p.csv").at(0, 0), -2.0);
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,--\n", "p.csv"), 1, 3, "found \"--\"");
}

TEST(CsvDialect, DecimalCommaWithSemicolonsIsDetected) {
    const Raster r = parseCsvGrid("1,5;2;-3,25\n4;5,5;6\n", "de.csv");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.at(0, 0), 1.5);
    EXPECT_EQ(r.at(2, 0), -3.25);
    EXPECT_EQ(r.at(1, 1), 5.5);
    EXPECT_EQ(r.fact("delimiter"), "semicolon (detected)");
    EXPECT_EQ(r.fact("decimal mark"), "comma (detected)");
    // A header above decimal-comma values is still a header; the values are not one.
    const Raster h = parseCsvGrid("a;b\n1,5;2,5\n", "de.csv");
    EXPECT_EQ(h.rows, 1);
    EXPECT_EQ(h.at(1, 0), 2.5);
    const Raster first_row_values = parseCsvGrid("1,5;2,5\n3;4\n", "de.csv");
    EXPECT_EQ(first_row_values.rows, 2);
    EXPECT_EQ(first_row_values.fact("header"), "");
}

TEST(CsvDialect, DecimalCommaGivenAndItsMistakes) {
    // Given: a one-column file whose commas would otherwise be the delimiter.
    const Raster one = parseCsvGrid("1,5\n2,5\n", "c.csv", 0, DecimalMark::Comma);
    ASSERT_EQ(one.cols, 1);
    EXPECT_EQ(one.at(0, 1), 2.5);
    EXPECT_EQ(one.fact("decimal mark"), "comma");
    // Thousands separators are refused, not misread.
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,5;2\n1.234,5;3\n", "c.csv"), 2, 1, "decimal point in a table read with decimal commas");
    EXPECT_INPUT_ERROR(parseCsvGrid("1;2\n", "c.csv", ',', DecimalMark::Comma), "needs another delimiter");
    // Comma-separated files keep the decimal point.
    const Raster plain = parseCsvGrid("1,5\n2,5\n", "c.csv");
    EXPECT_EQ(plain.cols, 2);
    EXPECT_EQ(plain.fact("decimal mark"), "");
}

TEST(CsvDialect, DecimalCommasBetweenBlanksAreAWhitespaceGrid) {
    // "1,5 2,5 3,5": blanks separate the values, commas are decimal marks.
    const Raster r = parseCsvGrid("1,5 2,5 3,5\n4 5,25 -6,5\n", "ws.csv");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.at(0, 0), 1.5);
    EXPECT_EQ(r.at(1, 1), 5.25);
    EXPECT_EQ(r.at(2, 1), -6.5);
    EXPECT_EQ(r.fact("delimiter"), "whitespace (detected)");
    EXPECT_EQ(r.fact("decimal mark"), "comma (detected)");
    // A comma followed by a blank is a delimiter, as it always was.
    const Raster c = parseCsvGrid("1, 2, 3\n4, 5, 6\n", "c.csv");
    EXPECT_EQ(c.cols, 3);
    EXPECT_EQ(c.fact("delimiter"), "comma (detected)");
}

TEST(CsvDialect, DecimalCommaOnACommaSeparatedFileIsRefusedNotAHeader) {
    EXPECT_INPUT_ERROR(parseCsvGrid("1,2,3\n4,5,6\n", "c.csv", 0, DecimalMark::Comma),
                       "--decimal-comma: the values are separated by commas");
}

TEST(CsvDialect, PandasIndexColumnIsDropped) {
    // DataFrame.to_csv(): an empty corner cell, column names 0..n-1, row labels first.
    const Raster r = parseCsvGrid(",0,1,2\n0,1.5,2,3\n1,4,5,6\n", "pd.csv");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.at(0, 0), 1.5);
    EXPECT_EQ(r.at(2, 1), 6.0);
    EXPECT_EQ(r.fact("header"), "line 1 skipped");
    EXPECT_NE(r.fact("index column"), "");
    // Text column names and text row labels ("2020-01-01") too.
    const Raster t = parseCsvGrid(",a,b\n2020-01-01,1,2\n2020-01-02,3,4\n", "pd.csv");
    ASSERT_EQ(t.cols, 2);
    EXPECT_EQ(t.at(1, 1), 4.0);
    // An empty first cell above numbers that do not count 0, 1, 2 is a no-data value.
    const Raster nd = parseCsvGrid(",5,7\n1,2,3\n", "nd.csv");
    ASSERT_EQ(nd.cols, 3);
    ASSERT_EQ(nd.rows, 2);
    EXPECT_TRUE(std::isnan(nd.at(0, 0)));
}

TEST(CsvDialect, AnIndexWithoutHeaderIsNamedWithTheFix) {
    const Raster r = parseCsvGrid("0,5,6\n1,7,8\n2,9,9\n", "ix.csv");
    EXPECT_EQ(r.cols, 3) << "kept: it cannot be told from data";
    EXPECT_NE(r.fact("note").find("index=False"), std::string::npos);
    EXPECT_EQ(parseCsvGrid("0,5,6\n3,7,8\n2,9,9\n", "ix.csv").fact("note"), "");
}

}  // namespace
}  // namespace tsf
