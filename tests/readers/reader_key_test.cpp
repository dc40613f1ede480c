// The model's key as a blind reader meets it: it opens with what the data
// is in the file's own words (a GeoTIFF band's description and units, a
// NetCDF variable's long_name, units and time step), says where the no-data
// is in words and which model of a series it is; its reader's part has no
// command-line option, e-notation or space-grouped digits (for every key
// the tests write); and its braille, read back with liblouis, says the same
// numbers and units as its text, in UEB and in EBAE.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <filesystem>
#include <regex>

#include "gen/key/braille_ready_file.h"
#include "gen/model/features/braille.h"
#include "tests/readers/geotiff_test_writer.h"
#include "tests/readers/netcdf_test_writer.h"
#include "tests/support/files.h"
#include "tests/support/reader_text.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

std::string joinedProblems(const std::string& text) {
    std::string all;
    for (const std::string& p : test::readerTextProblems(text)) all += p + "\n";
    return all;
}

/// A 12 x 10 elevation GeoTIFF, 100 m pixels (EPSG:32633), its band
/// described "elevation" in metres, no data (-9999) all round its border.
std::string elevationFile(const std::filesystem::path& dir) {
    test::GeoTiffSpec s;
    s.cols = 12, s.rows = 10, s.epsg = 32633, s.west = 500000, s.north = 5000000, s.pixel_w = s.pixel_h = 100;
    s.nodata = -9999;
    s.description = "elevation";
    s.units = "m";
    for (int r = 0; r < s.rows; ++r)
        for (int c = 0; c < s.cols; ++c)
            s.values.push_back(r == 0 || c == 0 || r == s.rows - 1 || c == s.cols - 1 ? -9999.0f : float(1000 + 150 * c + 20 * r));
    const std::string path = (dir / "dem.tif").string();
    EXPECT_TRUE(test::writeGeoTiff(path, s));
    return path;
}

