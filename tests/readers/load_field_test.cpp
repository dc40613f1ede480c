// loadField: the library entry point that turns any input file into a
// HexField, the same for rasters and points as `tsf gen` (no command line).
#include "gen/readers/load_field.h"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

TEST(LoadField, ARasterIsResampledOntoHexagons) {
    FieldLoadOptions in;
    in.input = test::writeScratch("load_raster.csv", "1,2,3\n4,5,6\n");
    const HexField f = loadField(in);
    EXPECT_EQ(f.source, in.input);
    EXPECT_GT(f.grid.cellCount(), 0);
    EXPECT_EQ(int64_t(f.values.size()), f.grid.cellCount());
}

TEST(LoadField, PointsAreBinnedIntoHexagons) {
    FieldLoadOptions in;
    in.input = test::writeScratch("load_points.csv", "x,y\n0,0\n1,0\n0,1\n1,1\n0.5,0.5\n");
    in.points = "x=x,y=y";
    in.bins = 4;
    const HexField f = loadField(in);
    EXPECT_EQ(f.source, in.input);
    double total = 0;
    for (double v : f.values)
        if (!std::isnan(v)) total += v;
    EXPECT_EQ(total, 5.0) << "every point counted once";
}

TEST(LoadField, BadOptionsAreInputErrors) {
    FieldLoadOptions in;
    in.input = test::writeScratch("load_bad.csv", "1,2\n3,4\n");
    in.delimiter = "|";
    EXPECT_INPUT_ERROR_AT(loadField(in), 0, 0, "--delimiter");
    in.delimiter = "";
    in.sample = "cubic";
    EXPECT_THROW(loadField(in), InputError);
    FieldLoadOptions missing;
    missing.input = test::writeScratch("load_missing.csv", "") + ".absent";
    EXPECT_THROW(loadField(missing), InputError);
}

}  // namespace
}  // namespace tsf
