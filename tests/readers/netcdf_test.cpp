// NetCDF through GDAL: a file of two variables is read by --variable (or by
// GDAL's own name of the variable), a band is a time step with its date
// decoded from CF metadata, the fill value is no data, packed values are
// unpacked, the units are read; tsf gen makes one pillar per value of the
// step asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gen/readers/gdal_reader.h"
#include "gen/readers/netcdf_classic_size.h"
#include "gen/readers/raster_reader.h"
#include "gen/util/error.h"
#include "tests/readers/netcdf_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

std::string fact(const Raster& r, const std::string& key) {
    for (const ReadFact& f : r.facts)
        if (f.name == key) return f.value;
    return "";
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

/// The test's own file (tests run in parallel, each in its own folder).
std::string climateFile() {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "climate.nc").string();
    EXPECT_TRUE(test::writeNetCdf(path)) << "GDAL's netCDF driver (Debian libgdal32 has it)";
    return path;
}

TEST(NetCdf, AFileOfSeveralVariablesAsksWhichAndListsThem) {
    const std::string path = climateFile();
    const InputError e = test::catchInputError([&] { readRaster(path); });
    EXPECT_TRUE(has(e.what(), "holds 2 variables")) << e.what();
    EXPECT_TRUE(has(e.what(), "pr ")) << e.what();
    EXPECT_TRUE(has(e.what(), "tas ")) << e.what();
    EXPECT_TRUE(has(e.what(), "--variable NAME")) << e.what();
    RasterReadOptions o;
    o.variable = "rain";
    const InputError none = test::catchInputError([&] { readRaster(path, o); });
    EXPECT_TRUE(has(none.what(), "has no variable 'rain'")) << none.what();
}

// Step 3 of pr: every value where it was written (row 0 is the north: the
// file's latitudes ascend, GDAL turns them north-up), the fill value no
// data, the date of the step, the units.
TEST(NetCdf, AVariableAndATimeStepAreReadValueForValue) {
    const std::string path = climateFile();
    RasterReadOptions o;
    o.variable = "pr";
    o.band = 3;
    for (const std::string& name : {path, "NETCDF:\"" + path + "\":pr"}) {
        const Raster r = readRaster(name, name == path ? o : RasterReadOptions{.band = 3});
        ASSERT_EQ(r.cols, 5);
        ASSERT_EQ(r.rows, 4);
        for (int row = 0; row < 4; ++row)
            for (int col = 0; col < 5; ++col) {
                const int lat = 3 - row;
                if (lat == 0 && col == 0) EXPECT_TRUE(std::isnan(r.at(col, row))) << "the fill value is no data";
                else EXPECT_DOUBLE_EQ(r.at(col, row), test::netcdfPr(2, lat, col)) << name << " " << col << "," << row;
            }
        EXPECT_EQ(r.units, "mm/day");
        EXPECT_TRUE(has(fact(r, "band"), "3 of 3: time = 60 days since 2000-01-01 (2000-03-01)")) << fact(r, "band");
        EXPECT_EQ(fact(r, "bands"), "1: 2000-01-01; 2: 2000-02-01; 3: 2000-03-01");  // every step, to choose from
        if (name == path) EXPECT_TRUE(has(fact(r, "variable"), "pr")) << fact(r, "variable");
    }
}

TEST(NetCdf, PackedValuesAreUnpacked) {
    const std::string path = climateFile();
    RasterReadOptions o;
    o.variable = "tas";
    o.band = 2;
    const Raster r = readRaster(path, o);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 5; ++col) EXPECT_DOUBLE_EQ(r.at(col, row), test::netcdfTas(1, 3 - row, col));
    EXPECT_TRUE(has(fact(r, "packed"), "x 0.5 + 200")) << fact(r, "packed");
    EXPECT_EQ(r.units, "K");
    EXPECT_TRUE(has(fact(r, "band"), "(2000-02-01)")) << fact(r, "band");
}

