// Readable by default: the model tsf gen makes from its defaults passes
// tsf verify --tactile --scene on rasters as users have them (made here with
// GDAL): a UTM DEM with holes of no data, a sea-temperature grid whose land
// is no data, a geographic grid with a valley one pixel wide between high
// ground, CF NetCDF variables. Where the first model fails, gen says what it
// changed; where the user gave the option, gen keeps it and names a value
// that passes.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <nlohmann/json.hpp>

#include "tests/readers/geotiff_test_writer.h"
#include "tests/readers/netcdf_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

// Every tactile check of `tsf verify --json` output, as "id status" lines.
std::string tactileStatuses(const std::string& json_text) {
    std::string out;
    const nlohmann::json j = nlohmann::json::parse(json_text, nullptr, false);
    if (j.is_discarded()) return "(no JSON)";
    for (const auto& c : j["checks"])
        if (c["id"].get<std::string>().rfind("tactile_", 0) == 0)
            out += c["id"].get<std::string>() + " " + c["status"].get<std::string>() + ": " + c["note"].get<std::string>() + "\n";
    return out;
}

// gen with `options`, then verify --tactile --scene; returns gen's summary JSON.
nlohmann::json genAndVerify(const std::filesystem::path& dir, const std::string& input, const std::string& name,
                            const std::string& options = "") {
    const std::string model = (dir / (name + ".stl")).string();
    const auto g = test::runTsf("gen " + input + " " + options + " --json -o " + model, dir);
    EXPECT_EQ(g.exit_code, test::kExitOk) << name << "\n" << g.out << g.err;
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    EXPECT_EQ(v.exit_code, test::kExitOk) << name << "\n" << tactileStatuses(v.out) << g.out;
    const nlohmann::json j = nlohmann::json::parse(g.out, nullptr, false);
    return j.is_discarded() ? nlohmann::json() : j;
}

// A hill 200-1400 m on a UTM grid, 30 m pixels, with three holes of no data.
TEST(LegibleDefaults, AUtmDemWithHolesPasses) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = 40;
    s.rows = 32;
    s.epsg = 32633;
    s.west = 500000;
    s.north = 5200000;
    s.pixel_w = s.pixel_h = 30;
    s.nodata = -9999;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) {
            const double d = std::hypot(c - 20.0, r - 16.0);
            s.values.push_back(float(200 + 1200 * std::exp(-d * d / 150.0)));
        }
    for (const auto& [c, r] : {std::pair{18, 15}, {25, 10}, {12, 22}}) s.values[size_t(r * s.cols + c)] = -9999;
    const std::string path = (dir / "dem.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const nlohmann::json j = genAndVerify(dir, path, "dem");
    EXPECT_EQ(j["scene"]["cells"]["with_data"].get<int>() + 3, s.cols * s.rows) << "the holes stay holes";
}

// Sea temperature 275-300 K on a 1-degree grid whose land, a strip one pixel
// wide and a block, is no data: pits between tall pillars, read as holes.
TEST(LegibleDefaults, ASeaTemperatureGridWithLandPasses) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = 36;
    s.rows = 24;
    s.epsg = 4326;
    s.west = -20;
    s.north = 12;
    s.nodata = -32768;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) {
            const bool land = (c == 17 && r > 3 && r < 20) || (c > 26 && c < 31 && r > 6 && r < 12);
            s.values.push_back(land ? -32768.0f : float(275 + 25 * std::cos((r - 12) / 15.0)));
        }
    const std::string path = (dir / "sst.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    genAndVerify(dir, path, "sst");
}

