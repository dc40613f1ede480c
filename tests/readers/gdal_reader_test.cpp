// GDAL rasters: a GeoTIFF's no-data value, pixel size and CRS give the model a
// user expects, and a binary file is never parsed as text.
#include "gen/readers/gdal_reader.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "gen/field/resample.h"
#include "gen/readers/load_field.h"
#include "gen/readers/raster_reader.h"
#include "tests/readers/geotiff_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "tests/support/run.h"

#include <cpl_string.h>
#include <filesystem>
#include <set>

#include <nlohmann/json.hpp>

namespace tsf {
namespace {

// 4 x 3 values 1..12, -9999 at (1, 0) and (3, 2).
test::GeoTiffSpec demSpec() {
    test::GeoTiffSpec s;
    s.cols = 4;
    s.rows = 3;
    for (int k = 0; k < 12; ++k) s.values.push_back(float(k + 1));
    s.values[1] = -9999.0f;
    s.values[11] = -9999.0f;
    s.nodata = -9999.0;
    return s;
}

TEST(GdalReader, ProjectedGeoTiffWithNoData) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    s.epsg = 32633;  // WGS 84 / UTM zone 33N, metres
    s.west = 500000;
    s.north = 5200000;
    s.pixel_w = s.pixel_h = 30;
    const std::string path = (dir / "dem.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const Raster r = readRaster(path);
    ASSERT_EQ(r.cols, 4);
    ASSERT_EQ(r.rows, 3);
    EXPECT_EQ(r.kind, "gdal/GTiff");
    EXPECT_EQ(r.at(0, 0), 1.0);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    EXPECT_TRUE(std::isnan(r.at(3, 2)));
    EXPECT_EQ(r.at(2, 2), 11.0);
    EXPECT_EQ(r.cell_size, 30.0);
    EXPECT_NE(r.fact("crs").find("EPSG:32633"), std::string::npos) << r.fact("crs");
    EXPECT_NE(r.fact("crs").find("projected: true aspect"), std::string::npos);
    EXPECT_EQ(r.fact("pixel"), "30 x 30 metre");
    EXPECT_EQ(r.fact("no-data value"), "-9999 (from the file)");
}

// Oblong pixels keep their shape: one pillar per value in hexagons stretched
// to it, and only a resampling makes them square (nearest, repeating a row).
TEST(GdalReader, OblongPixelsAreKeptAndSquaredOnlyToResample) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    s.epsg = 32633;
    s.pixel_w = 30;
    s.pixel_h = 60;  // each pixel twice as tall as wide: 120 m x 180 m on the ground
    const std::string path = (dir / "tall.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const Raster r = readRaster(path);
    EXPECT_EQ(r.cols, 4);
    EXPECT_EQ(r.rows, 3) << "every pixel read once";
    EXPECT_EQ(r.cell_size, 30.0);
    EXPECT_EQ(r.row_aspect, 2.0);
    EXPECT_NE(r.fact("pixel shape").find("2 times as far apart"), std::string::npos) << r.fact("pixel shape");
    const Raster square = squarePixels(r);
    EXPECT_EQ(square.rows, 6);
    EXPECT_EQ(square.at(0, 1), 1.0) << "nearest neighbour repeats the row";
    EXPECT_NE(square.fact("resampled"), "");
    RasterPlacement one;
    one.pitch_mm = 5;
    const HexField f = placeRaster(r, one);
    EXPECT_TRUE(f.one_to_one);
    EXPECT_EQ(f.grid.rows, 3);
    EXPECT_EQ(f.row_aspect, 2.0);
    one.true_aspect = false;  // regular hexagons: the pixels are made square first
    const HexField regular = placeRaster(r, one);
    EXPECT_EQ(regular.grid.rows, 6);
    EXPECT_FALSE(regular.one_to_one) << "a repeated row is not one pillar per value";
    EXPECT_NE(regular.how.find("one pillar per square pixel"), std::string::npos) << regular.how;
}

TEST(GdalReader, GeographicLongitudeIsScaledByCosLatitude) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    s.epsg = 4326;
    s.west = 10;
    s.north = 60.015;  // mean latitude 60: a degree of longitude is half a degree of latitude
    s.pixel_w = s.pixel_h = 0.01;
    const std::string path = (dir / "geo.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const Raster r = readRaster(path);
    EXPECT_EQ(r.cols, 4);
    EXPECT_EQ(r.rows, 3);
    EXPECT_NEAR(r.row_aspect, 2.0, 1e-9) << "pixels of 0.005 x 0.01 degrees of latitude on the ground";
    EXPECT_NE(r.fact("crs").find("cos(60 deg) = 0.5"), std::string::npos) << r.fact("crs");
}

// The model's width / depth (mm, the pillars' box) from tsf gen --json.
double modelAspect(const nlohmann::json& j) {
    return j["scene"]["size_mm"][0].get<double>() / j["scene"]["size_mm"][1].get<double>();
}

// A cols x rows UTM 33N raster (EPSG:32633) of px_w x px_h m pixels; the
// caller fills its values.
test::GeoTiffSpec utmSpec(int cols, int rows, double px_w, double px_h) {
    test::GeoTiffSpec s;
    s.cols = cols;
    s.rows = rows;
    s.epsg = 32633;
    s.west = 500000;
    s.north = 6000000;
    s.pixel_w = px_w;
    s.pixel_h = px_h;
    return s;
}

// True aspect: one pillar per value of a projected DEM keeps the ground's
// proportions (the hexagons stretched north-south so rows stand a cell
// apart), and the report gives the ground's size and the scale; regular
// hexagons are 13% shallower.
TEST(GdalReader, OnePillarPerValueKeepsTheGroundsAspect) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = utmSpec(60, 40, 30, 30);  // 1800 x 1200 m on the ground
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) s.values.push_back(float(100 + 3 * c + 2 * r + (r * c) % 7));
    const std::string path = (dir / "dem.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const auto run = test::runTsf("gen " + path + " --cell 2 -o " + (dir / "dem.stl").string() + " --json");
    ASSERT_EQ(run.exit_code, test::kExitOk) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    EXPECT_TRUE(j["scene"]["one_pillar_per_value"].get<bool>());
    EXPECT_NEAR(modelAspect(j) / 1.5, 1.0, 0.03) << j["scene"]["size_mm"].dump();
    EXPECT_NEAR(j["scene"]["y_scale"].get<double>(), 2 / std::sqrt(3.0), 1e-15);
    EXPECT_NEAR(j["ground"]["width_m"].get<double>(), 1800.0, 1e-9);
    EXPECT_NEAR(j["ground"]["depth_m"].get<double>(), 1200.0, 1e-9);
    // 30 m a cell, 2 mm a cell: 1 to 15,000 both ways.
    EXPECT_NEAR(j["ground"]["scale"].get<double>(), 15000.0, 1e-6);
    EXPECT_NEAR(j["ground"]["scale_north_south"].get<double>(), 15000.0, 1e-6);
    EXPECT_TRUE(j["ground"]["longitude_scale"].is_null());
    const auto text = test::runTsf("gen " + path + " --cell 2 -o " + (dir / "t.stl").string());
    EXPECT_NE(text.output.find("scale 1 to 15,000 (1 mm on the model is 15 m on the ground)"), std::string::npos)
        << text.output;
    EXPECT_NE(text.output.find("aspect    true"), std::string::npos) << text.output;
    const std::string key = test::readText(dir / "t.key.txt");
    EXPECT_NE(key.find("The model shows ground 1800 metres from west to east and 1200 metres from south to north, at a "
                       "scale of 1 to 15,000: 1 millimetre on the model is 15 metres on the ground."),
              std::string::npos)
        << key;

    const auto regular = test::runTsf("gen " + path + " --cell 2 --regular-hexagons -o " +
                                      (dir / "regular.stl").string() + " --json");
    ASSERT_EQ(regular.exit_code, test::kExitOk) << regular.output;
    const nlohmann::json rj = nlohmann::json::parse(regular.output.substr(regular.output.find('{')));
    EXPECT_NEAR(modelAspect(rj) / 1.5, 2 / std::sqrt(3.0), 0.01) << "regular hexagons: 13% shallower";
    EXPECT_EQ(rj["scene"]["y_scale"].get<double>(), 1.0);
    EXPECT_NEAR(rj["ground"]["scale_north_south"].get<double>(), 15000.0 * 2 / std::sqrt(3.0), 1e-6);
}

// Pixels twice as wide as tall on the ground: the hexagons are squashed
// north-south to them, one pillar per value, and a tilted model of them
// (its tops read back over the shorter spokes) verifies, flat and mirrored.
TEST(GdalReader, WidePixelsSquashTheHexagonsAndStillVerify) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = utmSpec(20, 30, 60, 30);  // 1200 x 900 m on the ground
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c) s.values.push_back(float(50 + 10 * std::sin(c * 0.4) * std::cos(r * 0.3)));
    const std::string path = (dir / "wide.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    for (const char* extra : {"", " --mirror"}) {
        const auto run = test::runTsf("gen " + path + " --cell 5 --tilt gradient" + extra + " -o " +
                                      (dir / "wide.stl").string() + " --json");
        ASSERT_EQ(run.exit_code, test::kExitOk) << run.output;
        const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
        EXPECT_TRUE(j["scene"]["one_pillar_per_value"].get<bool>());
        EXPECT_NEAR(j["scene"]["y_scale"].get<double>(), 1 / std::sqrt(3.0), 1e-12);
        EXPECT_NEAR(modelAspect(j) / (1200.0 / 900.0), 1.0, 0.03) << j["scene"]["size_mm"].dump();
        EXPECT_TRUE(j["verify"]["passed"].get<bool>()) << extra;
    }
}

