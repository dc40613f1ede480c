#include "gen/readers/raster_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "png_test_writer.h"

namespace tsf {
namespace {

using test::sourcePath;
using test::writeScratch;

TEST(RasterReader, DetectsFormatByContentFirst) {
    test::PngSpec s;
    s.samples = {42};
    const std::string png = test::makePng(s);
    EXPECT_EQ(detectRasterFormat(png, "data.csv"), RasterFormat::Png);
    EXPECT_EQ(detectRasterFormat("P5 1 1 255\n*", "x.csv"), RasterFormat::Pgm);
    EXPECT_EQ(detectRasterFormat("P6 1 1 255\n***", "x"), RasterFormat::Pgm);  // named in the PGM error
    EXPECT_EQ(detectRasterFormat("\xEF\xBB\xBF  NCOLS 3\n", "x.txt"), RasterFormat::EsriAscii);
    EXPECT_EQ(detectRasterFormat("1,2\n", "x.asc"), RasterFormat::EsriAscii);  // extension when content says nothing
    EXPECT_EQ(detectRasterFormat("1,2\n", "x.PNG"), RasterFormat::Png);
    EXPECT_EQ(detectRasterFormat("1,2\n", "x.pgm"), RasterFormat::Pgm);
    EXPECT_EQ(detectRasterFormat("1,2\n", "x.txt"), RasterFormat::Csv);
    EXPECT_EQ(detectRasterFormat("P,2\n", "x.csv"), RasterFormat::Csv);

    const Raster r = readRaster(writeScratch("really_png.csv", png));
    EXPECT_EQ(r.kind, "png");
    EXPECT_EQ(r.at(0, 0), 42.0);
}

TEST(RasterReader, FormatAndDelimiterOptions) {
    const std::string path = writeScratch("semi.dat", "1;2\n3;4\n");
    RasterReadOptions opts;
    opts.delimiter = ';';
    EXPECT_EQ(readRaster(path, opts).at(1, 1), 4.0);
    opts.format = RasterFormat::EsriAscii;
    EXPECT_THROW(readRaster(path, opts), InputError);
    opts.delimiter = 'x';
    EXPECT_THROW(readRaster(path, opts), InputError);
    EXPECT_EQ(parseRasterFormat("ASC"), RasterFormat::EsriAscii);
    EXPECT_EQ(parseRasterFormat("png"), RasterFormat::Png);
    EXPECT_STREQ(rasterFormatName(RasterFormat::EsriAscii), "esri-ascii");
    EXPECT_EQ(parseRasterFormat("tiff"), RasterFormat::Gdal);
    EXPECT_THROW(parseRasterFormat("jpeg"), InputError);
}

TEST(RasterReader, MissingFileNamesThePath) {
    const InputError e = test::catchInputError([] { readRaster("/no/such/dir/field.csv"); });
    EXPECT_EQ(e.path(), "/no/such/dir/field.csv");
    EXPECT_NE(std::string(e.what()).find("/no/such/dir/field.csv"), std::string::npos);
}

// The example files: sizes and values known from their sources.
TEST(ExampleData, VolcanoCsvAndAscAreTheSameGrid) {
    const Raster csv = readRaster(sourcePath("examples/volcano.csv"));
    const Raster asc = readRaster(sourcePath("examples/volcano.asc"));
    ASSERT_EQ(csv.cols, 61);
    ASSERT_EQ(csv.rows, 87);
    EXPECT_EQ(asc.kind, "esri-ascii");
    EXPECT_EQ(asc.cell_size, 10.0);
    ASSERT_EQ(asc.cols, csv.cols);
    ASSERT_EQ(asc.rows, csv.rows);
    EXPECT_EQ(asc.values, csv.values);
    // R's volcano: heights 94..195 m. Corners (R's row i runs south to north,
    // column j east to west): [1,1] = 100 is the south-east corner here,
    // [87,61] = 94 north-west, [1,61] = 103 south-west, [87,1] = 97 north-east.
    EXPECT_EQ(*std::min_element(csv.values.begin(), csv.values.end()), 94.0);
    EXPECT_EQ(*std::max_element(csv.values.begin(), csv.values.end()), 195.0);
    EXPECT_EQ(csv.at(60, 86), 100.0);
    EXPECT_EQ(csv.at(0, 0), 94.0);
    EXPECT_EQ(csv.at(0, 86), 103.0);
    EXPECT_EQ(csv.at(60, 0), 97.0);
}

TEST(ExampleData, ThreeBumpsPgm) {
    const Raster r = readRaster(sourcePath("examples/three-bumps.pgm"));
    ASSERT_EQ(r.cols, 120);
    ASSERT_EQ(r.rows, 80);
    const auto top = std::max_element(r.values.begin(), r.values.end());
    const int64_t at = top - r.values.begin();
    // Highest bump centred at (32, 28) px: the pixels around that corner.
    EXPECT_NEAR(double(at % 120), 31.5, 0.5);
    EXPECT_NEAR(double(at / 120), 27.5, 0.5);
    EXPECT_GT(*top, 59000.0);
    EXPECT_LE(*top, 60000.0);
    EXPECT_EQ(r.at(0, 79), 0.0);  // far from every bump
}

}  // namespace
}  // namespace tsf