TEST(NetCdf, GdalDatasetNamesAreNotFileNames) {
    EXPECT_TRUE(isGdalDatasetName("NETCDF:\"a.nc\":pr"));
    EXPECT_TRUE(isGdalDatasetName("HDF5:/data/f.h5://group/x"));
    EXPECT_TRUE(isGdalDatasetName("GPKG:tiles.gpkg:dem"));
    EXPECT_FALSE(isGdalDatasetName("C:\\\\data\\\\a.tif"));
    EXPECT_FALSE(isGdalDatasetName("data/a.tif"));
    EXPECT_FALSE(isGdalDatasetName("odd:name.csv"));
}

// tsf gen: --variable pr --band 3 with cells small enough is one pillar per
// value of step 3, the fill cell a pit; the same through GDAL's name; tsf
// info lists the variable and the step.
TEST(NetCdf, GenMakesOnePillarPerValueOfTheStep) {
    const std::string path = climateFile();
    const auto dir = std::filesystem::path(path).parent_path();
    for (const std::string& input : {path + " --variable pr", "'NETCDF:\"" + path + "\":pr'"}) {
        const test::RunResult r =
            test::runTsf("gen " + input + " --band 3 --cell 5 --json -o " + (dir / "pr.stl").string(), dir);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const auto j = nlohmann::json::parse(r.out);
        EXPECT_TRUE(j["scene"]["one_pillar_per_value"].get<bool>()) << r.out;
        EXPECT_EQ(j["scene"]["cells"]["with_data"].get<int>(), 19);  // 20 less the fill cell
        EXPECT_TRUE(j["verify"]["passed"].get<bool>());
    }
    const test::RunResult info = test::runTsf("info " + path + " --variable tas --band 2", dir);
    ASSERT_EQ(info.exit_code, 0) << info.output;
    EXPECT_TRUE(has(info.out, "tas")) << info.out;
    EXPECT_TRUE(has(info.out, "2000-02-01")) << info.out;
    const test::RunResult bad = test::runTsf("gen " + path + " -o " + (dir / "x.stl").string(), dir);
    EXPECT_EQ(bad.exit_code, 2);
    EXPECT_TRUE(has(bad.err, "--variable NAME")) << bad.err;
}

// --band 1-3: three models on one scale (the same floor value and value at
// full height, from every step's values), each file named by its band, the
// legend naming the step where the title says {band}; --band 1,3 a list.
TEST(NetCdf, ABandSeriesIsOneModelPerStepOnOneScale) {
    const std::string path = climateFile();
    const auto dir = std::filesystem::path(path).parent_path();
    const test::RunResult r = test::runTsf(
        "gen " + path + " --variable pr --band 1-3 --title '{band}' --cell 20 --json -o " + (dir / "pr.stl").string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.out);
    ASSERT_EQ(j["series"].size(), 3u);
    EXPECT_DOUBLE_EQ(j["common_scale"]["value_max"].get<double>(), test::netcdfPr(2, 3, 4));  // the largest of all steps
    EXPECT_DOUBLE_EQ(j["common_scale"]["baseline"].get<double>(), 0.0);
    const char* dates[3] = {"2000-01-01", "2000-02-01", "2000-03-01"};
    for (int k = 0; k < 3; ++k) {
        const auto& m = j["series"][size_t(k)];
        EXPECT_EQ(m["band"], k + 1);
        EXPECT_EQ(m["label"], dates[k]);
        EXPECT_DOUBLE_EQ(m["model"]["scene"]["mapping"]["value_max"].get<double>(), test::netcdfPr(2, 3, 4));
        EXPECT_TRUE(m["model"]["verify"]["passed"].get<bool>());
        const std::string stem = (dir / ("pr-band-" + std::to_string(k + 1))).string();
        EXPECT_TRUE(std::filesystem::exists(stem + ".stl"));
        EXPECT_TRUE(has(test::readText(stem + ".key.txt"), std::string("\n") + dates[k] + "\n")) << "the legend's title";
    }
    // A list (names are zero-padded when the last band needs more digits).
    EXPECT_EQ(test::runTsf("gen " + path + " --variable pr --band 1,3 --cell 20 -o " + (dir / "two.stl").string(), dir).exit_code, 0);
    EXPECT_TRUE(std::filesystem::exists(dir / "two-band-3.stl"));
    EXPECT_FALSE(std::filesystem::exists(dir / "two-band-2.stl"));
    // Bad series and series where one band is read are bad input.
    for (const char* bad : {"3-1", "0-2", "1,,2", "x"})
        EXPECT_EQ(test::runTsf("gen " + path + " --variable pr --band " + bad + " -o " + (dir / "bad.stl").string(), dir).exit_code, 2)
            << bad;
    EXPECT_EQ(test::runTsf("info " + path + " --variable pr --band 1-3", dir).exit_code, 2);
}