// A geographic grid: a degree of longitude at 60 degrees north is half a
// degree of latitude on the ground, and the model keeps that aspect too.
TEST(GdalReader, AGeographicGridKeepsTheCosLatitudeAspect) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = s.rows = 30;
    s.epsg = 4326;
    s.west = 10;
    s.north = 60.15;  // mean latitude 60
    s.pixel_w = s.pixel_h = 0.01;
    for (int k = 0; k < s.cols * s.rows; ++k) s.values.push_back(float(k % 17));
    const std::string path = (dir / "geo.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const auto run = test::runTsf("gen " + path + " --cell 1.5 -o " + (dir / "geo.stl").string() + " --json");
    ASSERT_EQ(run.exit_code, test::kExitOk) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    EXPECT_NEAR(modelAspect(j) / 0.5, 1.0, 0.03) << j["scene"]["size_mm"].dump();
    // One pillar per value: no row repeated to make the pixels square.
    EXPECT_TRUE(j["scene"]["one_pillar_per_value"].get<bool>());
    EXPECT_EQ(j["scene"]["cells"]["with_data"].get<int>(), 30 * 30);
    EXPECT_NEAR(j["scene"]["y_scale"].get<double>(), 2 * 2 / std::sqrt(3.0), 1e-3);
    EXPECT_NEAR(j["ground"]["scale"].get<double>(), j["ground"]["scale_north_south"].get<double>(), 1e-6);
    EXPECT_NEAR(j["ground"]["longitude_scale"].get<double>(), 0.5, 1e-3);
    // 0.3 degrees of latitude north-south.
    EXPECT_NEAR(j["ground"]["depth_m"].get<double>(), 0.3 * kMetresPerDegreeOfLatitude, 1.0);
}

