// The whole program under random option combinations: random small fields
// (grids with gaps and no-data, clustered points, constants, one row or one
// column) and random sets of `tsf gen` options (legend, scale, marks,
// mirror, halves, tilt, culling, transfer, snapping, printer, formats,
// parts). Every run must end in a model that `tsf verify --scene` passes
// (exit 0) or in a clear error (exit 2 with "error:"); never the
// self-check's exit 1, an external-tool exit 3 without a tool, a crash or
// a hang. A failure prints the field and the command that reproduce it.
//
// CI runs TSF_COMBINATION_RUNS (default 40) combinations from a fixed seed;
// run longer on demand with another seed:
//   TSF_COMBINATION_RUNS=2000 TSF_COMBINATION_SEED=7 build/tests/test_gen --gtest_filter='Combination*'
// What it finds becomes a regression test of its own.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include "tests/support/run.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using test::runTsf;

long envOr(const char* name, long fallback) {
    const char* v = std::getenv(name);
    return v && *v ? std::strtol(v, nullptr, 10) : fallback;
}

struct Case {
    std::string field;    ///< the input file's text
    bool points = false;  ///< a point table, not a grid
    bool lonlat = false;  ///< its columns are lon, lat (projected with PROJ unless asked not to)
    std::string options;  ///< for tsf gen, without the input and -o
    std::string output;   ///< file name of the model
};

Case randomCase(std::mt19937_64& rng) {
    auto chance = [&](double p) { return std::uniform_real_distribution<double>(0, 1)(rng) < p; };
    auto pick = [&](std::initializer_list<const char*> v) { return std::string(*(v.begin() + std::uniform_int_distribution<size_t>(0, v.size() - 1)(rng))); };
    auto integer = [&](int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng); };
    Case c;
    c.points = chance(0.4);
    std::ostringstream f;
    f.precision(6);
    if (c.points) {
        // Clustered points: a few centres, each point near one; sometimes
        // repeated; sometimes longitude / latitude.
        c.lonlat = chance(0.3);
        f << (c.lonlat ? "lon,lat\n" : "x,y\n");
        const int n = chance(0.2) ? integer(1, 5) : integer(6, 80);
        std::vector<std::pair<double, double>> centres;
        for (int k = integer(1, 4); k > 0; --k) centres.push_back({integer(-50, 50), integer(-50, 50)});
        const double spread = chance(0.2) ? 1e-3 : double(integer(1, 30));
        std::normal_distribution<double> d(0, spread);
        for (int k = 0; k < n; ++k) {
            const auto& ctr = centres[size_t(integer(0, int(centres.size()) - 1))];
            f << ctr.first + d(rng) << "," << ctr.second + d(rng) << "\n";
        }
    } else {
        // A grid: one row, one column or a block; values smooth, random or
        // constant; some cells empty (no data).
        const int shape = integer(0, 5);
        const int cols = shape == 0 ? 1 : integer(2, 14), rows = shape == 1 ? 1 : integer(2, 12);
        const int kind = integer(0, 3);
        const double empty = chance(0.5) ? 0.0 : 0.25;
        for (int r = 0; r < rows; ++r) {
            for (int col = 0; col < cols; ++col) {
                if (col) f << ",";
                if (chance(empty)) continue;
                const double v = kind == 0 ? 3.0 : kind == 1 ? double(integer(-5, 100)) : kind == 2 ? double(r * cols + col) : double(integer(0, 1));
                f << v;
            }
            f << "\n";
        }
    }
    c.field = f.str();

    std::string o;
    if (c.points) {
        o += c.lonlat ? " --points x=lon,y=lat" : " --points x=x,y=y";
        if (c.lonlat && chance(0.3)) o += " --project " + pick({"equal-area", "equirect", "none", "EPSG:3035"});
        if (chance(0.5)) o += " --bins " + std::to_string(integer(1, 40));
        if (chance(0.2)) o += " --tilt points";
    } else {
        if (chance(0.15)) o += " --bins " + std::to_string(integer(2, 60));
        if (chance(0.15)) o += " --tilt gradient";
    }
    const bool mirror = chance(0.25);
    if (mirror) {
        o += " --mirror";
        if (chance(0.3)) o += " --halves";
    }
    if (chance(0.35)) o += " --title " + pick({"x", "Rain", "T"});
    if (chance(0.3)) o += " --units " + pick({"mm", "airports", "u"});
    if (chance(0.25)) o += " --scale";
    if (chance(0.3)) o += " --marks-on " + pick({"data", "tab"});
    if (chance(0.1)) o += " --no-notch";
    if (chance(0.1)) o += " --no-triangle";
    if (chance(0.25)) o += " --cull " + pick({"hull", "concave", "none"});
    if (chance(0.2)) o += " --transfer " + pick({"sqrt", "log", "linear"});
    if (chance(0.15)) o += " --height " + pick({"0", "5", "60"});
    if (chance(0.15)) o += " --base " + pick({"0.6", "1", "4"});
    if (chance(0.15)) o += " --layer " + pick({"0.1", "0.2", "0.3"});
    if (chance(0.1)) o += " --snap 1e-06";
    if (chance(0.15)) o += " --bed " + pick({"100x100", "220x220", "60x60"});
    else if (chance(0.15)) o += " --cell " + pick({"2", "5", "12"});
    if (chance(0.1)) o += " --no-texture-structural";
    if (chance(0.05)) o += " --steepness 3";
    c.options = o;
    const std::string format = pick({"stl", "stl", "3mf", "off", "obj"});
    if (format == "3mf" && chance(0.5)) c.options += " --parts";
    c.output = "model." + format;
    return c;
}

