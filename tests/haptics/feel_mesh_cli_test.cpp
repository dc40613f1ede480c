// tsf feel MODEL.stl: a mesh file is felt as it is, on the grid of the scene
// sidecar of the model it was made from. The written model feels as its
// sidecar does; an edit of the generated .scad, rendered by OpenSCAD, is
// felt edited, and tsf verify names the edited cell in words.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>
#include <utility>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/required_tools.h"
#include "tests/support/run.h"

namespace {

// x_mm,y_mm -> z_mm of a relief CSV (tsf feel --relief).
std::map<std::pair<long, long>, double> readRelief(const std::string& path) {
    std::map<std::pair<long, long>, double> z;
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    double x, y, h;
    while (std::getline(in, line))
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &x, &y, &h) == 3) z[{std::lround(x * 1000), std::lround(y * 1000)}] = h;
    return z;
}

const char* kGrid = "1,2,3,4\n2,3,4,5\n3,4,5,6\n4,5,6,7\n";

TEST(FeelCli, FeelsAMeshFileOnTheGridOfItsSidecar) {
    const auto dir = tsf::test::scratchDir("feel_mesh");
    tsf::test::writeText(dir / "g.csv", kGrid);
    const std::string model = (dir / "g.stl").string();
    ASSERT_EQ(tsf::test::runTsf("gen " + (dir / "g.csv").string() + " --cell 8 -o " + model, dir).exit_code, 0);
    const auto mesh = tsf::test::runTsf("feel " + model + " --trajectory taps --relief " + (dir / "a.csv").string() + " --json", dir);
    ASSERT_EQ(mesh.exit_code, 0) << mesh.output;
    EXPECT_EQ(nlohmann::json::parse(mesh.out)["field"]["how"], "the mesh as written, on the grid of its scene sidecar");
    const auto side = tsf::test::runTsf("feel " + model + ".scene.json --trajectory taps --relief " + (dir / "b.csv").string(), dir);
    ASSERT_EQ(side.exit_code, 0) << side.output;
    // The file is the model its sidecar describes: the same surface, point for point
    // (within the float32 rounding of the STL).
    const auto a = readRelief((dir / "a.csv").string()), b = readRelief((dir / "b.csv").string());
    ASSERT_GT(a.size(), 1000u);
    ASSERT_EQ(a.size(), b.size());
    size_t same = 0;
    for (const auto& [k, z] : a) {
        const auto it = b.find(k);
        same += it != b.end() && ((std::isnan(z) && std::isnan(it->second)) || std::fabs(z - it->second) <= 1e-3);
    }
    EXPECT_GE(double(same), 0.99 * double(a.size()));

    // A --scene that is not there is bad input naming it.
    const auto missing = tsf::test::runTsf("feel " + model + " --scene " + (dir / "nope.json").string() + " --trajectory taps", dir);
    EXPECT_EQ(missing.exit_code, tsf::test::kExitBadInput) << missing.output;
    EXPECT_NE(missing.err.find("nope.json"), std::string::npos) << missing.err;
}

