// End-to-end: the tsf binary on real files, its outputs read back and checked
// by code that shares nothing with the writer, and by an external checker.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "tests/support/required_tools.h"

namespace tsf {
namespace {
using test::runCommand;
using test::runTsf;
using test::scratchDir;
using test::writeText;

// Minimal binary STL reader, written against the format description and
// merging only bit-identical vertices.
Mesh readBinaryStl(const std::filesystem::path& path) {
    const std::string bytes = test::readText(path);
    Mesh m;
    if (bytes.size() < 84) return m;
    uint32_t n;
    std::memcpy(&n, bytes.data() + 80, 4);
    EXPECT_EQ(bytes.size(), 84 + 50 * size_t(n));
    std::map<std::array<float, 3>, uint32_t> index;
    for (uint32_t t = 0; t < n; ++t) {
        std::array<uint32_t, 3> tri;
        for (int v = 0; v < 3; ++v) {
            std::array<float, 3> p;
            std::memcpy(p.data(), bytes.data() + 84 + 50 * size_t(t) + 12 + 12 * v, 12);
            auto [it, fresh] = index.emplace(p, uint32_t(m.positions.size()));
            if (fresh) m.positions.push_back({p[0], p[1], p[2]});
            tri[v] = it->second;
        }
        m.triangles.push_back(tri);
    }
    return m;
}

std::string volcanoLike(int cols, int rows) {
    std::string csv;
    for (int r = 0; r < rows; ++r) {
        for (int c = 0; c < cols; ++c) {
            const double dx = c - cols / 2.0, dy = r - rows / 2.0;
            csv += std::to_string(int(100 * std::exp(-(dx * dx + dy * dy) / 20.0)));
            csv += c + 1 < cols ? "," : "\n";
        }
    }
    return csv;
}

TEST(GenCli, GridCsvToBinaryStlIsAClosedSolid) {
    const auto dir = scratchDir("gen_csv");
    writeText(dir / "field.csv", volcanoLike(12, 10));
    const auto r = runTsf("gen " + (dir / "field.csv").string() + " -o " + (dir / "m.stl").string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    const Mesh m = readBinaryStl(dir / "m.stl");
    const auto inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.euler, 2);
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(j["mesh"]["triangles"].get<size_t>(), m.triangleCount());
    EXPECT_NEAR(j["mesh"]["volume_mm3"].get<double>(), inv.volume, 1e-3 * inv.volume);
}

TEST(GenCli, PointsAreBinnedAndMirrored) {
    const auto dir = scratchDir("gen_points");
    std::string csv = "name,lon,lat\n";
    for (int k = 0; k < 200; ++k) csv += "p" + std::to_string(k) + "," + std::to_string(10 + (k * 37 % 100) / 10.0) +
                                         "," + std::to_string(50 + (k * 53 % 70) / 10.0) + "\n";
    writeText(dir / "pts.csv", csv);
    const auto r = runTsf("gen " + (dir / "pts.csv").string() + " --points x=lon,y=lat --bins 8 --mirror -o " +
                          (dir / "m.stl").string());
    ASSERT_EQ(r.exit_code, 0) << r.output;
    EXPECT_NE(r.output.find("mirrored"), std::string::npos) << r.output;
    const auto inv = test::checkInvariants(readBinaryStl(dir / "m.stl"));
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.euler, 2);
}

TEST(GenCli, AdmeshReportsOneCleanPart) {
    const auto probe = runCommand("admesh --version");
    TSF_NEED_TOOL(probe.exit_code == 0, "admesh");
    const auto dir = scratchDir("gen_admesh");
    writeText(dir / "field.csv", volcanoLike(15, 13));
    for (const char* extra : {"", " --mirror", " --cull none"}) {
        SCOPED_TRACE(extra);
        ASSERT_EQ(runTsf("gen " + (dir / "field.csv").string() + extra + " -o " + (dir / "m.stl").string()).exit_code, 0);
        const auto a = runCommand("admesh " + (dir / "m.stl").string());
        ASSERT_EQ(a.exit_code, 0) << a.output;
        auto stat = [&](const std::string& label) {
            std::smatch m;
            const std::regex re(label + R"(\s*:\s*(\d+))");
            EXPECT_TRUE(std::regex_search(a.output, m, re)) << label << "\n" << a.output;
            return m.empty() ? -1 : std::stoi(m[1]);
        };
        EXPECT_EQ(stat("Number of parts"), 1);
        EXPECT_EQ(stat("Total disconnected facets"), 0);
        EXPECT_EQ(stat("Degenerate facets"), 0);
        EXPECT_EQ(stat("Edges fixed"), 0);
        EXPECT_EQ(stat("Facets removed"), 0);
        EXPECT_EQ(stat("Facets added"), 0);
        EXPECT_EQ(stat("Facets reversed"), 0);
        EXPECT_EQ(stat("Backwards edges"), 0);
        EXPECT_EQ(stat("Normals fixed"), 0);
    }
}

TEST(GenCli, BadInputGivesLocatedErrorAndWritesNothing) {
    const auto dir = scratchDir("gen_bad");
    writeText(dir / "bad.csv", "1,2,3\n4,x5,6\n");
    const auto r = runTsf("gen " + (dir / "bad.csv").string() + " -o " + (dir / "m.stl").string());
    EXPECT_EQ(r.exit_code, 2) << r.output;
    EXPECT_NE(r.output.find("bad.csv:2:"), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl"));
    writeText(dir / "ragged.csv", "1,2,3\n4,5\n");
    const auto r2 = runTsf("gen " + (dir / "ragged.csv").string() + " -o " + (dir / "m.stl").string());
    EXPECT_EQ(r2.exit_code, 2);
    EXPECT_NE(r2.output.find("ragged.csv:2"), std::string::npos) << r2.output;
    EXPECT_EQ(runTsf("gen " + (dir / "missing.csv").string() + " -o " + (dir / "m.stl").string()).exit_code, 2);
    EXPECT_EQ(runTsf("gen " + (dir / "bad.csv").string()).exit_code, 2);  // nothing to write
    // An existing model survives a failed run untouched.
    writeText(dir / "keep.stl", "precious");
    EXPECT_EQ(runTsf("gen " + (dir / "bad.csv").string() + " -o " + (dir / "keep.stl").string()).exit_code, 2);
    std::ifstream in(dir / "keep.stl");
    EXPECT_EQ(std::string((std::istreambuf_iterator<char>(in)), {}), "precious");
    for (const auto& e : std::filesystem::directory_iterator(dir))
        EXPECT_EQ(e.path().filename().string().find(".tmp"), std::string::npos) << e.path();
}

TEST(GenCli, InfoDescribesTheModelWithoutWriting) {
    const auto dir = scratchDir("info");
    writeText(dir / "field.csv", "0,0,0\n0,5,nan\n0,0,0\n");
    const auto r = runTsf("info " + (dir / "field.csv").string() + " --json");
    ASSERT_EQ(r.exit_code, 0) << r.output;
    const auto j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
    // The no-data pixel leaves at least one hexagon without data.
    EXPECT_LT(j["cells"]["with_data"].get<int>(), j["grid"]["cols"].get<int>() * j["grid"]["rows"].get<int>());
    EXPECT_GE(j["cells"]["nonempty"].get<int>(), 1);
}

}  // namespace
}  // namespace tsf