// High ground 900-1000 m cut by a valley one pixel wide at 0 m: a fingertip
// cannot reach its floor 20 mm down. gen lowers the model until it does,
// keeping every step of 0.5 mm or more, and says so; given --height, it is
// kept and a height that passes is named.
TEST(LegibleDefaults, ANarrowValleyIsReachedByALowerModel) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = 30;
    s.rows = 24;
    s.epsg = 4326;
    s.west = 10;
    s.north = 50;
    s.pixel_w = s.pixel_h = 0.01;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) s.values.push_back(c == 15 ? 0.0f : float(900 + 100.0 * r / s.rows));
    const std::string path = (dir / "valley.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const nlohmann::json j = genAndVerify(dir, path, "valley");
    ASSERT_TRUE(j.contains("legibility")) << j.dump(1);
    EXPECT_NE(j["legibility"]["changed"].get<std::string>().find("--height"), std::string::npos) << j["legibility"].dump(1);
    const double height = j["scene"]["mapping"]["max_height_mm"].get<double>();
    EXPECT_LT(height, 20.0);
    EXPECT_GE(height, 2.0) << "the valley's step stays felt";

    const std::string kept = (dir / "kept.stl").string();
    const auto g = test::runTsf("gen " + path + " --height 20 -o " + kept, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    EXPECT_NE(g.out.find("warn      a fingertip reaches the bottom"), std::string::npos) << g.out;
    EXPECT_NE(g.out.find("passes every tactile check (tried"), std::string::npos) << "a value that works is named:\n" << g.out;
}

// A plateau 1000 m high pocked by single-pixel sinks 300 m deep on a
// 4-pixel lattice, with a ramp whose steps are just felt (so no lower model
// keeps them): `scale` pixels per original pixel.
test::GeoTiffSpec pockedPlateau(int scale) {
    test::GeoTiffSpec s;
    s.cols = s.rows = 48 * scale;
    s.epsg = 32633;
    s.west = 500000;
    s.north = 5200000;
    s.pixel_w = s.pixel_h = 30.0 / scale;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) {
            const int pr = r / scale, pc = c / scale;
            const bool sink = pr % 4 == 1 && pc % 4 == 1 && pr < 44;
            const bool ramp = pr >= 46 && pc < 12;  // steps of 28 m, 0.56 mm at 20 mm for 1000 m
            s.values.push_back(sink ? 700.0f : ramp ? float(1000 - 28 * pc) : 1000.0f);
        }
    return s;
}

// A raster tsf resamples to fit (192 by 192 pixels: 49 hexagons across at
// 3 mm) whose sinks a fingertip cannot reach and whose felt steps forbid a
// lower model: gen reads it again with larger hexagons (fewer across, each
// the mean of more pixels), says what it changed, what that generalises and
// how to keep the first, and the key says so. --bins given is kept.
TEST(LegibleDefaults, AResampledRasterGetsLargerCellsWhenNothingElsePasses) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "pocked.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, pockedPlateau(4)));
    const nlohmann::json j = genAndVerify(dir, path, "pocked");
    ASSERT_TRUE(j.contains("legibility")) << j.dump(1);
    const std::string changed = j["legibility"].value("changed", "");
    EXPECT_EQ(changed.rfind("--bins ", 0), 0u) << j["legibility"].dump(1);
    EXPECT_NE(j["legibility"].value("generalised", "").find("times the ground it did"), std::string::npos)
        << j["legibility"].dump(1);
    const int bins = std::stoi(changed.substr(7));
    EXPECT_LT(bins, 49);
    EXPECT_EQ(j["scene"]["grid"]["cols"].get<int>(), bins) << j["scene"].dump(1).substr(0, 400);
    const std::string key = test::readText(dir / "pocked.key.txt");
    EXPECT_NE(key.find("So that a fingertip reaches the bottom of every low"), std::string::npos) << key;

    const std::string kept = (dir / "kept.stl").string();
    const auto g = test::runTsf("gen " + path + " --bins 49 -o " + kept, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    EXPECT_NE(g.out.find("warn      a fingertip reaches the bottom"), std::string::npos) << g.out;
    EXPECT_NE(g.out.find("tried: --bins "), std::string::npos) << "the --bins that passes is named:\n" << g.out;
    EXPECT_NE(g.out.find("the options given are kept"), std::string::npos) << g.out;
}

// The same field as one pillar per value (48 by 48 pixels fit at 3.1 mm):
// the data is kept as read, never resampled for legibility; the summary
// names the --bins that would pass.
TEST(LegibleDefaults, OnePillarPerValueIsNeverResampledToPass) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "pocked.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, pockedPlateau(1)));
    const std::string model = (dir / "one.stl").string();
    const auto g = test::runTsf("gen " + path + " --json -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const nlohmann::json j = nlohmann::json::parse(g.out);
    EXPECT_EQ(j["scene"]["grid"]["cols"].get<int>(), 48) << "one pillar per value";
    ASSERT_TRUE(j.contains("legibility")) << j.dump(1);
    EXPECT_FALSE(j["legibility"].contains("changed")) << j["legibility"].dump(1);
    EXPECT_EQ(j["legibility"].value("would_pass", "").rfind("--bins ", 0), 0u) << j["legibility"].dump(1);
    EXPECT_NE(j["legibility"].value("why", "").find("one pillar per value"), std::string::npos) << j["legibility"].dump(1);
}

