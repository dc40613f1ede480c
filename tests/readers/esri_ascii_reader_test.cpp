#include "gen/readers/esri_ascii_reader.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

const char* kGrid =
    "ncols        3\n"
    "nrows        2\n"
    "xllcorner    1000.5\n"
    "yllcorner    -20\n"
    "cellsize     25\n"
    "NODATA_value -9999\n"
    "1 2 3\n"
    "4 -9999 6.5\n";

TEST(EsriAsciiReader, HeaderValuesAndNoData) {
    const Raster r = parseEsriAscii(kGrid, "g.asc");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.kind, "esri-ascii");
    EXPECT_EQ(r.cell_size, 25.0);
    EXPECT_EQ(r.x_origin, 1000.5);
    EXPECT_EQ(r.y_origin, -20.0);
    EXPECT_EQ(r.at(0, 0), 1.0);  // first data line = north row
    EXPECT_EQ(r.at(2, 0), 3.0);
    EXPECT_EQ(r.at(0, 1), 4.0);
    EXPECT_TRUE(std::isnan(r.at(1, 1)));
    EXPECT_EQ(r.at(2, 1), 6.5);
}

TEST(EsriAsciiReader, CentreKeysAnyOrderAnyCaseAndCrlf) {
    const Raster r = parseEsriAscii(
        "\xEF\xBB\xBFNROWS 1\r\nCellSize 2\r\nYLLCENTER 11\r\nncols 2\r\nxllcenter 5\r\n7 8\r\n", "c.asc");
    EXPECT_EQ(r.cols, 2);
    EXPECT_EQ(r.rows, 1);
    EXPECT_EQ(r.cell_size, 2.0);
    EXPECT_EQ(r.x_origin, 4.0);   // centre 5 minus half a cell
    EXPECT_EQ(r.y_origin, 10.0);
    EXPECT_EQ(r.at(1, 0), 8.0);
}

TEST(EsriAsciiReader, SquareDxDyAndNanNoData) {
    const Raster r = parseEsriAscii(
        "ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ndx 0.5\ndy 0.5\nNODATA_value nan\nnan 3\n", "d.asc");
    EXPECT_EQ(r.cell_size, 0.5);
    EXPECT_TRUE(std::isnan(r.at(0, 0)));
    EXPECT_EQ(r.at(1, 0), 3.0);
    EXPECT_INPUT_ERROR_AT(
        parseEsriAscii("ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ndx 1\ndy 2\n5\n", "d.asc"), 6, 0,
        "not square");
}

TEST(EsriAsciiReader, FreeFlowValuesWhenLinesAreWrapped) {
    // First data line does not hold ncols values: values may wrap anywhere.
    const Raster r = parseEsriAscii(
        "ncols 4\nnrows 2\nxllcorner 0\nyllcorner 0\ncellsize 1\n1 2 3\n4 5 6\n7 8\n", "w.asc");
    EXPECT_EQ(r.at(3, 0), 4.0);
    EXPECT_EQ(r.at(0, 1), 5.0);
    EXPECT_EQ(r.at(3, 1), 8.0);
}

TEST(EsriAsciiReader, WrongValueCountsNameTheLine) {
    const std::string head = "ncols 3\nnrows 3\nxllcorner 0\nyllcorner 0\ncellsize 1\n";  // data starts on line 6
    // A short line inside a row-structured grid.
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 2 3\n4 5\n6 7 8\n", "n.asc"), 7, 0, "line has 2 values, expected ncols = 3");
    // A long line.
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 2 3\n4 5 6 0\n7 8 9\n", "n.asc"), 7, 0, "line has 4 values");
    // A missing row: reported at the last data line.
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 2 3\n4 5 6\n", "n.asc"), 7, 0, "too few values: expected ncols x nrows = 3 x 3 = 9, found 6");
    // An extra row: the first extra value.
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 2 3\n4 5 6\n7 8 9\n  10 11 12\n", "n.asc"), 9, 3, "more values than");
    // No values at all.
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head, "n.asc"), 5, 0, "too few values");
}

TEST(EsriAsciiReader, HeaderErrors) {
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\n1 2\n", "h.asc"), 5, 0, "no cellsize");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 2\nnrows 1\nxllcorner 0\ncellsize 1\n1 2\n", "h.asc"), 5, 0, "yllcorner or yllcenter");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\nbanana 3\n1 2\n", "h.asc"), 6, 1, "unknown ESRI grid header key \"banana\"");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 2\nNCOLS 2\n", "h.asc"), 2, 1, "given twice (first on line 1)");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 2.5\n", "h.asc"), 1, 7, "ncols must be a whole number");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 1\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize -1\n1\n", "h.asc"), 5, 10, "greater than 0");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 1\nnrows 1\nxllcorner x\n", "h.asc"), 3, 11, "xllcorner: expected a number");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 0\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n", "h.asc"), 2, 0, "at least 1 x 1");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("ncols 30000\nnrows 30000\nxllcorner 0\nyllcorner 0\ncellsize 1\n1\n", "h.asc"), 2, 0, "largest side");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii("", "h.asc"), 0, 0, "empty");
}

TEST(EsriAsciiReader, BadValues) {
    const std::string head = "ncols 2\nnrows 1\nxllcorner 0\nyllcorner 0\ncellsize 1\n";
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 x2\n", "v.asc"), 6, 3, "found \"x2\"");
    EXPECT_INPUT_ERROR_AT(parseEsriAscii(head + "1 1e999\n", "v.asc"), 6, 3, "infinite");
}

TEST(EsriAsciiReader, ReadsFromFile) {
    const std::string path = test::writeScratch("read.asc", kGrid);
    const Raster r = readEsriAscii(path);
    EXPECT_EQ(r.source, path);
    EXPECT_EQ(r.at(2, 1), 6.5);
}

}  // namespace
}  // namespace tsf
