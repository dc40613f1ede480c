// End-to-end: the files teachers and researchers actually have (spreadsheet
// exports, -9999 placeholders) give the model they expect, and `tsf info`
// says what it detected.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "tests/support/run.h"

namespace tsf {
namespace {
using test::runTsf;
using test::scratchDir;
using test::writeText;

nlohmann::json infoJson(const std::string& args) {
    const auto r = runTsf("info " + args + " --json");
    EXPECT_EQ(r.exit_code, 0) << r.output;
    const size_t brace = r.output.find('{');
    return brace == std::string::npos ? nlohmann::json() : nlohmann::json::parse(r.output.substr(brace));
}

// A mistake in an option is answered with the option and a value that
// works: a wrong --delimiter (the header is one field that splits at
// another), --bins or --bin too fine for the hexagon limit (the value
// suggested is then accepted), --project and --crs that PROJ does not
// know (what forms are accepted, not GDAL's "unknown error"), and a CSV
// saved as UTF-16 (how to save it as UTF-8).
TEST(InputCli, MistakesNameTheOptionAndAValueThatWorks) {
    const auto dir = scratchDir();
    writeText(dir / "p.csv", "lon,lat,w\n10,50,1\n11,51,2\n12,52,3\n10.5,50.5,4\n");
    const std::string p = (dir / "p.csv").string() + " --points x=lon,y=lat";
    const auto has = [](const test::RunResult& r, const std::string& text) {
        return r.exit_code == test::kExitBadInput && r.output.find(text) != std::string::npos;
    };
    const auto semicolon = runTsf("info " + p + " --delimiter ';'");
    EXPECT_TRUE(has(semicolon, "The delimiter seems wrong: the line was split at ';' (--delimiter ;), and split at ','"))
        << semicolon.output;
    EXPECT_TRUE(has(semicolon, "give --delimiter ,")) << semicolon.output;

    const auto bins = runTsf("info " + p + " --bins 5000");
    const size_t at = bins.output.find("give --bins ");
    ASSERT_TRUE(has(bins, "give --bins ") && at != std::string::npos) << bins.output;
    const int fewer = std::stoi(bins.output.substr(at + 12));
    EXPECT_LT(fewer, 5000);
    EXPECT_EQ(runTsf("info " + p + " --bins " + std::to_string(fewer)).exit_code, 0) << "the value suggested works";
    EXPECT_EQ(runTsf("info " + p + " --bins " + std::to_string(fewer + 1)).exit_code, test::kExitBadInput)
        << "and is the largest that does";
    const auto bin = runTsf("info " + p + " --bin 0.01");
    const size_t bin_at = bin.output.find("give a --bin of at least ");
    ASSERT_TRUE(has(bin, "give a --bin of at least ") && bin_at != std::string::npos) << bin.output;
    EXPECT_EQ(runTsf("info " + p + " --bin " + bin.output.substr(bin_at + 25, bin.output.find_first_of(" \n", bin_at + 25) - bin_at - 25))
                  .exit_code,
              0);

    const auto project = runTsf("info " + p + " --project bogus");
    EXPECT_TRUE(has(project, "--project 'bogus' is not a projection")) << project.output;
    EXPECT_TRUE(has(project, "EPSG:3035")) << project.output;
    EXPECT_EQ(project.output.find("unknown GDAL error"), std::string::npos) << project.output;
    const auto crs = runTsf("info " + p + " --crs nonsense");
    EXPECT_TRUE(has(crs, "--crs 'nonsense' is not a coordinate reference system")) << crs.output;
    EXPECT_EQ(crs.output.find("unknown GDAL error"), std::string::npos) << crs.output;

    // UTF-16 with a byte-order mark, and without one, as points and as a grid.
    const std::string text = "lon,lat,w\n10,50,1\n11,51,2\n12,52,3\n10.5,50.5,4\n";
    std::string le = "\xFF\xFE", be_no_mark;
    for (const char c : text) {
        le += std::string(1, c) + '\0';
        be_no_mark += std::string(1, '\0') + c;
    }
    writeText(dir / "le.csv", le);
    writeText(dir / "be.csv", be_no_mark);
    for (const char* name : {"le.csv", "be.csv"})
        for (const std::string& as : {std::string(" --points x=lon,y=lat"), std::string()}) {
            const auto r = runTsf("info " + (dir / name).string() + as);
            EXPECT_TRUE(has(r, std::string(name) + ": is UTF-16 text")) << name << as << ": " << r.output;
            EXPECT_TRUE(has(r, "save it as UTF-8")) << r.output;
        }
}

TEST(InputCli, SpreadsheetExportWithDecimalCommas) {
    const auto dir = scratchDir();
    writeText(dir / "de.csv", "Nord;Mitte;Sued\n1,5;2,5;N/A\n3,25;4;5\n");
    const auto j = infoJson((dir / "de.csv").string());
    EXPECT_EQ(j["read"]["detected"]["delimiter"], "semicolon (detected)");
    EXPECT_EQ(j["read"]["detected"]["decimal mark"], "comma (detected)");
    EXPECT_EQ(j["read"]["detected"]["header"], "line 1 skipped");
    EXPECT_EQ(j["read"]["nodata_values"], 1);
    EXPECT_EQ(j["read"]["min"], 1.5);
    EXPECT_EQ(j["read"]["max"], 5.0);
    const auto text = runTsf("info " + (dir / "de.csv").string());
    EXPECT_NE(text.output.find("decimal mark: comma (detected)"), std::string::npos) << text.output;
    EXPECT_NE(text.output.find("1 of 6 without data"), std::string::npos) << text.output;
    const auto gen = runTsf("gen " + (dir / "de.csv").string() + " -o " + (dir / "de.stl").string());
    EXPECT_EQ(gen.exit_code, 0) << gen.output;
}

TEST(InputCli, PandasIndexColumnIsReportedAndDropped) {
    const auto dir = scratchDir();
    writeText(dir / "pd.csv", ",0,1,2\n0,1,2,3\n1,4,5,6\n");
    const auto j = infoJson((dir / "pd.csv").string());
    EXPECT_EQ(j["read"]["cols"], 3);
    EXPECT_TRUE(j["read"]["detected"].contains("index column")) << j.dump();
}

TEST(InputCli, NoDataPlaceholderIsNamedAndTaken) {
    const auto dir = scratchDir();
    writeText(dir / "dem.csv", "-9999,120,130\n110,125,-9999\n100,105,115\n");
    // Not given: the relief would be a sliver on top of -9999, and tsf says so.
    const auto guess = runTsf("info " + (dir / "dem.csv").string());
    EXPECT_NE(guess.output.find("give --nodata -9999"), std::string::npos) << guess.output;
    const auto j = infoJson((dir / "dem.csv").string() + " --nodata -9999");
    EXPECT_EQ(j["read"]["nodata_values"], 2);
    EXPECT_EQ(j["read"]["min"], 100.0);
    EXPECT_EQ(j["read"]["max"], 130.0);
    EXPECT_EQ(j["read"]["detected"]["no-data value"], "-9999 (--nodata), 2 cells");
}

}  // namespace
}  // namespace tsf