// A deterministic noise in [-0.5, 0.5) (a hash of the pixel), for texture.
double pixelNoise(int c, int r) {
    uint32_t h = uint32_t(c) * 374761393u + uint32_t(r) * 668265263u;
    h = (h ^ (h >> 13)) * 1274126177u;
    return double(h ^ (h >> 16)) / 4294967296.0 - 0.5;
}

// Hills on a grid: four Gaussian bumps (heights and widths in pixels) over a
// base, with noise of `noise` peak to peak and a lake that floods what lies
// below `lake`.
std::vector<float> hills(int n, double base, double noise, double lake) {
    const double bumps[4][4] = {{0.3, 0.4, 0.25, 250}, {0.7, 0.3, 0.2, 180}, {0.5, 0.75, 0.3, 300}, {0.15, 0.8, 0.15, 120}};
    std::vector<float> v;
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c) {
            double z = base + noise * pixelNoise(c, r);
            for (const auto& b : bumps) {
                const double dx = c - b[0] * n, dy = r - b[1] * n, w = b[2] * n;
                z += b[3] * std::exp(-(dx * dx + dy * dy) / (w * w));
            }
            v.push_back(float(std::max(z, lake)));
        }
    return v;
}

// More rasters as users have them: a geographic DEM at 60 degrees north (its
// pixels narrower east-west than north-south on the ground) with a lake; a
// Landsat-like byte band of reflectance with pixel texture; a polar
// stereographic 10 by 10 grid; a land cover class map with single-pixel
// speckle. Each default model passes.
TEST(LegibleDefaults, MoreRastersAsUsersHaveThemPass) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec dem;
    dem.cols = dem.rows = 121;
    dem.epsg = 4326;
    dem.west = 10;
    dem.north = 61;
    dem.pixel_w = dem.pixel_h = 1.0 / 120;
    dem.values = hills(121, 80, 8, 100);
    test::GeoTiffSpec landsat;
    landsat.cols = landsat.rows = 60;
    landsat.epsg = 32611;
    landsat.west = 300000;
    landsat.north = 4001800;
    landsat.pixel_w = landsat.pixel_h = 30;
    landsat.byte_band = true;
    for (const float z : hills(60, 60, 32, 0)) landsat.values.push_back(std::min(255.0f, z / 5));
    test::GeoTiffSpec polar;
    polar.cols = polar.rows = 10;
    polar.epsg = 3413;
    polar.west = -1000000;
    polar.north = -750000;
    polar.pixel_w = polar.pixel_h = 25000;
    for (int r = 0; r < 10; ++r)
        for (int c = 0; c < 10; ++c) polar.values.push_back(float(250 + 0.8 * r + 0.5 * c + 2 * pixelNoise(c, r)));
    test::GeoTiffSpec cover;
    cover.cols = cover.rows = 80;
    cover.epsg = 32617;
    cover.west = 500000;
    cover.north = 4002400;
    cover.pixel_w = cover.pixel_h = 30;
    cover.classes = true;
    const int codes[] = {11, 21, 41, 42, 52, 71, 81, 82, 90};
    for (int r = 0; r < 80; ++r)
        for (int c = 0; c < 80; ++c) {
            const int region = (r / 27) * 3 + c / 27;  // nine blocks
            const bool speckle = pixelNoise(c, r) > 0.42;
            cover.values.push_back(float(codes[speckle ? (region + 4) % 9 : region % 9]));
        }
    for (const auto& [name, spec] : {std::pair<std::string, const test::GeoTiffSpec*>{"dem", &dem},
                                     {"landsat", &landsat},
                                     {"polar", &polar},
                                     {"cover", &cover}}) {
        const std::string path = (dir / (name + ".tif")).string();
        ASSERT_TRUE(test::writeGeoTiff(path, *spec)) << name;
        genAndVerify(dir, path, name);
    }
}

// CF NetCDF: precipitation with a fill value, and packed air temperature.
TEST(LegibleDefaults, NetCdfVariablesPass) {
    const auto dir = test::scratchDir();
    const std::string path = (dir / "climate.nc").string();
    ASSERT_TRUE(test::writeNetCdf(path, {2, 12, 16})) << "GDAL's netCDF driver";
    genAndVerify(dir, path + " --variable pr --band 2", "pr");
    genAndVerify(dir, path + " --variable tas --band 1", "tas");
}

}  // namespace
}  // namespace tsf
