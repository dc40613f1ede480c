#include "gen/readers/csv_grid_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "gen/readers/csv_tokenizer.h"
#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

using test::writeScratch;

TEST(CsvGridReader, CommaGridKeepsRowOrderAndValues) {
    // Row 0 of the raster is the first line (north).
    const Raster r = parseCsvGrid("1,2,3\n4,5,6\n", "g.csv");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.kind, "csv");
    EXPECT_EQ(r.source, "g.csv");
    EXPECT_EQ(r.cell_size, 1.0);
    EXPECT_EQ(r.at(0, 0), 1.0);
    EXPECT_EQ(r.at(2, 0), 3.0);
    EXPECT_EQ(r.at(0, 1), 4.0);
    EXPECT_EQ(r.at(2, 1), 6.0);
}

TEST(CsvGridReader, NumberSpellings) {
    const Raster r = parseCsvGrid("-1.5e3,+2,.5,5.,0007,1e-400\n", "g.csv");
    ASSERT_EQ(r.cols, 6);
    EXPECT_EQ(r.at(0, 0), -1500.0);
    EXPECT_EQ(r.at(1, 0), 2.0);
    EXPECT_EQ(r.at(2, 0), 0.5);
    EXPECT_EQ(r.at(3, 0), 5.0);
    EXPECT_EQ(r.at(4, 0), 7.0);
    EXPECT_EQ(r.at(5, 0), 0.0);  // underflow is zero, not an error
}

TEST(CsvGridReader, DetectsSemicolonTabAndWhitespace) {
    const Raster semi = parseCsvGrid("1.5;2.5\n3;4\n", "s.csv");
    EXPECT_EQ(semi.cols, 2);
    EXPECT_EQ(semi.at(1, 0), 2.5);
    const Raster tab = parseCsvGrid("1\t2\t3\n4\t5\t6\n", "t.tsv");
    EXPECT_EQ(tab.cols, 3);
    EXPECT_EQ(tab.at(2, 1), 6.0);
    // Runs of blanks, leading blanks and trailing blanks: no empty fields.
    const Raster ws = parseCsvGrid("  1   2 \t 3\n4 5 6   \n", "w.txt");
    ASSERT_EQ(ws.cols, 3);
    ASSERT_EQ(ws.rows, 2);
    EXPECT_EQ(ws.at(2, 0), 3.0);
    EXPECT_EQ(ws.at(0, 1), 4.0);
    // Tab-separated with blanks inside header names: still tab-separated.
    const Raster named = parseCsvGrid("mean temp\tmax temp\n1\t2\n", "t.tsv");
    EXPECT_EQ(named.cols, 2);
    EXPECT_EQ(named.rows, 1);
    EXPECT_EQ(detectCsvDelimiter("\n\n1;2,5\n"), ';');
    EXPECT_EQ(detectCsvDelimiter("\"a;b\",c\n"), ',');  // ';' inside quotes does not count
}

TEST(CsvGridReader, ExplicitDelimiterOverridesDetection) {
    // Detection would pick ';' here; with ',' forced the fields are "1;2" and "3".
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1;2,3\n", "g.csv", ','), 1, 1, "\"1;2\"");
    const Raster r = parseCsvGrid("1 2\n3 4\n", "g.csv", ' ');
    EXPECT_EQ(r.cols, 2);
    EXPECT_THROW(parseCsvGrid("1|2\n", "g.csv", '|'), InputError);
}

TEST(CsvGridReader, HeaderRowIsSkipped) {
    const Raster r = parseCsvGrid("west,middle,east\n1,2,3\n", "h.csv");
    EXPECT_EQ(r.rows, 1);
    EXPECT_EQ(r.cols, 3);
    EXPECT_EQ(r.at(0, 0), 1.0);
    // A first line of no-data values is data, not a header.
    const Raster nan_first = parseCsvGrid("NA,nan\n1,2\n", "h.csv");
    EXPECT_EQ(nan_first.rows, 2);
    EXPECT_TRUE(std::isnan(nan_first.at(0, 0)));
}

TEST(CsvGridReader, NoDataSpellingsBecomeNaN) {
    const Raster r = parseCsvGrid("1,,3\nNaN,NA,nan\n\"\",na,7\n", "n.csv");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 3);
    EXPECT_EQ(r.at(0, 0), 1.0);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    EXPECT_TRUE(std::isnan(r.at(0, 1)));
    EXPECT_TRUE(std::isnan(r.at(1, 1)));
    EXPECT_TRUE(std::isnan(r.at(2, 1)));
    EXPECT_TRUE(std::isnan(r.at(0, 2)));
    EXPECT_TRUE(std::isnan(r.at(1, 2)));
    EXPECT_EQ(r.at(2, 2), 7.0);
}

