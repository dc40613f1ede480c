// The summary tsf gen prints, as a blind maker hears it with a screen
// reader: what was written and what to check first, the model's size and
// heights next, details last; short lines, "by" for dimensions, no arrows;
// and --json keeps its keys.
#include <gtest/gtest.h>

#include <regex>
#include <sstream>

#include <nlohmann/json.hpp>

#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

TEST(GenSummary, EssentialsFirstInShortLinesAScreenReaderReadsWell) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "v.stl").string();
    const test::RunResult r =
        test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " --title Volcano --scale -o " + model, dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const std::string& out = r.out;
    const size_t wrote = out.find("\nWrote:\n"), check = out.find("\nCheck:\n"), size = out.find("\nModel:\n  size "),
                 details = out.find("\nDetails:\n");
    ASSERT_NE(wrote, std::string::npos) << out;
    EXPECT_TRUE(wrote < check && check < size && size < details) << out;
    EXPECT_NE(out.find("  " + model + " (model)"), std::string::npos) << out;
    EXPECT_LT(out.find("  verify    passed: "), size) << out;
    EXPECT_LT(out.find("  heights   linear: value 0 at the floor; value 193.75 at 20.00 mm above it;"), details) << out;
    EXPECT_GT(out.find("  input     mean of the pixels"), details) << out;
    // Words for arrows and "by" for dimensions.
    EXPECT_EQ(out.find("->"), std::string::npos) << out;
    EXPECT_FALSE(std::regex_search(out, std::regex(R"(\d x \d)"))) << out;
    EXPECT_FALSE(std::regex_search(out, std::regex(R"(\d[eE][+-]?\d)"))) << out;
    // Short lines: a line over 80 characters is one item that cannot be cut
    // (no "; " or ", " in it after its label, but in a short bracket such
    // as a place "(76.0, 38.5)", which stays whole).
    std::istringstream lines(out);
    int longest = 0, total = 0;
    for (std::string line; std::getline(lines, line); ++total) {
        longest = std::max(longest, int(line.size()));
        if (line.size() > 80) {
            const std::string rest = std::regex_replace(line.substr(12), std::regex(R"(\([^()]{0,22}\))"), "()");
            EXPECT_EQ(rest.find("; "), std::string::npos) << line;
            EXPECT_EQ(rest.find(", "), std::string::npos) << line;
        }
    }
    EXPECT_GT(total, 20);

    // --json: the keys it always had, and the data's own words added.
    const test::RunResult j = test::runTsf("gen " + test::sourcePath("examples/volcano.csv") + " --json -o " + model, dir);
    ASSERT_EQ(j.exit_code, 0) << j.output;
    const auto json = nlohmann::json::parse(j.out);
    for (const char* key : {"input", "field", "scene", "ground", "classes", "mesh", "outputs", "timings_ms", "verify", "printer"})
        EXPECT_TRUE(json.contains(key)) << key;
    EXPECT_TRUE(json["field"].contains("how"));
    EXPECT_TRUE(json["field"].contains("pitch_data_units"));
    EXPECT_EQ(json["field"]["per_hexagon"], "the mean of the values that fall in it");
    EXPECT_TRUE(json["verify"].contains("passed"));
}

}  // namespace
}  // namespace tsf