TEST(CombinationFuzz, RandomOptionsOnRandomFieldsGiveAVerifiedModelOrAClearError) {
    const long runs = envOr("TSF_COMBINATION_RUNS", 40);
    const uint64_t seed = uint64_t(envOr("TSF_COMBINATION_SEED", 20261126));
    std::mt19937_64 rng(seed);
    const fs::path dir = test::scratchDir();
    int made = 0, refused = 0;
    std::map<std::string, int> reasons;
    for (long run = 0; run < runs; ++run) {
        const Case c = randomCase(rng);
        const fs::path in = dir / (c.points ? "field_points.csv" : "field_grid.csv"), out = dir / c.output;
        for (const auto& e : fs::directory_iterator(dir)) fs::remove_all(e.path());
        test::writeText(in, c.field);
        const std::string gen = "gen " + in.string() + c.options + " -o " + out.string();
        const test::RunResult g = runTsf(gen);
        const std::string repro = "run " + std::to_string(run) + " of seed " + std::to_string(seed) + ":\n  tsf " + gen +
                                  "\nfield:\n" + c.field.substr(0, 2000) + "\noutput:\n" + g.output.substr(0, 3000);
        if (g.exit_code == test::kExitBadInput) {
            const size_t at = g.output.find("error: ");
            EXPECT_NE(at, std::string::npos) << repro;
            // The reason, up to its first colon: "--title/--units", "--halves", ...
            if (at != std::string::npos) {
                const std::string reason = g.output.substr(at + 7, 60);
                ++reasons[reason.substr(0, std::min(reason.find(':'), reason.find('\n')))];
            }
            ++refused;
            continue;
        }
        if (g.exit_code != test::kExitOk) {
            ADD_FAILURE() << "exit " << g.exit_code << ", " << repro;
            continue;
        }
        ++made;
        // Models cut into halves are written as two files, each with its sidecar.
        std::vector<fs::path> models;
        for (const auto& e : fs::directory_iterator(dir))
            if (e.path().extension() == out.extension() && e.path().filename().string().rfind("model", 0) == 0)
                models.push_back(e.path());
        EXPECT_FALSE(models.empty()) << repro;
        for (const fs::path& m : models) {
            const fs::path sidecar = m.string() + ".scene.json";
            if (!fs::exists(sidecar)) continue;
            const test::RunResult v = runTsf("verify " + m.string() + " --scene " + sidecar.string());
            EXPECT_EQ(v.exit_code, test::kExitOk) << repro << "\nverify " << m << ":\n" << v.output.substr(0, 3000);
        }
    }
    // The mix reaches both outcomes, so neither path goes untested.
    EXPECT_GT(made, 0);
    std::printf("combination fuzz: %d models made and verified, %d refused with exit 2, seed %llu\n", made, refused,
                (unsigned long long)seed);
    for (const auto& [reason, n] : reasons) std::printf("  %4d refused: %s\n", n, reason.c_str());
}

}  // namespace
}  // namespace tsf
