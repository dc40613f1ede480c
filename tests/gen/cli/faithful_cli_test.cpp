// End-to-end: what a teacher types is what the model shows. The tsf binary on
// small files; its STL read back by code that shares nothing with tsf.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "tests/support/run.h"

namespace tsf {
namespace {
using test::runTsf;
using test::scratchDir;
using test::writeText;

struct Tri {
    float p[3][3];
};

std::vector<Tri> readStlTriangles(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), {});
    std::vector<Tri> out;
    if (bytes.size() < 84) return out;
    uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    for (uint32_t t = 0; t < n && 84 + 50 * size_t(t + 1) <= bytes.size(); ++t) {
        Tri tri;
        std::memcpy(tri.p, bytes.data() + 84 + 50 * size_t(t) + 12, 36);
        out.push_back(tri);
    }
    return out;
}

// Highest surface over (x, y) in mm, or -inf.
double topAt(const std::vector<Tri>& tris, double x, double y) {
    double best = -INFINITY;
    for (const Tri& t : tris) {
        const double ax = t.p[0][0], ay = t.p[0][1], bx = t.p[1][0], by = t.p[1][1], cx = t.p[2][0], cy = t.p[2][1];
        const double d = (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
        if (std::fabs(d) < 1e-9) continue;
        const double u = ((bx - x) * (cy - y) - (by - y) * (cx - x)) / d;
        const double v = ((cx - x) * (ay - y) - (cy - y) * (ax - x)) / d;
        const double w = 1 - u - v;
        if (u < -1e-7 || v < -1e-7 || w < -1e-7) continue;
        best = std::max(best, u * t.p[0][2] + v * t.p[1][2] + w * t.p[2][2]);
    }
    return best;
}

nlohmann::json summary(const std::string& output) {
    const size_t start = output.find('{');
    EXPECT_NE(start, std::string::npos) << output;
    return nlohmann::json::parse(output.substr(start == std::string::npos ? 0 : start));
}

TEST(FaithfulCli, SixteenTypedValuesAreSixteenPillarsEachAtItsOwnValue) {
    const auto dir = scratchDir("faithful_4x4");
    const double v[4][4] = {{0, 1, 2, 3}, {4, 5, 6, 7}, {8, 9, 10, 11}, {12, 13, 14, 16}};
    std::ostringstream csv;
    for (auto& row : v) csv << row[0] << "," << row[1] << "," << row[2] << "," << row[3] << "\n";
    writeText(dir / "field.csv", csv.str());
    const auto r = runTsf("gen " + (dir / "field.csv").string() + " -o " + (dir / "m.stl").string() +
                          " --cell 10 --height 16 --base 2 --no-notch --no-triangle --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = summary(r.output);
    EXPECT_TRUE(j["scene"]["one_pillar_per_value"].get<bool>()) << j.dump(2);
    EXPECT_EQ(j["scene"]["cells"]["kept"], 16);
    const std::vector<Tri> tris = readStlTriangles(dir / "m.stl");
    // Pointy-top hexagons, odd rows shifted east, row 0 north; pitch 10 mm:
    // centre x = (2 col + row % 2 + 1) * 5, y = (3 (rows - 1 - row) + 2) * 10 / (2 sqrt 3).
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 4; ++col) {
            const double x = (2 * col + row % 2 + 1) * 5.0, y = (3 * (3 - row) + 2) * 10.0 / (2 * std::sqrt(3.0));
            // 16 mm for the largest value (16) above a 2 mm base: 1 mm per unit.
            EXPECT_NEAR(topAt(tris, x, y), 2.0 + v[row][col], 1e-4) << "cell " << col << "," << row;
        }
}

TEST(FaithfulCli, DefaultModelCarriesBothMarksInStlAnd3mf) {
    const auto dir = scratchDir("faithful_marks");
    std::ostringstream csv;
    for (int r = 0; r < 12; ++r)
        for (int c = 0; c < 14; ++c) csv << (c >= 10 ? 3 + (r + c) % 4 : 0) << (c + 1 < 14 ? "," : "\n");
    writeText(dir / "field.csv", csv.str());
    for (const char* ext : {".stl", ".3mf"}) {
        const std::string model = (dir / (std::string("m") + ext)).string();
        const auto r = runTsf("gen " + (dir / "field.csv").string() + " -o " + model + " --json");
        ASSERT_EQ(r.exit_code, 0) << r.output;
        const nlohmann::json j = summary(r.output);
        // On the orientation tab by default, at full size.
        const nlohmann::json& tab = j["scene"]["marks"]["tab"];
        ASSERT_TRUE(tab.is_object()) << ext << j["scene"]["marks"].dump();
        ASSERT_FALSE(tab["notch"].is_null()) << ext;
        ASSERT_FALSE(tab["triangle"].is_null()) << ext;
        EXPECT_NEAR(tab["notch"]["depth_mm"].get<double>(), 6.0, 1e-3) << ext;
        EXPECT_GE(tab["triangle"]["leg_x_mm"].get<double>(), 12.7) << ext;
        EXPECT_GT(tab["triangle"]["leg_x_mm"].get<double>(), tab["triangle"]["leg_y_mm"].get<double>());
        const auto v = runTsf("verify " + model + " --scene " + model + ".scene.json");
        EXPECT_EQ(v.exit_code, 0) << v.output;
    }
}

TEST(FaithfulCli, NodataValueIsNotAHeight) {
    const auto dir = scratchDir("faithful_nodata");
    writeText(dir / "field.csv", "1,2,3\n4,-9999,6\n7,8,9\n");
    const auto r = runTsf("gen " + (dir / "field.csv").string() + " -o " + (dir / "m.stl").string() +
                          " --nodata -9999 --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const nlohmann::json j = summary(r.output);
    EXPECT_EQ(j["scene"]["cells"]["kept_without_data"], 1);
    // The relief is not flattened by the placeholder: 9 stands at full height.
    EXPECT_EQ(j["scene"]["mapping"]["value_max"], 9);
    EXPECT_EQ(j["scene"]["mapping"]["baseline"], 0);
}

TEST(FaithfulCli, CellThatOverflowsTheBoxIsAnError) {
    const auto dir = scratchDir("faithful_cell_box");
    writeText(dir / "field.csv", "1,2,3,4,5,6,7,8,9,10\n");
    const auto r = runTsf("gen " + (dir / "field.csv").string() + " -o " + (dir / "m.stl").string() +
                          " --cell 10 --width 50");
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("--cell"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl"));
}

TEST(FaithfulCli, LonLatPointsAreProjectedAndSaySo) {
    const auto dir = scratchDir("faithful_lonlat");
    std::ostringstream csv;
    csv << "name,lon,lat\n";
    for (int k = 0; k < 40; ++k) csv << "p" << k << "," << -5 + (k * 7) % 30 << "," << 40 + (k * 3) % 20 << "\n";
    writeText(dir / "pts.csv", csv.str());
    const auto r = runTsf("info " + (dir / "pts.csv").string() + " --points x=lon,y=lat --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("Lambert azimuthal equal-area"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("area distortion at most"), std::string::npos) << r.output;
    const auto none = runTsf("info " + (dir / "pts.csv").string() + " --points x=lon,y=lat --project none --json");
    EXPECT_EQ(none.output.find("projected"), std::string::npos) << none.output;
}

TEST(FaithfulCli, LargeRasterIsResampledToTactileCellsAndSaysWhy) {
    const auto dir = scratchDir("faithful_large");
    std::ostringstream csv;
    for (int r = 0; r < 120; ++r)
        for (int c = 0; c < 120; ++c) csv << (r * c) % 17 << (c + 1 < 120 ? "," : "\n");
    writeText(dir / "big.csv", csv.str());
    const auto r = runTsf("info " + (dir / "big.csv").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("resampled because"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace tsf