TEST(CsvGridReader, QuotedFieldsCrlfBomAndBlankLines) {
    const std::string text = "\xEF\xBB\xBF\"a,1\",\"b \"\"2\"\"\"\r\n\r\n\"1.5\", 2 \r\n3,\"4\"\r\n\r\n";
    const Raster r = parseCsvGrid(text, "q.csv");
    ASSERT_EQ(r.cols, 2);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.at(0, 0), 1.5);
    EXPECT_EQ(r.at(1, 0), 2.0);
    EXPECT_EQ(r.at(1, 1), 4.0);
    // No newline at the end, lone CR line ends.
    const Raster cr = parseCsvGrid("1,2\r3,4", "cr.csv");
    EXPECT_EQ(cr.rows, 2);
    EXPECT_EQ(cr.at(1, 1), 4.0);
}

TEST(CsvGridReader, TrailingDelimiterOnEveryLineAddsNoColumn) {
    const Raster r = parseCsvGrid("1,2,\n3,4,\n", "t.csv");
    EXPECT_EQ(r.cols, 2);
    EXPECT_EQ(r.rows, 2);
    EXPECT_EQ(r.at(1, 1), 4.0);
    // Only some lines: the empty field is real no data.
    const Raster some = parseCsvGrid("1,2,\n3,4,5\n", "t.csv");
    EXPECT_EQ(some.cols, 3);
    EXPECT_TRUE(std::isnan(some.at(2, 0)));
}

TEST(CsvGridReader, RaggedRowNamesLineAndCounts) {
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2,3\n4,5\n", "r.csv"), 2, 0, "has 2 comma-separated fields, expected 3");
    // Too many: the column of the first extra field.
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2\n\n3,4,55\n", "r.csv"), 3, 5, "has 3 comma-separated fields, expected 2");
    // Columns count characters, not bytes: "é" is one character (two bytes).
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("a,b\n1,2\né,2,3\n", "r.csv"), 3, 5, "has 3");
    // A header fixes the count too.
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("a,b,c\n1,2\n", "r.csv"), 2, 0, "expected 3 like line 1");
}

TEST(CsvGridReader, BadNumberNamesLineColumnAndText) {
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2,3\n4,abc,6\n", "b.csv"), 2, 3, "found \"abc\"");
    // Column of the field's first non-blank character.
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2,3\n4,  7x,6\n", "b.csv"), 2, 5, "found \"7x\"");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2\n\"é\",2\n", "b.csv"), 2, 1, "found \"é\"");
    // Once a decimal point has been seen, a decimal comma is a mistake (decimal_mark.h).
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1.5;2\n3;1,5\n", "b.csv"), 2, 3, "decimal comma? write 1.5");
    // Other readers' sloppiness is not accepted: thousands separators, units.
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2\n1 000,3\n", "b.csv", ','), 2, 1, "found \"1 000\"");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1\n12m\n", "b.csv"), 2, 1, "\"12m\"");
    // A first line without any number is a header, so a lone bad first line reads as "no data".
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("12m\n", "b.csv"), 1, 0, "no data lines");
}

TEST(CsvGridReader, InfinityIsAnError) {
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,inf\n", "i.csv"), 1, 3, "infinite");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2\n-Infinity,3\n", "i.csv"), 2, 1, "infinite");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,1e999\n", "i.csv"), 1, 3, "\"1e999\"");
}

TEST(CsvGridReader, UnterminatedQuoteAndTextAfterQuote) {
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,2\n3,\"4\n", "u.csv"), 2, 3, "never closed");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("1,\"2\"x\n", "u.csv"), 1, 6, "after the closing quote");
}

TEST(CsvGridReader, EmptyAndHeaderOnlyFiles) {
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("", "e.csv"), 0, 0, "empty");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("\n \n\r\n", "e.csv"), 0, 0, "empty");
    EXPECT_INPUT_ERROR_AT(parseCsvGrid("\na,b,c\n", "e.csv"), 2, 0, "no data lines");
}

TEST(CsvGridReader, TooManyColumnsIsRejectedBeforeReadingOn) {
    std::string line;
    for (int k = 0; k < 20001; ++k) line += "0,";
    line += "0\n";
    EXPECT_INPUT_ERROR_AT(parseCsvGrid(line, "big.csv"), 1, 0, "largest side");
}

TEST(CsvGridReader, ReadsFromFileAndReportsMissingFile) {
    const std::string path = writeScratch("grid_read.csv", "1,2\n3,4\n");
    const Raster r = readCsvGrid(path);
    EXPECT_EQ(r.source, path);
    EXPECT_EQ(r.at(1, 1), 4.0);
    const InputError e = test::catchInputError([] { readCsvGrid("/nonexistent/tsf/grid.csv"); });
    EXPECT_EQ(e.path(), "/nonexistent/tsf/grid.csv");
    EXPECT_NE(e.detail().find("not found"), std::string::npos);
    const InputError d = test::catchInputError([] { readCsvGrid(TSF_TEST_SCRATCH); });
    EXPECT_NE(d.detail().find("folder"), std::string::npos);
}

}  // namespace
}  // namespace tsf
