// Numerical and shape extremes end to end: every stage a user runs, on the
// fields that break tools. Each field gives a verified model or a clear error
// with exit 2: never a crash, an assertion abort, a hang or silent garbage.
//
// Stages per field: `tsf gen` (its self-check verifies the direct mesh
// against the Scene), `tsf verify` of that mesh with the scene sidecar,
// `tsf render` of the OpenSCAD file through OpenSCAD and `tsf verify` of what
// OpenSCAD made against the same sidecar, and `tsf feel` on the same field
// with the simulated hand. The 2000 x 2000 field is generated once, its peak
// memory measured (getrusage of the child) against the bound docs/limits.md
// states; it is not rendered through OpenSCAD (only small fields are).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include "tests/support/run.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using test::kExitBadInput;
using test::kExitOk;
using test::runTsf;
using test::scratchDir;
using test::writeText;

// One row per line, values as written; a std::string so a test can spell
// values the way a file would ("1e308", "4.9e-324", "nan", "inf").
std::string csvOf(const std::vector<std::vector<std::string>>& rows) {
    std::string out;
    for (const auto& r : rows) {
        for (size_t c = 0; c < r.size(); ++c) out += (c ? "," : "") + r[c];
        out += "\n";
    }
    return out;
}

// A cols x rows grid of `fill` with the listed cells (col, row, value) set.
std::string gridCsv(int cols, int rows, const std::string& fill,
                    const std::vector<std::tuple<int, int, std::string>>& cells = {}) {
    std::vector<std::vector<std::string>> g(size_t(rows), std::vector<std::string>(size_t(cols), fill));
    for (const auto& [c, r, v] : cells) g[size_t(r)][size_t(c)] = v;
    return csvOf(g);
}

struct Extreme {
    std::string name;
    std::string csv;
    std::string options;      ///< extra gen/feel options
    bool model = true;        ///< a verified model; false: exit 2
    std::string message;      ///< with model == false: part of the error
};

std::vector<Extreme> extremes() {
    const std::string dbl_max = "1.7976931348623157e308";
    return {
        {"one_by_one", "7\n", ""},
        {"one_row", "1,2,3,4,5,6\n", ""},
        {"one_column", "1\n2\n3\n4\n5\n6\n", ""},
        {"one_nonzero_cell", gridCsv(5, 5, "0", {{2, 2, "4"}}), ""},
        {"all_zero", gridCsv(4, 4, "0"), ""},
        {"constant", gridCsv(4, 4, "2.5"), ""},
        // Neighbours 1e-12 apart with the baseline at the smallest value:
        // the whole relief is made of differences a double barely holds.
        {"picometre_steps", csvOf({{"1", "1.000000000001", "1.000000000002"}, {"1.000000000003", "1.000000000004", "1.000000000005"}}),
         "--baseline min"},
        // The assertion abort of issue 15 (exit 134): the span overflows a double.
        {"plus_minus_1e308", csvOf({{"1e308", "-1e308"}, {"-1e308", "1e308"}}), ""},
        {"plus_minus_dbl_max", csvOf({{dbl_max, "-" + dbl_max, "0"}, {"0", dbl_max, "-" + dbl_max}}), ""},
        {"plus_minus_1e_minus_308", csvOf({{"1e-308", "-1e-308"}, {"-1e-308", "1e-308"}}), ""},
        {"denormals", csvOf({{"4.9e-324", "1e-323", "0"}, {"2.5e-320", "0", "4.9e-324"}}), ""},
        {"mixed_signs", csvOf({{"-3", "2", "-1"}, {"4", "-5", "6"}, {"-7", "8", "-9"}}), ""},
        {"nan_cells", csvOf({{"1", "nan", "3"}, {"nan", "5", "nan"}, {"7", "nan", "9"}}), ""},
        // Found by the sanitizer run: a mirrored slab only the base thick had
        // no room for a pit from both faces.
        {"flat_mirrored_with_nan", csvOf({{"nan", "0"}, {"0", "0"}}), "--mirror --cull none"},
        {"checkerboard", [] {
             std::vector<std::vector<std::string>> g(6, std::vector<std::string>(6));
             for (int r = 0; r < 6; ++r)
                 for (int c = 0; c < 6; ++c) g[size_t(r)][size_t(c)] = (r + c) % 2 ? "1" : "0";
             return csvOf(g);
         }(), ""},
        {"sparse_islands", gridCsv(14, 12, "0", {{1, 1, "5"}, {2, 1, "5"}, {1, 2, "5"}, {12, 10, "3"}, {7, 3, "9"}}), ""},
        {"collinear_cells", gridCsv(9, 7, "0", {{1, 3, "3"}, {4, 3, "3"}, {7, 3, "3"}}), ""},
        // Clear errors.
        {"infinite_cell", csvOf({{"1", "inf", "3"}, {"4", "5", "6"}}), "", false, "infinite"},
        {"overflowing_number", csvOf({{"1", "1e309"}}), "", false, "1e309"},
        {"all_nan", csvOf({{"nan", "nan"}, {"nan", "nan"}}), "", false, "no data"},
        {"value_max_below_baseline", gridCsv(3, 3, "2", {{1, 1, "5"}}), "--baseline 4 --value-max 3", false,
         "must be above the baseline"},
        {"value_max_at_baseline", gridCsv(3, 3, "2", {{1, 1, "5"}}), "--value-max 0", false,
         "must be above the baseline"},
        {"baseline_above_every_value", gridCsv(3, 3, "2", {{1, 1, "5"}}), "--baseline 100", false,
         "every value is below the baseline"},
    };
}

nlohmann::json lastJson(const std::string& out) {
    const size_t start = out.find('{');
    if (start == std::string::npos) return nlohmann::json();
    return nlohmann::json::parse(out.substr(start), nullptr, false);
}