// A classic netCDF file cut short (a download that stopped half way) is
// refused, naming the size its header asks for: the netCDF library reads
// what is missing as zeros without an error, so GDAL alone would hand on a
// model with half its values on the floor. The whole file still reads.
TEST(NetCdf, ATruncatedClassicFileIsRefusedNotReadAsZeros) {
    const auto dir = test::scratchDir();
    for (const char* format : {"NC", "NC2"}) {
        const std::string path = (dir / (std::string(format) + ".nc")).string();
        // 24 x 18 values a step, as in a CF file cut in half that was once read with half its cells at 0.
        const test::NetCdfSpec spec{.steps = 3, .rows = 24, .cols = 18};
        ASSERT_TRUE(test::writeNetCdf(path, spec, format)) << format;
        const std::string bytes = test::readText(path);
        ASSERT_TRUE(isNetcdfClassic(bytes)) << format << " is a classic netCDF file";
        const auto extent = netcdfClassicExtent(bytes);
        ASSERT_TRUE(extent) << format;
        // The header asks for the data of pr and tas: 3 x 24 x 18 floats and as many 16-bit integers.
        EXPECT_FALSE(extent->header_cut);
        EXPECT_LE(extent->end_bytes, int64_t(bytes.size())) << format;
        EXPECT_GE(extent->end_bytes, int64_t(1296 * 4 + 1296 * 2)) << format;
        RasterReadOptions o;
        o.variable = "pr";
        o.band = 3;
        EXPECT_DOUBLE_EQ(readRaster(path, o).at(4, 0), test::netcdfPr(2, 23, 4)) << "the whole file reads";
        for (const size_t keep : {bytes.size() / 2, size_t(extent->end_bytes) - 1}) {
            const std::string cut = (dir / (std::string(format) + "-cut.nc")).string();
            test::writeText(cut, bytes.substr(0, keep));
            const InputError e = test::catchInputError([&] { readRaster(cut, o); });
            EXPECT_EQ(e.path(), cut);
            EXPECT_TRUE(has(e.detail(), "truncated netCDF file")) << e.what();
            EXPECT_TRUE(has(e.detail(), "runs to byte " + std::to_string(extent->end_bytes))) << e.what();
            EXPECT_TRUE(has(e.detail(), "the file has " + std::to_string(keep) + " bytes")) << e.what();
            // The same from bytes in memory.
            const InputError m = test::catchInputError([&] { parseRaster(bytes.substr(0, keep), cut, o); });
            EXPECT_TRUE(has(m.detail(), "truncated netCDF file")) << m.what();
        }
        // Cut inside the header: said so, not GDAL's "unknown error".
        const std::string header_cut = (dir / (std::string(format) + "-header.nc")).string();
        test::writeText(header_cut, bytes.substr(0, 64));
        const InputError h = test::catchInputError([&] { readRaster(header_cut, o); });
        EXPECT_TRUE(has(h.detail(), "ends inside its header, after 64 bytes")) << h.what();
        // From the user's end: exit 2, the reason, no model.
        const std::string cut = (dir / (std::string(format) + "-cut.nc")).string();
        test::writeText(cut, bytes.substr(0, bytes.size() / 2));
        const test::RunResult r =
            test::runTsf("gen " + cut + " --variable pr --band 3 -o " + (dir / "cut.stl").string(), dir);
        EXPECT_EQ(r.exit_code, 2) << r.output;
        EXPECT_TRUE(has(r.err, "truncated netCDF file")) << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "cut.stl"));
    }
}

}  // namespace
}  // namespace tsf
