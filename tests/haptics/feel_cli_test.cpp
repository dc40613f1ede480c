// `tsf feel` end to end: the binary on small fields, as a user runs it.
#include <cstdio>
#include <cmath>
#include <cstdlib>
#include <algorithm>
#include <array>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <fcntl.h>
#include <png.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"

#include "tests/support/run.h"

namespace fs = std::filesystem;

namespace {

const fs::path kScratch = fs::path(TSF_TEST_SCRATCH) / "feel";

/// A file name unique to the running test (ctest may run tests in parallel).
fs::path scratchFile(const std::string& suffix) {
    return kScratch / (std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()) + "-" + suffix);
}

/// A 12 x 9 field with one hill and a no-data corner, written once.
std::string hillField() {
    fs::create_directories(kScratch);
    const fs::path p = scratchFile("hill.csv");
    std::ofstream f(p);
    for (int r = 0; r < 9; ++r) {
        for (int c = 0; c < 12; ++c) {
            if (c) f << ",";
            if (r == 0 && c == 0) f << "NaN";
            else f << 10.0 * std::max(0, 16 - (c - 6) * (c - 6) - (r - 4) * (r - 4));
        }
        f << "\n";
    }
    return p.string();
}

std::vector<std::vector<std::string>> readCsv(const fs::path& p) {
    std::ifstream f(p);
    std::vector<std::vector<std::string>> rows;
    std::string line;
    while (std::getline(f, line)) {
        std::vector<std::string> cells;
        std::stringstream ss(line);
        std::string cell;
        while (std::getline(ss, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

}  // namespace

TEST(FeelCli, SimSweepWritesAForceLogAndAPlot) {
    const fs::path log = kScratch / "forces.csv", plot = kScratch / "forces.png";
    fs::remove(log);
    fs::remove(plot);
    const tsf::test::RunResult r = tsf::test::runTsf("feel " + hillField() + " --device sim --trajectory sweep --max-force 5 --log " + log.string() +
                      " --plot " + plot.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("zero force sent"), std::string::npos) << r.output;
    const auto rows = readCsv(log);
    ASSERT_GT(rows.size(), 1000u);
    ASSERT_EQ(rows[0][0], "t_s");
    ASSERT_EQ(rows[0][7], "force_N");
    size_t contact = 0;
    double prev_t = -1.0;
    for (size_t i = 1; i < rows.size(); ++i) {
        const double t = std::stod(rows[i][0]), f = std::stod(rows[i][7]);
        ASSERT_GT(t, prev_t);
        prev_t = t;
        ASSERT_LE(f, 5.0 + 1e-4) << "row " << i;  // the limit asked for, never more
        if (rows[i][11] == "1") ++contact;
    }
    EXPECT_GT(contact, rows.size() / 4) << "the sweep must press on the surface";
    // The plot is a real PNG of the field (12 x 9 cells).
    FILE* fp = std::fopen(plot.c_str(), "rb");
    ASSERT_NE(fp, nullptr);
    png_structp png = png_create_read_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    ASSERT_EQ(setjmp(png_jmpbuf(png)), 0);
    png_init_io(png, fp);
    png_read_info(png, info);
    const auto w = png_get_image_width(png, info), h = png_get_image_height(png, info);
    png_destroy_read_struct(&png, &info, nullptr);
    std::fclose(fp);
    EXPECT_GT(w, 700u);
    // One pillar per value: the 12 x 9 grid is (3 * 9 + 1) / (2 sqrt 3) =
    // 8.08 cells deep and 12.5 wide, so the picture (with its title and
    // legend) is wider than it is tall.
    EXPECT_GT(h, 300u);
    EXPECT_LT(h, w);
}

TEST(FeelCli, ALogReplaysThroughTheSameFieldWithTheSameForces) {
    const fs::path log = kScratch / "taps.csv", again = kScratch / "taps-again.csv";
    ASSERT_EQ(tsf::test::runTsf("feel " + hillField() + " --trajectory taps --friction off --log " + log.string()).exit_code, 0);
    const tsf::test::RunResult r = tsf::test::runTsf("feel " + hillField() + " --friction off --device replay:" + log.string() + " --log " +
                      again.string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["loop"]["end"], "device-ended");
    EXPECT_TRUE(j["loop"]["zero_force_sent"].get<bool>());
    // Positions come back exactly at the recorded ticks, so the forces are
    // the same (the loop ticks on the same 1 ms grid).
    const auto a = readCsv(log), b = readCsv(again);
    ASSERT_GT(b.size(), a.size() - 3);
    double worst = 0.0;
    for (size_t i = 1; i + 1 < b.size(); ++i) worst = std::max(worst, std::abs(std::stod(a[i][7]) - std::stod(b[i][7])));
    EXPECT_LT(worst, 1e-3);
}

TEST(FeelCli, FeelsTheReliefGenPrintsFromTheSameOptions) {
    // The value -> height rule comes from the same options as tsf gen's,
    // resolved the same way (tsf info shows what gen would print).
    const std::string f = hillField(), opts = " --transfer sqrt --baseline 20 --value-max 120 --cull none";
    const tsf::test::RunResult info = tsf::test::runTsf("info " + f + opts + " --json");
    const tsf::test::RunResult feel = tsf::test::runTsf("feel " + f + opts + " --trajectory taps --json");
    ASSERT_EQ(info.exit_code, 0) << info.output;
    ASSERT_EQ(feel.exit_code, 0) << feel.output;
    const auto i = nlohmann::json::parse(info.output), j = nlohmann::json::parse(feel.output);
    EXPECT_EQ(j["relief"]["transfer"], "sqrt");
    EXPECT_EQ(j["relief"]["transfer"], i["mapping"]["transfer"]);
    EXPECT_EQ(j["relief"]["baseline"], i["mapping"]["baseline"]);
    EXPECT_EQ(j["relief"]["value_max"], i["mapping"]["value_max"]);
    EXPECT_EQ(j["relief"]["printed_height_mm"], i["mapping"]["max_height_mm"]);
    EXPECT_EQ(j["field"]["kept_cells"], i["cells"]["kept"]);
    EXPECT_EQ(j["field"]["cols"], i["grid"]["cols"]);
    EXPECT_TRUE(j["relief"]["exact_at_cell_centres"].get<bool>());
}

// The sidecar tsf gen writes beside a model is felt as that model: its
// mapping and cells, whatever options are given to feel.
TEST(FeelCli, FeelsTheModelASidecarDescribes) {
    const std::string f = hillField();
    const auto dir = tsf::test::scratchDir("feel_sidecar");
    const std::string model = (dir / "m.stl").string();
    const tsf::test::RunResult gen =
        tsf::test::runTsf("gen " + f + " --transfer sqrt --baseline 20 --scale --title Hill -o " + model + " --json", dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.output;
    const auto g = nlohmann::json::parse(gen.out);
    const tsf::test::RunResult feel =
        tsf::test::runTsf("feel " + model + ".scene.json --transfer log --trajectory taps --json", dir);
    ASSERT_EQ(feel.exit_code, 0) << feel.output;
    const auto j = nlohmann::json::parse(feel.out);
    EXPECT_EQ(j["relief"]["transfer"], "sqrt");  // the model's, not --transfer log
    EXPECT_EQ(j["relief"]["baseline"], g["scene"]["mapping"]["baseline"]);
    EXPECT_EQ(j["field"]["kept_cells"], g["scene"]["cells"]["kept"]);
    EXPECT_EQ(j["field"]["how"], "the model its scene sidecar describes, as printed");
}

// --relief writes the surface the hand meets: the written STL's top, checked
// here against the STL rasterised on its own at the CSV's points (within
// 0.1 mm at 99 % of the points; the others lie on walls, where a point's
// column meets either side), NaN beside the model, over the whole footprint
// (the orientation tab, the legend's plate and the scale included).
TEST(FeelCli, TheReliefCsvIsTheWrittenModelsTop) {
    const auto dir = tsf::test::scratchDir("feel_relief_csv");
    const std::string model = (dir / "m.stl").string(), csv = (dir / "relief.csv").string();
    const tsf::test::RunResult gen =
        tsf::test::runTsf("gen " + hillField() + " --title Hill --units m --scale -o " + model, dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.output;
    const tsf::test::RunResult feel =
        tsf::test::runTsf("feel " + model + ".scene.json --trajectory taps --relief " + csv, dir);
    ASSERT_EQ(feel.exit_code, 0) << feel.output;
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    ASSERT_EQ(line, "x_mm,y_mm,z_mm");
    std::vector<std::array<double, 3>> pts;
    while (std::getline(in, line)) {
        std::array<double, 3> p{};
        ASSERT_EQ(std::sscanf(line.c_str(), "%lf,%lf,%lf", &p[0], &p[1], &p[2]), 3) << line;  // "NaN" reads as nan
        pts.push_back(p);
    }
    ASSERT_GT(pts.size(), 1000u);
    const tsf::Mesh m = tsf::readMesh(model);
    const tsf::Bounds b = tsf::meshBounds(m);
    // The grid: 0.5 mm or finer, and it spans the footprint.
    const double step = pts[1][0] - pts[0][0];
    EXPECT_LE(step, 0.5 + 1e-9);
    double x_lo = 1e9, x_hi = -1e9;
    for (const auto& p : pts) x_lo = std::min(x_lo, p[0]), x_hi = std::max(x_hi, p[0]);
    EXPECT_LE(x_lo, b.min.x + step);
    EXPECT_GE(x_hi, b.max.x - step);
    // The STL's top at every point, rasterised here.
    const double x0 = pts[0][0], y0 = pts[0][1];
    const auto cols = int32_t(std::lround((x_hi - x0) / step)) + 1;
    const auto rows = int32_t(pts.size() / size_t(cols));
    std::vector<double> top(size_t(cols) * size_t(rows), NAN);
    for (const auto& t : m.triangles) {
        const tsf::Vec3 &a = m.positions[t[0]], &bb = m.positions[t[1]], &c = m.positions[t[2]];
        const double area2 = (bb.x - a.x) * (c.y - a.y) - (c.x - a.x) * (bb.y - a.y);
        if (!(area2 > 1e-12)) continue;
        const auto i0 = std::max(0, int32_t(std::ceil((std::min({a.x, bb.x, c.x}) - x0) / step)));
        const auto i1 = std::min(cols - 1, int32_t(std::floor((std::max({a.x, bb.x, c.x}) - x0) / step)));
        const auto j0 = std::max(0, int32_t(std::ceil((std::min({a.y, bb.y, c.y}) - y0) / step)));
        const auto j1 = std::min(rows - 1, int32_t(std::floor((std::max({a.y, bb.y, c.y}) - y0) / step)));
        for (int32_t j = j0; j <= j1; ++j)
            for (int32_t i = i0; i <= i1; ++i) {
                const double x = x0 + i * step, y = y0 + j * step;
                const double wa = (bb.x - x) * (c.y - y) - (c.x - x) * (bb.y - y);
                const double wb = (c.x - x) * (a.y - y) - (a.x - x) * (c.y - y);
                const double wc = area2 - wa - wb;
                if (wa < -1e-9 || wb < -1e-9 || wc < -1e-9) continue;
                double& z = top[size_t(j) * size_t(cols) + size_t(i)];
                const double here = (wa * a.z + wb * bb.z + wc * c.z) / area2;
                if (std::isnan(z) || here > z) z = here;
            }
    }
    size_t agree = 0, surface = 0;
    for (size_t n = 0; n < pts.size() && n < top.size(); ++n) {
        const double want = top[n], got = pts[n][2];
        surface += !std::isnan(want);
        agree += (std::isnan(want) && std::isnan(got)) || std::fabs(want - got) <= 0.1;
    }
    EXPECT_GT(surface, pts.size() / 2);
    EXPECT_GE(double(agree), 0.99 * double(pts.size())) << agree << " of " << pts.size();
}

TEST(FeelCli, UnsafeOrBadOptionsAreRejectedWithExitTwo) {
    const std::string f = hillField();
    for (const std::string& args :
         {std::string("--stiffness 5000"), std::string("--max-force 20"), std::string("--mu-s 0.1 --mu-k 0.3"),
          std::string("--rate 200 --stiffness 2000"), std::string("--device replay:/nonexistent.csv"),
          std::string("--device usb"), std::string("--levels 0")}) {
        const tsf::test::RunResult r = tsf::test::runTsf("feel " + f + " " + args);
        EXPECT_EQ(r.exit_code, 2) << args << "\n" << r.output;
        EXPECT_NE(r.output.find("error"), std::string::npos) << args;
    }
    EXPECT_EQ(tsf::test::runTsf("feel " + (kScratch / "missing.csv").string()).exit_code, 2);
}

TEST(FeelCli, JsonStatisticsForVolumeModeAndMipmaps) {
    const tsf::test::RunResult r = tsf::test::runTsf("feel " + hillField() +
                      " --trajectory taps --volume --scale-space mipmap --levels 3 --sampling bilinear --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output);
    EXPECT_EQ(j["field"]["cols"], 12);
    EXPECT_EQ(j["field"]["nodata_cells"], 1);
    EXPECT_EQ(j["scale_space"]["levels"], 3);
    EXPECT_LE(j["forces"]["max_N"].get<double>(), 6.0);
    EXPECT_EQ(j["forces"]["rejected_ticks"], 0);
    EXPECT_GT(j["loop"]["ticks"].get<int>(), 1000);
}

TEST(FeelCli, CtrlCRampsDownZeroesAndExitsWith130) {
    const fs::path log = kScratch / "interrupted.csv";
    fs::remove(log);
    const std::string field = hillField();
    const pid_t pid = fork();
    ASSERT_GE(pid, 0);
    if (pid == 0) {
        const int null = open("/dev/null", O_WRONLY);
        dup2(null, 1);
        dup2(null, 2);
        execl(TSF_BINARY, TSF_BINARY, "feel", field.c_str(), "--trajectory", "sweep", "--realtime", "--log",
              log.c_str(), static_cast<char*>(nullptr));
        _exit(127);
    }
    usleep(1200 * 1000);  // into the session, past the 1 s start ramp
    kill(pid, SIGINT);
    int status = 0;
    ASSERT_EQ(waitpid(pid, &status, 0), pid);
    ASSERT_TRUE(WIFEXITED(status));
    EXPECT_EQ(WEXITSTATUS(status), 130);
    // The log was still written; the session stopped well before the sweep's
    // end, and the last force logged is already ramped down to almost nothing.
    const auto rows = readCsv(log);
    ASSERT_GT(rows.size(), 100u);
    EXPECT_LT(std::stod(rows.back()[0]), 5.0);
    EXPECT_LT(std::stod(rows.back()[7]), 0.05);
}

TEST(FeelCli, ThePlotOfAVeryWideFieldStaysBounded) {
    // 3000 x 4 cells: the picture is sized by the plot, not by the grid.
    const fs::path field = scratchFile("wide.csv"), plot = scratchFile("wide.png");
    {
        std::ofstream f(field);
        for (int r = 0; r < 4; ++r)
            for (int c = 0; c < 3000; ++c) f << (r + c) % 9 << (c + 1 < 3000 ? "," : "\n");
    }
    const auto r = tsf::test::runTsf("feel " + field.string() + " --duration 1 --plot " + plot.string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    std::ifstream in(plot, std::ios::binary);
    unsigned char ihdr[24] = {};
    in.read(reinterpret_cast<char*>(ihdr), sizeof ihdr);
    const uint32_t width = (uint32_t(ihdr[16]) << 24) | (uint32_t(ihdr[17]) << 16) | (uint32_t(ihdr[18]) << 8) | ihdr[19];
    EXPECT_GT(width, 700u);
    EXPECT_LT(width, 2400u);
}

TEST(FeelCli, TheSummarySaysHowMuchTheFitExaggeratesSlopesAndPrintedProportionsDoNot) {
    const std::string volcano = std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv";
    const auto fitted = tsf::test::runTsf("feel " + volcano + " --duration 0.2 --json");
    ASSERT_EQ(fitted.exit_code, 0) << fitted.output;
    const auto f = nlohmann::json::parse(fitted.output.substr(fitted.output.find('{')))["proportions"];
    EXPECT_EQ(f["mode"], "fitted");
    // The footprint and the relief are fitted apart: 20 mm printed become 24 mm felt.
    EXPECT_NEAR(f["scale_z"].get<double>(), 1.2, 1e-9);
    EXPECT_NEAR(f["slope_exaggeration"].get<double>(), f["scale_z"].get<double>() / f["scale_xy"].get<double>(), 1e-9);
    EXPECT_GT(f["slope_exaggeration"].get<double>(), 2.0);
    const auto text = tsf::test::runTsf("feel " + volcano + " --duration 0.2");
    EXPECT_NE(text.output.find("steeper than printed"), std::string::npos) << text.output;
    const auto printed = tsf::test::runTsf("feel " + volcano + " --duration 0.2 --proportions printed --json");
    ASSERT_EQ(printed.exit_code, 0) << printed.output;
    const auto p = nlohmann::json::parse(printed.output.substr(printed.output.find('{')))["proportions"];
    EXPECT_NEAR(p["scale_xy"].get<double>(), p["scale_z"].get<double>(), 1e-9);
    EXPECT_NEAR(p["scale_xy"].get<double>(), f["scale_xy"].get<double>(), 1e-9);  // the footprint's scale: the relief fits
    EXPECT_EQ(tsf::test::runTsf("feel " + volcano + " --proportions steep").exit_code, tsf::test::kExitBadInput);
}