TEST(GdalReader, LoadFieldReportsWhatWasRead) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    s.epsg = 32633;
    s.pixel_w = s.pixel_h = 30;
    FieldLoadOptions in;
    in.input = (dir / "dem.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(in.input, s));
    const HexField f = loadField(in);
    EXPECT_EQ(f.input.nodata, 2);
    EXPECT_EQ(f.input.min, 1.0);
    EXPECT_EQ(f.input.max, 11.0);
    EXPECT_TRUE(f.one_to_one);
}

// A land-cover map: class codes with a colour table. Resampled, every
// hexagon is a class of the map (the most common of its pixels), never the
// mean of two codes; the same numbers without a colour table are measurements
// and are averaged.
TEST(GdalReader, AClassMapIsResampledByItsMostCommonClassNeverByAMean) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = s.rows = 60;
    s.epsg = 32633;
    s.pixel_w = s.pixel_h = 30;
    // Wetland classes 90 and 95 in a fine checkerboard of 3 x 3 pixel blocks,
    // a forest (41) in the north-west quarter.
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c)
            s.values.push_back(r < 30 && c < 30 ? 41.0f : ((r / 3 + c / 3) % 2 ? 95.0f : 90.0f));
    s.classes = true;
    FieldLoadOptions in;
    in.input = (dir / "landcover.tif").string();
    in.bins = 12;  // 60 px -> 12 hexagons across: about 5 px a hexagon
    ASSERT_TRUE(test::writeGeoTiff(in.input, s));
    const HexField f = loadField(in);
    EXPECT_FALSE(f.one_to_one);
    EXPECT_NE(f.how.find("most common class"), std::string::npos) << f.how;
    size_t cells = 0;
    for (const double v : f.values) {
        if (std::isnan(v)) continue;
        ++cells;
        EXPECT_TRUE(v == 41.0 || v == 90.0 || v == 95.0) << v << " is no class of the map";
    }
    EXPECT_GT(cells, 100u);
    bool said = false;
    for (const ReadFact& fact : f.input.facts) said = said || fact.value.find("colour table") != std::string::npos;
    EXPECT_TRUE(said);
    // Without the colour table the same numbers are measurements: the mean.
    s.classes = false;
    in.input = (dir / "measured.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(in.input, s));
    const HexField m = loadField(in);
    bool averaged = false;
    for (const double v : m.values) averaged = averaged || (v > 90.0 && v < 95.0);
    EXPECT_TRUE(averaged) << m.how;
    // Asked for by name, mode works on any raster.
    in.sample = "mode";
    const HexField mode = loadField(in);
    for (const double v : mode.values)
        if (!std::isnan(v)) EXPECT_TRUE(v == 41.0 || v == 90.0 || v == 95.0) << v;
}