TEST(ReaderKey, AGeoTiffKeyOpensWithTheBandsDescriptionAndSaysWhereTheNoDataIs) {
    const auto dir = test::scratchDir();
    const std::string tif = elevationFile(dir);
    const test::RunResult r = test::runTsf("gen " + tif + " -o " + (dir / "dem.stl").string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string key = test::readText(dir / "dem.key.txt");
    EXPECT_EQ(key.rfind("tsf model key\n\nElevation\n\nWhat it shows: elevation, in metres.", 0), 0u) << key;
    EXPECT_TRUE(has(key, "The data's own values go from 1170 to 2660 metres.")) << key;  // 1000+150+20 .. 1000+1650+160
    EXPECT_TRUE(has(key, "The data has no values around the border: the model leaves those places out")) << key;
    EXPECT_TRUE(has(key, "ground 1200 metres from west to east and 1000 metres from south to north, at a scale of 1 to "))
        << key;
    const std::string reader = test::readerPart(key);
    EXPECT_NE(reader.size(), key.size()) << "the key has its last section";
    EXPECT_EQ(joinedProblems(reader), "") << key;
    // tsf info says the same words.
    const test::RunResult info = test::runTsf("info " + tif, dir);
    EXPECT_TRUE(has(info.out, "\n  data      elevation, in m\n")) << info.out;
    // The processing is in the last section, after the reader's part.
    EXPECT_TRUE(has(key.substr(reader.size()), "How this model was made\n\nOne pillar per value")) << key;
}

/// The test's own NetCDF file (two variables; pr has long_name
/// "precipitation" and units "mm/day", three monthly steps).
std::string climateFile(const std::filesystem::path& dir) {
    const std::string path = (dir / "climate.nc").string();
    EXPECT_TRUE(test::writeNetCdf(path)) << "GDAL's netCDF driver (Debian libgdal32 has it)";
    return path;
}

TEST(ReaderKey, ANetCdfKeyOpensWithTheLongNameUnitsAndStep) {
    const auto dir = test::scratchDir();
    const std::string nc = climateFile(dir);
    const test::RunResult r =
        test::runTsf("gen " + nc + " --variable pr --band 2 --cell 20 -o " + (dir / "pr.stl").string(), dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string key = test::readText(dir / "pr.key.txt");
    EXPECT_EQ(key.rfind("tsf model key\n\nPrecipitation, 1 February 2000\n\n"
                        "What it shows: precipitation, in millimetres per day, for 1 February 2000.",
                        0),
              0u)
        << key;
    // Step 2: 200 + 10 * lat + lon, the fill value at (0, 0) no data.
    EXPECT_TRUE(has(key, "go from 201 to 234 millimetres per day.")) << key;
    EXPECT_TRUE(has(key, "The data has no values in the south-west corner: the model leaves that place out")) << key;
    EXPECT_EQ(joinedProblems(test::readerPart(key)), "") << key;
}

// --band 1-3: every key says which model of the series it is, on one scale.
TEST(ReaderKey, EveryKeyOfASeriesSaysWhichModelOfHowManyOnOneScale) {
    const auto dir = test::scratchDir();
    const std::string nc = climateFile(dir);
    const test::RunResult r = test::runTsf(
        "gen " + nc + " --variable pr --band 1-3 --cell 20 --preview " + (dir / "pr.png").string() + " -o " +
            (dir / "pr.stl").string(),
        dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    for (int k = 1; k <= 3; ++k) {
        const std::string key = test::readText(dir / ("pr-band-" + std::to_string(k) + ".key.txt"));
        EXPECT_TRUE(has(key, "This is model " + std::to_string(k) +
                                 " of 3 in a series, all on one height scale: a pillar of the same height means the same "
                                 "value in every model of the series."))
            << key;
        EXPECT_TRUE(std::filesystem::exists(dir / ("pr-band-" + std::to_string(k) + ".png")));
    }
    EXPECT_TRUE(has(r.out, "coloured on the series' one height scale")) << r.out;
}

/// The six-dot cells of a BRF (Braille ASCII back to cells; line ends and
/// form feeds become blank cells).
std::vector<uint8_t> brfCells(const std::string& brf) {
    std::array<int, 128> cell_of{};
    cell_of.fill(-1);
    for (int c = 0; c < 64; ++c) cell_of[size_t(brailleAsciiOf(uint8_t(c)))] = c;
    std::vector<uint8_t> cells;
    for (const char ch : brf) {
        if (ch == '\r') continue;
        if (ch == '\n' || ch == '\f') {
            if (!cells.empty() && cells.back() != 0) cells.push_back(0);
            continue;
        }
        const int c = cell_of[size_t(static_cast<unsigned char>(ch))];
        EXPECT_GE(c, 0) << "not Braille ASCII: " << int(ch);
        cells.push_back(uint8_t(c < 0 ? 0 : c));
    }
    return cells;
}

/// liblouis' EBAE back-translation (en-us-g1.ctb) ends a number at its
/// decimal point or thousands comma and reads the digits after it as the
/// letters a-j, though EBAE keeps the number going there (the forward
/// braille is the code's: number sign, digits, dots 4-6 or dot 2, digits):
/// the letters after a digit and '.' or ',' are read back as digits (and a
/// later thousands comma, which it gives as '1', as a comma).
std::string ebaeDigitsAfterPoint(const std::string& text) {
    std::string out;
    bool digits = false;  // inside a number, after its point or comma
    for (size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        const bool next_letter = k + 1 < text.size() && text[k + 1] >= 'a' && text[k + 1] <= 'j';
        if (digits && c >= 'a' && c <= 'j') {
            out += char(c == 'j' ? '0' : '1' + (c - 'a'));
            continue;
        }
        if (digits && c == '1' && next_letter) {
            out += ',';
            continue;
        }
        if ((c == '.' || c == ',') && next_letter && !out.empty() && std::isdigit(static_cast<unsigned char>(out.back()))) {
            out += c;
            digits = true;
            continue;
        }
        digits = digits && (c == ',' || c == '.') && next_letter;
        out += c;
    }
    return out;
}

/// Every number of the text with the word after it ("234 millimetres"),
/// lower case, in order.
std::vector<std::string> numbersWithUnits(std::string text) {
    for (char& c : text) c = char(std::tolower(static_cast<unsigned char>(c)));
    static const std::regex number(R"((\d[\d,]*(\.\d+)?)(\s+([a-z]+))?)");
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), number); it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1].str() + ((*it)[4].matched ? " " + (*it)[4].str() : ""));
    return out;
}

