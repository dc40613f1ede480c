// A raster's georeference read right or not at all: a rotated geotransform is
// resampled north-up with the true ground size, --ignore-georef reads the
// plain grid, and coordinates that cannot be degrees are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <set>

#include <nlohmann/json.hpp>

#include "gen/readers/gdal_reader.h"
#include "gen/readers/raster_reader.h"
#include "tests/readers/geotiff_test_writer.h"
#include "tests/readers/netcdf_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

// 20 x 20 pixels of 5.22 m (UTM 33N), the raster's top edge facing 73 degrees
// clockwise from north; value row * 100 + col, so each pixel is known by its value.
test::GeoTiffSpec rotatedSpec() {
    test::GeoTiffSpec s;
    s.cols = s.rows = 20;
    s.epsg = 32633;
    for (int r = 0; r < 20; ++r)
        for (int c = 0; c < 20; ++c) s.values.push_back(float(r * 100 + c));
    const double px = 5.22, t = 73.0 * kPi / 180.0;
    // Up the raster is (sin t, cos t) east and north; along a row is 90 degrees clockwise of it.
    s.geotransform = {500000, px * std::cos(t), -px * std::sin(t), 6000000, -px * std::sin(t), -px * std::cos(t)};
    return s;
}

// The north-up box of a 104.4 m square turned 73 degrees: 104.4 (cos 73 + sin 73) a side.
const double kSide = 20 * 5.22, kBox = kSide * (std::cos(73.0 * kPi / 180.0) + std::sin(73.0 * kPi / 180.0));

TEST(Georef, ARotatedRasterIsResampledNorthUpWithItsValuesAndItsGround) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "rotated.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, rotatedSpec()));
    const Raster r = readRaster(path);
    EXPECT_NEAR(r.cell_size, 5.22, 1e-9) << "square pixels of the source pixel's area";
    EXPECT_NEAR(r.cols * r.cell_size, kBox, 5.22);
    EXPECT_NEAR(r.rows * r.cell_size, kBox, 5.22);
    EXPECT_NE(r.fact("rotated").find("73.0 degrees clockwise from north"), std::string::npos) << r.fact("rotated");
    EXPECT_NE(r.fact("rotated").find("104.4 by 104.4"), std::string::npos) << r.fact("rotated");
    // Nearest neighbour: every value is a pixel of the file, about as many
    // pixels hold data as the file has, and the corners of the box are empty.
    int with_data = 0;
    int north_row = -1, east_col = -1;
    double north_value = NAN, east_value = NAN;
    for (int32_t y = 0; y < r.rows; ++y)
        for (int32_t x = 0; x < r.cols; ++x) {
            const double v = r.at(x, y);
            if (std::isnan(v)) continue;
            ++with_data;
            const int row = int(v) / 100, col = int(v) % 100;
            EXPECT_EQ(double(row * 100 + col), v);
            EXPECT_LT(row, 20);
            EXPECT_LT(col, 20);
            if (north_row < 0) north_row = y, north_value = v;
            if (x > east_col) east_col = x, east_value = v;
        }
    EXPECT_NEAR(with_data, 400, 40);
    EXPECT_TRUE(std::isnan(r.at(0, 0)) && std::isnan(r.at(r.cols - 1, r.rows - 1)));
    // The file's top-left corner is the northernmost point, its top-right the easternmost.
    EXPECT_LT(int(north_value) / 100, 3) << north_value;
    EXPECT_LT(int(north_value) % 100, 3) << north_value;
    EXPECT_LT(int(east_value) / 100, 3) << east_value;
    EXPECT_GT(int(east_value) % 100, 16) << east_value;

    // The summary's ground: the box the model shows, not 20 pixels of 1.5 m.
    const std::string model = (dir / "rotated.stl").string();
    const auto run = test::runTsf("gen " + path + " -o " + model + " --json");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    ASSERT_TRUE(j["ground"].is_object()) << j.dump();
    EXPECT_NEAR(j["ground"]["width_m"].get<double>(), kBox, 5.22);
    EXPECT_NEAR(j["ground"]["depth_m"].get<double>(), kBox, 5.22);
    // The scale is the ground over the model: millimetres of model per metre of ground.
    const double width_mm = j["scene"]["size_mm"][0].get<double>();
    EXPECT_NEAR(j["ground"]["scale"].get<double>(), kBox * 1000 / width_mm, 0.15 * kBox * 1000 / width_mm);
    const std::string key = test::readText(dir / "rotated.key.txt");
    EXPECT_NE(key.find("130"), std::string::npos) << "the ground's side, about 130 m\n" << key;
}

// A rotated raster by default, as a reader gets it: the north-up box is
// empty outside the turned square, and the model ends where the data does.
// The hull's slanted edges once kept a row of no-data pits along the rim,
// which the key announced as missing values, and the orientation tab, with
// no pillars to stand against on the slant, hung from one corner pillar
// (tactile_attachment_joints warned of hundreds of MPa). Every turn: no cell
// without data, and every check passes but the height steps' warning.
TEST(Georef, ARotatedRasterEndsWhereItsDataDoesAndItsTabHolds) {
    const auto dir = test::scratchDir();
    for (const double degrees : {30.0, 73.0, 140.0}) {
        test::GeoTiffSpec s;
        s.cols = 40;
        s.rows = 48;
        s.epsg = 32633;
        for (int r = 0; r < s.rows; ++r)
            for (int c = 0; c < s.cols; ++c) s.values.push_back(float(100 + 40 * std::sin(r * 0.2) * std::cos(c * 0.15)));
        const double px = 10, t = degrees * kPi / 180.0;
        s.geotransform = {500000, px * std::cos(t), -px * std::sin(t), 6000000, -px * std::sin(t), -px * std::cos(t)};
        const std::string path = (dir / "turned.tif").string();
        ASSERT_TRUE(test::writeGeoTiff(path, s));
        const auto run = test::runTsf("gen " + path + " -o " + (dir / "turned.stl").string() + " --json");
        ASSERT_EQ(run.exit_code, 0) << degrees << " degrees\n" << run.output;
        const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
        EXPECT_EQ(j["scene"]["cells"]["kept_without_data"].get<int>(), 0) << degrees << " degrees";
        for (const auto& c : j["verify"]["checks"]) {
            const std::string id = c["id"], status = c["status"];
            if (id == "tactile_height_steps" || id == "fits_bed") continue;
            EXPECT_EQ(status, "pass") << degrees << " degrees: " << id << ": " << c["note"];
        }
    }
}