void PrintTo(const Extreme& x, std::ostream* os) { *os << x.name; }

class Extremes : public ::testing::TestWithParam<Extreme> {};

TEST_P(Extremes, EveryStageGivesAVerifiedModelOrExitTwo) {
    const Extreme& x = GetParam();
    const fs::path dir = scratchDir("extremes_" + x.name);
    const std::string field = (dir / "field.csv").string();
    writeText(field, x.csv);
    const std::string stl = (dir / "m.stl").string(), scad = (dir / "m.scad").string();
    const std::string sidecar = stl + ".scene.json";

    const test::RunResult gen =
        runTsf("gen " + field + " " + x.options + " -o " + stl + " --scad " + scad + " --json", dir);
    const test::RunResult feel =
        runTsf("feel " + field + " " + x.options + " --device sim --trajectory sweep --max-force 5 --json", dir);
    if (!x.model) {
        EXPECT_EQ(gen.exit_code, kExitBadInput) << gen.output;
        EXPECT_NE(gen.err.find(x.message), std::string::npos) << gen.err;
        EXPECT_FALSE(fs::exists(stl));
        EXPECT_EQ(feel.exit_code, kExitBadInput) << feel.output;
        EXPECT_NE(feel.err.find(x.message), std::string::npos) << feel.err;
        return;
    }

    ASSERT_EQ(gen.exit_code, kExitOk) << gen.output;
    const nlohmann::json summary = lastJson(gen.out);
    ASSERT_TRUE(summary.is_object()) << gen.out;
    EXPECT_TRUE(summary["verify"]["passed"].get<bool>()) << summary["verify"].dump(2);
    // A readable scale, never "1 mm = inf data units" or "nan".
    const test::RunResult info = runTsf("info " + field + " " + x.options, dir);
    ASSERT_EQ(info.exit_code, kExitOk) << info.output;
    const size_t heights = info.out.find("  heights");
    ASSERT_NE(heights, std::string::npos) << info.out;
    const std::string heights_line = info.out.substr(heights, info.out.find('\n', heights) - heights);
    EXPECT_EQ(heights_line.find("inf"), std::string::npos) << heights_line;
    EXPECT_EQ(heights_line.find("nan"), std::string::npos) << heights_line;

    const test::RunResult direct = runTsf("verify " + stl + " --scene " + sidecar, dir);
    EXPECT_EQ(direct.exit_code, kExitOk) << direct.output;

    // What OpenSCAD makes of the same model, judged against the same Scene.
    const std::string rendered = (dir / "m.openscad.stl").string();
    const test::RunResult render = runTsf("render " + scad + " -o " + rendered, dir);
    ASSERT_EQ(render.exit_code, kExitOk) << render.output;
    const test::RunResult judged = runTsf("verify " + rendered + " --scene " + sidecar, dir);
    EXPECT_EQ(judged.exit_code, kExitOk) << judged.output;

    // Felt: finite forces within the limit, the surface actually touched.
    ASSERT_EQ(feel.exit_code, kExitOk) << feel.output;
    const nlohmann::json felt = lastJson(feel.out);
    ASSERT_TRUE(felt.is_object()) << feel.out;
    const nlohmann::json& forces = felt["forces"];
    ASSERT_TRUE(forces["max_N"].is_number()) << forces.dump();  // NaN would be written as null
    EXPECT_LE(forces["max_N"].get<double>(), 5.0);
    EXPECT_GT(forces["max_N"].get<double>(), 0.0) << forces.dump();
    EXPECT_GT(forces["contact_ticks"].get<int64_t>(), 0) << forces.dump();
    EXPECT_EQ(forces["rejected_ticks"].get<int64_t>(), 0) << forces.dump();
    ASSERT_TRUE(felt["relief"]["felt_height_m"].is_number());
}

INSTANTIATE_TEST_SUITE_P(Fields, Extremes, ::testing::ValuesIn(extremes()),
                         [](const ::testing::TestParamInfo<Extreme>& info) { return info.param.name; });

// The stated bound for a 2000 x 2000 grid CSV (docs/limits.md): the raster
// (8 bytes a cell, 32 MB), the file's bytes (about 12 MB) and the resampled
// model's mesh and self-check.
constexpr double kBigGridPeakMiB = 200.0;

TEST(ExtremesBig, TwoThousandSquaredCellsStayWithinTheStatedMemory) {
    const fs::path dir = scratchDir("extremes_2000");
    const fs::path field = dir / "big.csv";
    {
        std::ofstream f(field);
        for (int r = 0; r < 2000; ++r) {
            for (int c = 0; c < 2000; ++c) f << (c ? "," : "") << (r * c) % 97;
            f << "\n";
        }
    }
    const fs::path stl = dir / "big.stl";
    const auto [code, peak_mib] = test::runMeasured(std::string(TSF_BINARY) + " gen " + field.string() + " -o " +
                                              stl.string() + " --json >" + (dir / "out.json").string() + " 2>" +
                                              (dir / "err.txt").string());
    ASSERT_EQ(code, kExitOk) << test::readText(dir / "err.txt");
    const nlohmann::json j = lastJson(test::readText(dir / "out.json"));
    EXPECT_TRUE(j["verify"]["passed"].get<bool>()) << j.dump(2);
    EXPECT_EQ(j["scene"]["one_pillar_per_value"].get<bool>(), false) << "a grid this large is resampled";
    EXPECT_LT(peak_mib, kBigGridPeakMiB) << "peak resident memory of tsf gen on 2000 x 2000 cells";
    std::fprintf(stderr, "2000 x 2000 grid: peak %.0f MiB\n", peak_mib);
}

}  // namespace
}  // namespace tsf