// A mesh tsf did not make (no sidecar): its own top is felt, on a grid laid
// over it. A 40 x 30 mm block 4 mm thick with a 10 x 10 mm block 6 mm
// higher on it, away from the origin: the relief is the two tops.
TEST(FeelCli, FeelsAMeshTsfDidNotMake) {
    const auto dir = tsf::test::scratchDir("feel_foreign_mesh");
    // Two boxes: [100, 140] x [50, 80] x [0, 4] and [115, 125] x [60, 70] x [4, 10], one closed solid each.
    auto box = [](double x0, double y0, double z0, double x1, double y1, double z1, int first) {
        std::string v, f;
        for (int k = 0; k < 8; ++k)
            v += std::to_string(k & 1 ? x1 : x0) + " " + std::to_string(k & 2 ? y1 : y0) + " " + std::to_string(k & 4 ? z1 : z0) + "\n";
        const int q[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
        for (const auto& s : q)
            f += "3 " + std::to_string(first + s[0]) + " " + std::to_string(first + s[1]) + " " + std::to_string(first + s[2]) +
                 "\n3 " + std::to_string(first + s[0]) + " " + std::to_string(first + s[2]) + " " + std::to_string(first + s[3]) + "\n";
        return std::make_pair(v, f);
    };
    const auto [v1, f1] = box(100, 50, 0, 140, 80, 4, 0);
    const auto [v2, f2] = box(115, 60, 4, 125, 70, 10, 8);
    tsf::test::writeText(dir / "blocks.off", "OFF\n16 24 0\n" + v1 + v2 + f1 + f2);
    const std::string csv = (dir / "r.csv").string();
    const auto r = tsf::test::runTsf("feel " + (dir / "blocks.off").string() + " --trajectory taps --relief " + csv + " --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_NE(j["field"]["how"].get<std::string>().find("no scene sidecar"), std::string::npos) << j["field"].dump();
    EXPECT_NEAR(j["relief"]["printed_height_mm"].get<double>(), 6.0, 0.05) << "the step above the lowest top";
    EXPECT_TRUE(j["sidecar"].is_null());
    // The relief: 10 mm over the small block, 4 mm over the rest of the big one, in the mesh's own frame.
    const auto z = readRelief(csv);
    size_t high = 0, low = 0;
    for (const auto& [k, h] : z) {
        const double x = k.first / 1000.0, y = k.second / 1000.0;
        if (x > 116 && x < 124 && y > 61 && y < 69) high += std::fabs(h - 10) < 1e-6;
        if ((x > 101 && x < 110) || (x > 130 && x < 139)) low += std::fabs(h - 4) < 1e-6;
    }
    EXPECT_GT(high, 100u);
    EXPECT_GT(low, 500u);
}

// The mesh's top at (x, y), mm: the highest triangle over that point (NaN
// where none is), by brute force over triangles bucketed on a 2 mm grid.
class MeshTop {
public:
    explicit MeshTop(const tsf::Mesh& m) : m_(m) {
        const tsf::Bounds b = tsf::meshBounds(m);
        x0_ = b.min.x, y0_ = b.min.y;
        cols_ = int(std::ceil((b.max.x - x0_) / kBucket)) + 1, rows_ = int(std::ceil((b.max.y - y0_) / kBucket)) + 1;
        buckets_.resize(size_t(cols_) * size_t(rows_));
        for (size_t t = 0; t < m.triangles.size(); ++t) {
            double lx = 1e300, ly = 1e300, hx = -1e300, hy = -1e300;
            for (uint32_t v : m.triangles[t]) {
                lx = std::min(lx, m.positions[v].x), hx = std::max(hx, m.positions[v].x);
                ly = std::min(ly, m.positions[v].y), hy = std::max(hy, m.positions[v].y);
            }
            for (int j = int((ly - y0_) / kBucket); j <= int((hy - y0_) / kBucket); ++j)
                for (int i = int((lx - x0_) / kBucket); i <= int((hx - x0_) / kBucket); ++i)
                    buckets_[size_t(j) * size_t(cols_) + size_t(i)].push_back(t);
        }
    }
    double at(double x, double y) const {
        const int i = int((x - x0_) / kBucket), j = int((y - y0_) / kBucket);
        if (i < 0 || j < 0 || i >= cols_ || j >= rows_) return NAN;
        double top = NAN;
        for (size_t t : buckets_[size_t(j) * size_t(cols_) + size_t(i)]) {
            const auto& a = m_.positions[m_.triangles[t][0]];
            const auto& b = m_.positions[m_.triangles[t][1]];
            const auto& c = m_.positions[m_.triangles[t][2]];
            const double d = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
            if (std::fabs(d) < 1e-12) continue;  // a wall
            const double u = ((x - a.x) * (c.y - a.y) - (c.x - a.x) * (y - a.y)) / d;
            const double v = ((b.x - a.x) * (y - a.y) - (x - a.x) * (b.y - a.y)) / d;
            if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) continue;
            const double z = a.z + u * (b.z - a.z) + v * (c.z - a.z);
            if (!(top >= z)) top = z;
        }
        return top;
    }

private:
    static constexpr double kBucket = 2.0;
    const tsf::Mesh& m_;
    double x0_ = 0, y0_ = 0;
    int cols_ = 0, rows_ = 0;
    std::vector<std::vector<size_t>> buckets_;
};

// A model tsf made, its sidecar gone (or never copied along): the relief
// written is the mesh's top in the mesh's own coordinates, the orientation
// tab west of x = 0 included.
TEST(FeelCli, TheReliefOfAMeshWithoutSidecarIsInTheMeshsOwnFrame) {
    const auto dir = tsf::test::scratchDir("feel_mesh_own_frame");
    const std::string model = (dir / "volcano.stl").string();
    ASSERT_EQ(tsf::test::runTsf("gen " + std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv -o " + model, dir).exit_code, 0);
    std::filesystem::remove(model + ".scene.json");
    const std::string csv = (dir / "r.csv").string();
    const auto r = tsf::test::runTsf("feel " + model + " --trajectory taps --relief " + csv + " --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_TRUE(nlohmann::json::parse(r.out)["sidecar"].is_null());
    const tsf::Mesh mesh = tsf::readMesh(model);
    ASSERT_LT(tsf::meshBounds(mesh).min.x, -10.0) << "the tab reaches west of x = 0";
    const MeshTop top(mesh);
    std::ifstream in(csv);
    std::string line;
    std::getline(in, line);
    size_t samples = 0, close = 0, west = 0;
    double x, y, h;
    while (std::getline(in, line)) {
        if (std::sscanf(line.c_str(), "%lf,%lf,%lf", &x, &y, &h) != 3) continue;
        const double t = top.at(x, y);
        if (std::isnan(t) && std::isnan(h)) continue;  // nothing there, said so
        ++samples;
        west += x < 0 && !std::isnan(h);
        close += !std::isnan(t) && !std::isnan(h) && std::fabs(t - h) <= 0.1;
    }
    ASSERT_GT(samples, 10000u);
    EXPECT_GT(west, 100u) << "the tab is in the relief";
    EXPECT_GE(double(close), 0.99 * double(samples)) << close << " of " << samples;
}

// MODEL.scene.json (the model's name without .stl) is taken as the sidecar
// too, and the summary says which one was used.
TEST(FeelCli, FindsASidecarNamedAfterTheModelAndSaysWhichItUsed) {
    const auto dir = tsf::test::scratchDir("feel_mesh_sidecar_name");
    tsf::test::writeText(dir / "g.csv", kGrid);
    const std::string model = (dir / "g.stl").string();
    ASSERT_EQ(tsf::test::runTsf("gen " + (dir / "g.csv").string() + " --cell 8 -o " + model, dir).exit_code, 0);
    const std::string plain = (dir / "g.scene.json").string();
    std::filesystem::rename(model + ".scene.json", plain);
    const auto r = tsf::test::runTsf("feel " + model + " --trajectory taps --json", dir);
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["sidecar"], plain);
    EXPECT_EQ(j["field"]["cols"], 4);  // the sidecar's grid, not one laid over the mesh
    EXPECT_EQ(j["field"]["rows"], 4);
    const auto text = tsf::test::runTsf("feel " + model + " --trajectory taps", dir);
    EXPECT_NE(text.out.find("sidecar   " + plain), std::string::npos) << text.out;
}

// A blind maker edits one value of the generated .scad (4 -> 7), OpenSCAD
// renders it, and tsf feel meets the edited pillar raised by the edit's
// height; tsf verify against the original sidecar names that cell.
TEST(FeelCli, AnOpenScadRenderOfAnEditedScadIsFeltEdited) {
    TSF_NEED_TOOL(std::system("command -v openscad >/dev/null 2>&1") == 0, "openscad");
    const auto dir = tsf::test::scratchDir("feel_scad_edit");
    tsf::test::writeText(dir / "g.csv", kGrid);
    const std::string model = (dir / "g.stl").string(), scad = (dir / "g.scad").string();
    ASSERT_EQ(tsf::test::runTsf("gen " + (dir / "g.csv").string() + " --cell 8 --scad " + scad + " -o " + model, dir).exit_code, 0);
    std::string text = tsf::test::readText(scad);
    const std::string row = "    [2, 3, 4, 5],  // row 1";
    const size_t at = text.find(row);
    ASSERT_NE(at, std::string::npos) << "the generated values table changed its layout";
    text.replace(at, row.size(), "    [2, 3, 7, 5],  // row 1");
    tsf::test::writeText(dir / "edited.scad", text);
    const std::string edited = (dir / "edited.stl").string();
    const auto render = tsf::test::runTsf("render " + (dir / "edited.scad").string() + " -o " + edited, dir);
    ASSERT_EQ(render.exit_code, 0) << render.output;

    const auto feel = tsf::test::runTsf("feel " + edited + " --scene " + model + ".scene.json --trajectory taps --relief " +
                                            (dir / "e.csv").string(), dir);
    ASSERT_EQ(feel.exit_code, 0) << feel.output;
    ASSERT_EQ(tsf::test::runTsf("feel " + model + ".scene.json --trajectory taps --relief " + (dir / "o.csv").string(), dir)
                  .exit_code, 0);
    // Heights: values 0..7 -> 0..20 mm above a 2 mm floor; the edited
    // cell's top goes from 2 + 20 * 4/7 to 2 + 20 mm, nothing else moves.
    const auto o = readRelief((dir / "o.csv").string()), e = readRelief((dir / "e.csv").string());
    size_t raised = 0, moved = 0;
    for (const auto& [k, z] : o) {
        const auto it = e.find(k);
        if (it == e.end() || std::isnan(z) || std::isnan(it->second)) continue;
        if (std::fabs(it->second - z) <= 0.01) continue;
        ++moved;
        raised += std::fabs(z - (2 + 20.0 * 4 / 7)) < 0.01 && std::fabs(it->second - 22.0) < 0.01;
    }
    EXPECT_GT(raised, 100u) << "the edited pillar's top, felt higher";
    EXPECT_GE(double(raised), 0.9 * double(moved)) << "and little else (points on its walls)";

    const auto verify = tsf::test::runTsf("verify " + edited + " --scene " + model + ".scene.json", dir);
    EXPECT_EQ(verify.exit_code, tsf::test::kExitCheckFailed) << verify.output;
    EXPECT_NE(verify.out.find("cell (col 2, row 1) top"), std::string::npos) << verify.out;
    EXPECT_NE(verify.out.find("value 4 reads as 7"), std::string::npos) << verify.out;
}

}  // namespace