TEST(Georef, IgnoreGeorefReadsThePlainGrid) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "rotated.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, rotatedSpec()));
    RasterReadOptions o;
    o.ignore_georef = true;
    const Raster r = readRaster(path, o);
    EXPECT_EQ(r.cols, 20);
    EXPECT_EQ(r.rows, 20);
    EXPECT_EQ(r.cell_size, 1.0);
    EXPECT_EQ(r.metres_per_unit, 0.0);
    EXPECT_FALSE(r.place.known);
    EXPECT_EQ(r.at(19, 0), 19.0);
    EXPECT_EQ(r.at(0, 19), 1900.0);
    EXPECT_NE(r.fact("georeference").find("--ignore-georef"), std::string::npos);

    const auto run = test::runTsf("gen " + path + " --ignore-georef -o " + (dir / "plain.stl").string() + " --json");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    EXPECT_TRUE(j["ground"].is_null()) << j["ground"].dump();

    const auto points = test::runTsf("gen " + path + " --points x=0,y=1 --ignore-georef -o " + (dir / "p.stl").string());
    EXPECT_EQ(points.exit_code, 2) << points.output;
    EXPECT_NE(points.output.find("--ignore-georef is for rasters"), std::string::npos) << points.output;
}

// A north-up file's pixels in its own coordinates, with the axes' names:
// longitude and latitude in degrees, easting and northing in metres.
TEST(Georef, ANorthUpRasterSaysWhereItsPixelsLieAndOnWhichAxes) {
    const auto dir = test::scratchDir();
    const auto expectPlace = [&](int epsg, double west, double north, double w, double h, const DataAxes& axes) {
        test::GeoTiffSpec g;
        g.cols = 8;
        g.rows = 6;
        g.values.assign(48, 1.0f);
        g.epsg = epsg;
        g.west = west;
        g.north = north;
        g.pixel_w = w;
        g.pixel_h = h;
        const std::string path = (dir / ("epsg" + std::to_string(epsg) + ".tif")).string();
        ASSERT_TRUE(test::writeGeoTiff(path, g));
        const PixelPlace p = readRaster(path, {}).place;
        ASSERT_TRUE(p.known) << epsg;
        EXPECT_EQ(p.axes.x, axes.x);
        EXPECT_EQ(p.axes.y, axes.y);
        EXPECT_EQ(p.axes.unit, axes.unit);
        EXPECT_DOUBLE_EQ(p.x_west, west);
        EXPECT_DOUBLE_EQ(p.dx, w);
        EXPECT_DOUBLE_EQ(p.y_north, north);
        EXPECT_DOUBLE_EQ(p.dy, h);
    };
    expectPlace(4326, 10, 50, 0.25, 0.125, {"longitude", "latitude", "degrees"});
    expectPlace(32633, 400000, 5500000, 30, 30, {"easting", "northing", "metres"});
}

// Degrees must be on the globe: a latitude of 435 is named, not modelled.
TEST(Georef, DegreesOffTheGlobeAreRefusedNamingTheValue) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = 4;
    s.rows = 3;
    s.values.assign(12, 1.0f);
    s.epsg = 4326;
    s.west = 10;
    s.north = 435;
    s.pixel_w = s.pixel_h = 1;
    const std::string path = (dir / "off.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    EXPECT_INPUT_ERROR(readRaster(path), "latitude 435");
    RasterReadOptions o;
    o.ignore_georef = true;
    EXPECT_EQ(readRaster(path, o).cols, 4) << "--ignore-georef, which the message offers, reads it";
}

// The same for a CF NetCDF file whose latitudes run to 435 degrees north.
TEST(Georef, NetCdfLatitudesOffTheGlobeAreRefusedNamingTheValue) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "off.nc").string();
    test::NetCdfSpec s;
    s.lat_shift = 433;  // latitudes 431.5 to 434.5, their pixels' edges to 435
    ASSERT_TRUE(test::writeNetCdf(path, s)) << "GDAL's netCDF driver (Debian libgdal32 has it)";
    RasterReadOptions o;
    o.variable = "pr";
    EXPECT_INPUT_ERROR(readRaster(path, o), "y values reach latitude 435 degrees");
    const auto run = test::runTsf("gen " + path + " --variable pr -o " + (dir / "off.stl").string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("latitude 435"), std::string::npos) << run.output;
    test::NetCdfSpec fine;
    const std::string ok_path = (dir / "fine.nc").string();
    ASSERT_TRUE(test::writeNetCdf(ok_path, fine));
    EXPECT_EQ(readRaster(ok_path, o).cols, fine.cols) << "latitudes on the globe are read";
}

}  // namespace
}  // namespace tsf