// A land-cover map of size x size 30 m pixels (UTM 33N, 8-bit codes, no
// colour table) in blocks of the classes `named` gives (code, name), whose
// names are the band's category names.
test::GeoTiffSpec landCover(int size, int block_rows, int block_cols, const std::vector<std::pair<int, std::string>>& named) {
    test::GeoTiffSpec s;
    s.cols = s.rows = size;
    s.epsg = 32633;
    s.pixel_w = s.pixel_h = 30;
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c)
            s.values.push_back(float(named[size_t(r / block_rows + c / block_cols) % named.size()].first));
    s.byte_band = true;
    int top = 0;
    for (const auto& [code, name] : named) top = std::max(top, code);
    s.category_names.assign(size_t(top) + 1, "");
    for (const auto& [code, name] : named) s.category_names[size_t(code)] = name;
    return s;
}

// A land-cover map with class names but no colour table: the names make it a
// class map, the summary and the key name every class, and no hexagon holds
// a class the map does not have.
TEST(GdalReader, ClassNamesMakeAClassMapAndTheSummaryAndTheKeyNameEveryClass) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = landCover(60, 7, 5,
                                    {{11, "Open Water"}, {41, "Deciduous Forest"}, {90, "Woody Wetlands"},
                                     {95, "Emergent Herbaceous Wetlands"}});
    const std::string path = (dir / "landcover.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const Raster r = readGdalRaster(path);
    EXPECT_TRUE(r.categorical);
    ASSERT_EQ(r.classes.size(), 4u);
    EXPECT_EQ(r.classes[2].code, 90.0);
    EXPECT_EQ(r.classes[2].name, "Woody Wetlands");

    const std::string model = (dir / "lc.stl").string();
    const auto run = test::runTsf("gen " + path + " --bins 20 -o " + model + " --json");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    ASSERT_TRUE(j["classes"].is_array()) << j.dump();
    ASSERT_EQ(j["classes"].size(), 4u) << j["classes"].dump();
    std::set<double> heights;
    std::set<std::string> textures;
    int64_t cells = 0;
    for (const auto& c : j["classes"]) {
        EXPECT_TRUE(c["name"].is_string()) << c.dump();
        heights.insert(c["height_mm"].get<double>());
        textures.insert(c["texture"].get<std::string>());
        cells += c["cells"].get<int64_t>();
    }
    // Nominal classes: one height, a texture each (no order invented).
    EXPECT_EQ(heights.size(), 1u) << j["classes"].dump();
    EXPECT_EQ(textures.size(), 4u) << j["classes"].dump();
    EXPECT_EQ(cells, j["scene"]["cells"]["with_data"].get<int64_t>());
    EXPECT_EQ(j["classes"][3]["name"], "Emergent Herbaceous Wetlands");
    const std::string key = test::readText(dir / "lc.key.txt");
    for (const char* said : {"classes, not amounts: 4 classes", "class 11 Open Water", "class 41 Deciduous Forest",
                             "class 90 Woody Wetlands", "class 95 Emergent Herbaceous Wetlands",
                             "told apart by the feel of its tops"})
        EXPECT_NE(key.find(said), std::string::npos) << said << "\n" << key;
    EXPECT_EQ(key.find("The values go from"), std::string::npos) << "a range of class codes means nothing\n" << key;
    // The braille plate says how many classes, not the range of their codes.
    const auto titled = test::runTsf("gen " + path + " --bins 20 --title Cover -o " + (dir / "t.stl").string() + " --json");
    ASSERT_EQ(titled.exit_code, 0) << titled.output;
    const nlohmann::json tj = nlohmann::json::parse(titled.output.substr(titled.output.find('{')));
    ASSERT_EQ(tj["scene"]["legend"]["lines"].size(), 2u) << tj["scene"]["legend"].dump();
    EXPECT_EQ(tj["scene"]["legend"]["lines"][1]["text"], "4 classes");
    // "ridges north-south: Emergent Herbaceous Wetlands" is wider than the
    // plate: the classes are named in the key files only, and the summary says so.
    bool said = false;
    for (const auto& n : tj["scene"]["notes"]) said = said || n.get<std::string>().find("names the classes only in the key") != std::string::npos;
    EXPECT_TRUE(said) << tj["scene"]["notes"].dump();

    // The same names in a raster attribute table (rows in any order).
    s.category_names.clear();
    s.attribute_names = {{95, "Emergent Herbaceous Wetlands"}, {11, "Open Water"}, {41, "Deciduous Forest"}, {90, "Woody Wetlands"}};
    const std::string rat_path = (dir / "landcover_rat.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(rat_path, s));
    const Raster rat = readGdalRaster(rat_path);
    EXPECT_TRUE(rat.categorical);
    ASSERT_EQ(rat.classes.size(), 4u);
    EXPECT_EQ(rat.classes[0].code, 11.0);
    EXPECT_EQ(rat.classes[0].name, "Open Water");
    EXPECT_EQ(rat.classes[3].name, "Emergent Herbaceous Wetlands");
}

// --class-order: the user says the classes are ordered; each stands one even
// step above the one before, in the order given (codes or the file's names),
// and every class the model holds must be listed.
TEST(GdalReader, ClassOrderGivesEachClassOneEvenStepInTheOrderGiven) {
    const auto dir = test::scratchDir();
    const test::GeoTiffSpec s = landCover(40, 8, 8, {{11, "Open Water"}, {41, "Deciduous Forest"}, {90, "Woody Wetlands"}});
    const std::string path = (dir / "lc.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const std::string model = (dir / "lc.stl").string();
    const auto run = test::runTsf("gen " + path + " --bins 16 --height 12 --class-order \"woody wetlands,11,Deciduous Forest\" -o " +
                                  model + " --json");
    ASSERT_EQ(run.exit_code, 0) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    ASSERT_EQ(j["classes"].size(), 3u) << j.dump();
    EXPECT_TRUE(j["class_order_given"].get<bool>());
    // Lowest first, in the order given, 4 mm apart (12 mm over three classes).
    const double want_code[3] = {90, 11, 41};
    for (size_t k = 0; k < 3; ++k) {
        EXPECT_EQ(j["classes"][k]["code"].get<double>(), want_code[k]) << j["classes"].dump();
        EXPECT_NEAR(j["classes"][k]["height_mm"].get<double>(), 4.0 * double(k + 1), 1e-9) << j["classes"].dump();
    }
    EXPECT_EQ(j["classes"][0]["name"], "Woody Wetlands");
    const std::string key = test::readText(dir / "lc.key.txt");
    EXPECT_NE(key.find("class 90 Woody Wetlands, 4 millimetres"), std::string::npos) << key;
    EXPECT_NE(key.find("one even step"), std::string::npos) << key;
    // The model verifies against its sidecar.
    const auto verified = test::runTsf("verify " + model + " --scene " + model + ".scene.json");
    EXPECT_EQ(verified.exit_code, 0) << verified.output;

    // A class left out, a name the file lacks, a class twice: exit 2, saying which.
    for (const auto& [order, said] : std::vector<std::pair<std::string, std::string>>{
             {"90,11", "leaves out class 41"}, {"90,11,Forest", "\"Forest\" is neither a class code nor a name"},
             {"90,11,41,90", "lists class 90 twice"}}) {
        const auto bad = test::runTsf("gen " + path + " --bins 16 --class-order \"" + order + "\" -o " + model);
        EXPECT_EQ(bad.exit_code, 2) << order << "\n" << bad.output;
        EXPECT_NE(bad.output.find(said), std::string::npos) << bad.output;
    }
    // Measurements are not classes.
    test::writeText(dir / "m.csv", "1,2\n3,4\n");
    const auto measured = test::runTsf("gen " + (dir / "m.csv").string() + " --class-order 1,2,3,4 -o " + model);
    EXPECT_EQ(measured.exit_code, 2) << measured.output;
    EXPECT_NE(measured.output.find("--class-order is for class maps"), std::string::npos) << measured.output;
}

// --categorical: codes in a plain grid are a class map too; points are not.
TEST(GdalReader, CategoricalMakesAnyRasterAClassMapAndIsRefusedForPoints) {
    const auto dir = test::scratchDir();
    std::string csv;
    for (int r = 0; r < 40; ++r) {
        for (int c = 0; c < 40; ++c) csv += std::string(c ? "," : "") + ((r / 2 + c / 2) % 2 ? "95" : "90");
        csv += "\n";
    }
    test::writeText(dir / "codes.csv", csv);
    FieldLoadOptions in;
    in.input = (dir / "codes.csv").string();
    in.bins = 8;
    const HexField mean = loadField(in);
    bool averaged = false;
    for (const double v : mean.values) averaged = averaged || (v > 90.0 && v < 95.0);
    EXPECT_TRUE(averaged) << "without --categorical the codes are measurements: " << mean.how;
    in.categorical = true;
    const HexField classes = loadField(in);
    EXPECT_TRUE(classes.input.categorical);
    for (const double v : classes.values)
        if (!std::isnan(v)) EXPECT_TRUE(v == 90.0 || v == 95.0) << v << " is no class of the map";
    test::writeText(dir / "p.csv", "x,y\n1,2\n3,4\n");
    const auto run = test::runTsf("gen " + (dir / "p.csv").string() + " --points x=x,y=y --categorical -o " +
                                  (dir / "p.stl").string());
    EXPECT_EQ(run.exit_code, 2) << run.output;
    EXPECT_NE(run.output.find("--categorical is for rasters"), std::string::npos) << run.output;
}

TEST(GdalReader, BandChoosesWhichBandIsReadAndABandTheFileLacksIsBadInput) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s;
    s.cols = 4;
    s.rows = 3;
    s.values = {1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12};
    s.bands = 3;  // band b holds the values + 100 (b - 1)
    const std::string path = (dir / "three.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    EXPECT_EQ(readGdalRaster(path).at(0, 0), 1.0);
    const Raster third = readGdalRaster(path, 3);
    EXPECT_EQ(third.at(0, 0), 201.0);
    EXPECT_EQ(third.at(3, 2), 212.0);
    EXPECT_NE(third.fact("band").find("3 of 3"), std::string::npos) << third.fact("band");
    FieldLoadOptions in;
    in.input = path;
    in.band = 2;
    const HexField f = loadField(in);
    EXPECT_EQ(f.input.min, 101.0);
    EXPECT_EQ(f.input.max, 112.0);
    in.band = 4;
    const InputError e = test::catchInputError([&] { loadField(in); });
    EXPECT_NE(std::string(e.what()).find("--band 4: it has 3 bands"), std::string::npos) << e.what();
    // A file with one band of its own (a CSV grid) refuses another number.
    test::writeText(dir / "g.csv", "1,2\n3,4\n");
    in.input = (dir / "g.csv").string();
    in.band = 2;
    const InputError csv = test::catchInputError([&] { loadField(in); });
    EXPECT_NE(std::string(csv.what()).find("this file has one band"), std::string::npos) << csv.what();
}

TEST(GdalReader, InfoSaysWhatWasRead) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    s.epsg = 32633;
    s.pixel_w = s.pixel_h = 30;
    ASSERT_TRUE(test::writeGeoTiff((dir / "dem.tif").string(), s));
    const auto r = test::runTsf("info " + (dir / "dem.tif").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (const char* said : {"EPSG:32633", "projected: true aspect", "pixel: 30 x 30 metre", "no-data value: -9999",
                             "2 of 12 without data"})
        EXPECT_NE(r.output.find(said), std::string::npos) << said << "\n" << r.output;
}

TEST(GdalReader, BinaryFilesAreNeverParsedAsText) {
    const auto dir = test::scratchDir();
    // TIFF magic under a .csv name, but no valid TIFF behind it.
    test::writeText(dir / "fake.csv", std::string("II*\0\x08\0\0\0garbage", 16));
    EXPECT_INPUT_ERROR(readRaster((dir / "fake.csv").string()), "is a TIFF image; GDAL cannot read it");
    // A spreadsheet saved as .xlsx is a ZIP archive: say so.
    test::writeText(dir / "sheet.csv", std::string("PK\x03\x04\x14\0\0\0", 8));
    EXPECT_INPUT_ERROR(readRaster((dir / "sheet.csv").string()), ".xlsx");
    const InputError e = test::catchInputError([&] { readRaster((dir / "fake.csv").string()); });
    EXPECT_EQ(std::string(e.what()).find("separated"), std::string::npos) << e.what();
}

TEST(GdalReader, BytesInMemoryReadLikeTheFile) {
    const auto dir = test::scratchDir();
    test::GeoTiffSpec s = demSpec();
    const std::string path = (dir / "mem.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, s));
    const Raster r = parseRaster(test::readText(path), "mem.tif");
    ASSERT_EQ(r.cols, 4);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
}

// GDAL is a module loaded when a raster needs it: the tsf binary itself does
// not link it (the dynamic loader lists what a binary needs, and exits).
TEST(GdalReader, TsfStartsWithoutLoadingGdal) {
    const auto r = test::runCommand(std::string("LD_TRACE_LOADED_OBJECTS=1 ") + TSF_BINARY);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("libstdc++"), std::string::npos) << r.output;  // the listing is there
    EXPECT_EQ(r.output.find("libgdal"), std::string::npos) << r.output;
}

TEST(GdalReader, AMissingModuleIsAToolErrorNamingWhereItLooked) {
    const auto dir = test::scratchDir();
    ASSERT_TRUE(test::writeGeoTiff((dir / "dem.tif").string(), demSpec()));
    const std::string nowhere = (dir / "no-such-folder" / "tsf-gdal.so").string();
    const auto r = test::runTsf("info " + (dir / "dem.tif").string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;

    const auto missing = test::runCommand("TSF_GDAL_MODULE=" + nowhere + " " + TSF_BINARY + " info " +
                                          (dir / "dem.tif").string());
    EXPECT_EQ(missing.exit_code, test::kExitToolFailed) << missing.output;
    EXPECT_NE(missing.output.find("dem.tif: this raster is read through GDAL"), std::string::npos) << missing.output;
    EXPECT_NE(missing.output.find("was not found (looked in: " + nowhere + ")"), std::string::npos) << missing.output;

    // Something that is not a module: the loader's reason is passed on.
    test::writeText(dir / "not-a-module.so", "text");
    const auto foreign = test::runCommand("TSF_GDAL_MODULE=" + (dir / "not-a-module.so").string() + " " +
                                          TSF_BINARY + " info " + (dir / "dem.tif").string());
    EXPECT_EQ(foreign.exit_code, test::kExitToolFailed) << foreign.output;
    EXPECT_NE(foreign.output.find("not-a-module.so cannot be loaded"), std::string::npos) << foreign.output;
    // Formats tsf reads itself never need it.
    test::writeText(dir / "f.csv", "1,2\n3,4\n");
    EXPECT_EQ(test::runCommand("TSF_GDAL_MODULE=" + nowhere + " " + TSF_BINARY + " info " +
                               (dir / "f.csv").string()).exit_code, 0);
}

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

// A raster larger than tsf holds whole (3000 x 3000 = 9 M values) is read
// as 1500 x 1500 means of 2 x 2 pixels: every mean exact, pixels without data
// left out of their block's mean, a block without any no data; a class map
// by its most common class.
TEST(GdalReader, ALargeRasterIsReadAsBlockMeansOfItsPixelsWithData) {
    const auto dir = test::scratchDir("gdal_large");
    test::GeoTiffSpec spec;
    spec.cols = spec.rows = 3000;
    spec.nodata = -1;
    spec.values.resize(size_t(3000) * 3000);
    for (int r = 0; r < 3000; ++r)
        for (int c = 0; c < 3000; ++c) spec.values[size_t(r) * 3000 + size_t(c)] = float(r + c);
    spec.values[0] = -1;                                  // block (0, 0): one pixel without data
    for (int k : {2, 3, 3002, 3003}) spec.values[size_t(k)] = -1;  // block (1, 0): none with data
    const std::string path = (dir / "large.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(path, spec));
    const Raster r = readRaster(path);
    ASSERT_EQ(r.cols, 1500);
    ASSERT_EQ(r.rows, 1500);
    EXPECT_EQ(r.decimation, 2);
    EXPECT_DOUBLE_EQ(r.at(0, 0), (1.0 + 1.0 + 2.0) / 3);  // pixels (0,1), (1,0), (1,1): values r + c
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    for (int i : {1, 700, 1499})
        for (int j : {2, 999, 1499}) EXPECT_DOUBLE_EQ(r.at(j, i), 2.0 * i + 2.0 * j + 1.0) << j << "," << i;
    bool said = false;
    for (const ReadFact& f : r.facts) said = said || (f.name == "decimated" && f.value.find("3000 x 3000 px -> 1500 x 1500") == 0);
    EXPECT_TRUE(said);

    test::GeoTiffSpec classes = spec;
    classes.classes = true;
    classes.nodata.reset();
    for (int r = 0; r < 3000; ++r)
        for (int c = 0; c < 3000; ++c) classes.values[size_t(r) * 3000 + size_t(c)] = float((r % 2 == 0 && c % 2 == 0) ? 7 : 3);
    const std::string class_path = (dir / "classes.tif").string();
    ASSERT_TRUE(test::writeGeoTiff(class_path, classes));
    const Raster k = readRaster(class_path);
    ASSERT_EQ(k.cols, 1500);
    EXPECT_DOUBLE_EQ(k.at(10, 10), 3.0);  // three pixels of 3 to one of 7: the class, never a mean
}

// A 40 000 x 40 000 GeoTIFF (tiled, sparse: a few MB on disk; 6.4 GB as
// float32 pixels) becomes a model: read decimated strip by strip to 2000 x
// 2000 means of 20 x 20 pixels, the summary saying so, in well under 1 GB.
// The data is a 4000 x 4000 square of r + c in the middle; every other
// pixel is no data, and a block's mean counts only its pixels with data.
TEST(GdalReader, AFortyThousandSquareRasterIsReadDecimatedUnderAGigabyte) {
    const auto dir = test::scratchDir("gdal_huge");
    const std::string path = (dir / "huge.tif").string();
    {
        GDALAllRegister();
        char** options = nullptr;
        for (const char* kv : {"TILED=YES", "SPARSE_OK=TRUE", "COMPRESS=DEFLATE", "BIGTIFF=YES"})
            options = CSLAddString(options, kv);
        GDALDatasetH ds = GDALCreate(GDALGetDriverByName("GTiff"), path.c_str(), 40000, 40000, 1, GDT_Float32, options);
        CSLDestroy(options);
        ASSERT_NE(ds, nullptr);
        const double gt[6] = {500000, 10, 0, 6000000, 0, -10};
        GDALSetGeoTransform(ds, const_cast<double*>(gt));
        GDALRasterBandH band = GDALGetRasterBand(ds, 1);
        GDALSetRasterNoDataValue(band, -9999);
        std::vector<float> v(size_t(4000) * 4000);
        for (int r = 0; r < 4000; ++r)
            for (int c = 0; c < 4000; ++c) v[size_t(r) * 4000 + size_t(c)] = float(r + c);
        ASSERT_EQ(GDALRasterIO(band, GF_Write, 18000, 18000, 4000, 4000, v.data(), 4000, 4000, GDT_Float32, 0, 0), CE_None);
        GDALClose(ds);
    }
    EXPECT_LT(std::filesystem::file_size(path), uint64_t(64) << 20) << "the test file stays small on disk";
    const std::string out = (dir / "huge.stl").string();
    const auto [code, peak_mib] = test::runMeasured(std::string(TSF_BINARY) + " gen " + path + " --json -o " + out +
                                                    " > " + (dir / "huge.json").string() + " 2> " +
                                                    (dir / "huge.err").string());
    ASSERT_EQ(code, 0) << test::readText(dir / "huge.err");
    EXPECT_LT(peak_mib, 1024.0);
    // A long read says how far it has got.
    const std::string said = test::readText(dir / "huge.err");
    EXPECT_NE(said.find("reading 40000 x 40000 pixels"), std::string::npos) << said;
    EXPECT_NE(said.find("read 50 % of the rows"), std::string::npos) << said;
    const auto j = nlohmann::json::parse(test::readText(dir / "huge.json"));
    const std::string how = j["field"]["how"];
    EXPECT_NE(how.find("read decimated, each value the mean of about 20 x 20 of its pixels"), std::string::npos) << how;
    EXPECT_NE(how.find("2000 x 2000 px"), std::string::npos) << how;
    // No value beyond the largest block mean (rows and columns 3980..3999 of
    // the square: 2 x 3989.5), and the hexagons' means near it.
    const double top = j["scene"]["mapping"]["value_max"].get<double>();
    EXPECT_LE(top, 2 * 3989.5);
    EXPECT_GT(top, 7500.0);
    EXPECT_FALSE(j["scene"]["one_pillar_per_value"].get<bool>());
    EXPECT_TRUE(j["verify"]["passed"].get<bool>());
}

}  // namespace
}  // namespace tsf