// The BRF read back with liblouis says the text's numbers and units, in
// order, in Unified English Braille (the default) and in EBAE
// (--braille-table en-us-g1.ctb); the key names its code.
TEST(ReaderKey, TheBrailleKeyReadBackSaysTheSameNumbersAndUnits) {
    const auto dir = test::scratchDir();
    const std::string nc = climateFile(dir);
    for (const std::string table : {"", "en-us-g1.ctb"}) {
        const std::string stem = (dir / ("pr" + table)).string();
        const test::RunResult r =
            test::runTsf("gen " + nc + " --variable pr --band 2 --cell 20 --scale --title Rain --units mm/day" +
                             (table.empty() ? "" : " --braille-table " + table) + " -o " + stem + ".stl",
                         dir);
        ASSERT_EQ(r.exit_code, 0) << r.output;
        // The model's stamp ends each key, for tsf verify, not for a reader:
        // on the BRF's last page as plain Braille ASCII, untranslated.
        auto beforeStamp = [](const std::string& key, const std::string& mark) { return key.substr(0, key.rfind(mark)); };
        const std::string text = beforeStamp(test::readText(stem + ".key.txt"), "Model stamp:");
        const std::string code = table.empty() ? "en-ueb-g1.ctb" : table;
        EXPECT_TRUE(has(text, table.empty() ? "Unified English Braille" : "en-us-g1.ctb")) << text;
        std::string back = backTranslateBraille(brfCells(beforeStamp(test::readText(stem + ".key.brf"), "MODEL STAMP:")), code);
        if (!table.empty()) back = ebaeDigitsAfterPoint(back);
        // The reader's part (in UEB the whole key: its last section too).
        const std::string body = text.substr(text.find("\n\n") + 2);
        const size_t made = back.find("How this model was made");
        ASSERT_NE(made, std::string::npos) << back;
        const std::vector<std::string> want =
            numbersWithUnits(table.empty() ? body : test::readerPart(text).substr(text.find("\n\n") + 2));
        const std::vector<std::string> got = numbersWithUnits(table.empty() ? back : back.substr(0, made));
        EXPECT_GT(want.size(), 20u);
        EXPECT_EQ(got, want) << code << "\n" << back;
        EXPECT_TRUE(has(back, "11.7 millimetres per day")) << back;
        EXPECT_TRUE(has(back, "5,560,000")) << back;
    }
}

// Every key a test run has written so far, and a set made here (a table
// of tiny values in kg m-2 s-1, one of millions, points, a class map, a
// coupon), reads well: no option, e-notation, space-grouped digits or
// arrow in the reader's part.
TEST(ReaderKey, NoKeysReadersPartHoldsAnOptionENotationOrSpaceGroupedDigits) {
    const auto dir = test::scratchDir();
    const std::string d = dir.string() + "/";
    std::string tiny, huge;
    for (int r = 0; r < 6; ++r) {
        for (int c = 0; c < 6; ++c) {
            tiny += (c ? "," : "") + std::to_string(1.5e-5 * (1 + r + c)).substr(0, 9);
            huge += (c ? "," : "") + std::to_string(int64_t(2'500'000) * (1 + r * c));
        }
        tiny += "\n", huge += "\n";
    }
    test::writeText(dir / "tiny.csv", tiny);
    test::writeText(dir / "huge.csv", huge);
    const std::string examples = test::sourcePath("examples/");
    for (const std::string& args : std::vector<std::string>{
             d + "tiny.csv --units 'kg m-2 s-1' --scale -o " + d + "tiny.stl",
             d + "huge.csv --units people --title People -o " + d + "huge.stl",
             examples + "airports-europe.csv --points x=lon,y=lat --bins 20 --units airports -o " + d + "airports.stl",
             examples + "volcano.csv --mirror --cell 6 -o " + d + "volcano.stl"}) {
        const test::RunResult r = test::runTsf("gen " + args, dir);
        ASSERT_EQ(r.exit_code, 0) << args << "\n" << r.output;
    }
    ASSERT_EQ(test::runTsf("coupon -o " + d + "coupon.stl", dir).exit_code, 0);
    const std::string tiny_key = test::readText(dir / "tiny.key.txt");
    EXPECT_TRUE(has(tiny_key, "kilograms per square metre per second")) << tiny_key;
    EXPECT_TRUE(has(tiny_key, "0.000015")) << tiny_key;
    EXPECT_TRUE(has(test::readText(dir / "huge.key.txt"), "2,500,000")) << test::readText(dir / "huge.key.txt");
    const std::string airports = test::readText(dir / "airports.key.txt");
    EXPECT_TRUE(has(airports, "What it shows: the points of the file airports-europe.csv, as airports.")) << airports;
    EXPECT_TRUE(has(airports, "stands for how many points fall in it")) << airports;
    const std::string coupon = test::readText(dir / "coupon.key.txt");
    EXPECT_TRUE(has(coupon, "What it shows: a calibration coupon")) << coupon;
    EXPECT_TRUE(has(coupon, "The lesson:")) << coupon;

    // Every key under the tests' scratch folders.
    int keys = 0;
    const auto root = std::filesystem::path(TSF_TEST_SCRATCH).parent_path();
    for (const auto& e : std::filesystem::recursive_directory_iterator(root)) {
        const std::string name = e.path().filename().string();
        if (!e.is_regular_file() || name.size() < 8 || name.substr(name.size() - 8) != ".key.txt") continue;
        const std::string key = test::readText(e.path());
        if (key.rfind("tsf model key\n", 0) != 0) continue;  // a user's file a test left where a key would go
        ++keys;
        EXPECT_EQ(joinedProblems(test::readerPart(key)), "") << e.path() << "\n" << key;
        EXPECT_TRUE(has(key, "\nHow this model was made\n")) << e.path();
    }
    EXPECT_GE(keys, 5);
}

}  // namespace
}  // namespace tsf
