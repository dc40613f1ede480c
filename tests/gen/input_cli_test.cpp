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
