// tsf gen --bed WxD --tile: the bundled airports on a 100 x 100 mm bed come
// out as tiles that each fit, each verified, the assembly verified, listed
// in the summary; what --tile cannot do yet is refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/files.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

TEST(TilesCli, BundledAirportsOnASmallBed) {
    const auto dir = test::scratchDir();
    const auto r = test::runTsf("gen " + test::sourcePath("examples/airports-europe.csv") +
                                    " --points x=lon,y=lat --bins 40 --bed 100x100 --tile --json -o " + (dir / "eu.stl").string() +
                                    " --preview " + (dir / "tiles.png").string(),
                                dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& t = j["tiles"];
    ASSERT_TRUE(t.is_object());
    EXPECT_GE(t["count"].get<int>(), 4);  // 173 x 123 mm on a 90 x 90 mm printable area
    EXPECT_GT(t["teeth"].get<int>(), 0);
    // A seam too short for a tooth is a warning; everything else passes.
    for (const auto& c : t["assembly"]["checks"])
        EXPECT_EQ(c["status"], c["id"] == "tiles_teeth" && c["status"] == "warn" ? "warn" : "pass") << c.dump();
    EXPECT_GT(t["teeth"].get<int>(), t["seams"].get<int>() / 2);
    EXPECT_FALSE(std::filesystem::exists(dir / "eu.stl"));  // the one piece is not written
    EXPECT_FALSE(std::filesystem::exists(dir / "eu.stl.scene.json"));
    ASSERT_EQ(t["files"].size(), t["tiles"].size());
    int with_marks = 0;
    for (size_t n = 0; n < t["tiles"].size(); ++n) {
        const auto& one = t["tiles"][n];
        const std::string expected_name =
            "eu-tile-" + std::to_string(one["row"].get<int>()) + "-" + std::to_string(one["col"].get<int>()) + ".stl";
        EXPECT_EQ(std::filesystem::path(t["files"][n].get<std::string>()).filename().string(), expected_name);
        EXPECT_EQ(one["verify"]["passed"], true) << expected_name;
        with_marks += one["marks"].get<bool>();
        const Mesh m = readMesh(t["files"][n].get<std::string>());
        EXPECT_TRUE(test::checkInvariants(m).closedManifold()) << expected_name;
        const Bounds b = meshBounds(m);
        EXPECT_LE(b.max.x - b.min.x, 90.0 + 1e-3) << expected_name;
        EXPECT_LE(b.max.y - b.min.y, 90.0 + 1e-3) << expected_name;
        EXPECT_EQ(one["code_pits"].get<int>(), one["row"].get<int>() + one["col"].get<int>() + 1) << expected_name;
    }
    EXPECT_EQ(with_marks, 1);
    EXPECT_TRUE(std::filesystem::exists(dir / "tiles.png"));
    // The key tells a reader how the tiles go together.
    const std::string key = test::readText(dir / "eu.key.txt");
    EXPECT_NE(key.find("The model prints in " + std::to_string(t["count"].get<int>()) + " tiles"), std::string::npos) << key;
}

// Tiling again to the same name with another bed leaves exactly the new
// tiles: the tiles of the first run that the second did not write are
// removed (and said so), not left to be printed with the new ones.
TEST(TilesCli, TilingAgainLeavesExactlyTheNewTiles) {
    const auto dir = test::scratchDir();
    const std::string gen = "gen " + test::sourcePath("examples/volcano.csv") + " --no-verify --tile --json -o " +
                            (dir / "v.stl").string() + " --bed ";
    const auto tiles = [&](const test::RunResult& r) {
        std::vector<std::string> names;
        const auto j = nlohmann::json::parse(r.out);
        for (const auto& f : j["tiles"]["files"])
            names.push_back(std::filesystem::path(f.get<std::string>()).filename().string());
        std::sort(names.begin(), names.end());
        return names;
    };
    const auto on_disk = [&] {
        std::vector<std::string> names;
        for (const auto& e : std::filesystem::directory_iterator(dir))
            if (e.path().filename().string().find("-tile-") != std::string::npos)
                names.push_back(e.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    };
    const auto small = test::runTsf(gen + "60x60", dir);
    ASSERT_EQ(small.exit_code, test::kExitOk) << small.err;
    const auto large = test::runTsf(gen + "100x100", dir);
    ASSERT_EQ(large.exit_code, test::kExitOk) << large.err;
    ASSERT_LT(tiles(large).size(), tiles(small).size());
    EXPECT_EQ(on_disk(), tiles(large));
    EXPECT_NE(large.out.find("a tile of an earlier run under this name"), std::string::npos) << large.out;
    // A user's own file that only looks similar is kept.
    test::writeText(dir / "v-tile-notes.stl", "mine");
    ASSERT_EQ(test::runTsf(gen + "100x100", dir).exit_code, test::kExitOk);
    EXPECT_TRUE(std::filesystem::exists(dir / "v-tile-notes.stl"));
}

// The tab's tile need not hold the model's southernmost pillars: it carries
// the model's own tab, not one placed again against fewer pillars (which was
// shorter, and failed the assembly check).
TEST(TilesCli, TheTabTileCarriesTheModelsTab) {
    const auto dir = test::scratchDir();
    for (const std::string& args : {std::string("--bins 60 --bed 60x60"), std::string("--bins 40 --bed 50x120")}) {
        const auto r = test::runTsf("gen " + test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat " + args +
                                        " --tile --no-key --json -o " + (dir / "t.stl").string(),
                                    dir);
        ASSERT_EQ(r.exit_code, test::kExitOk) << args << "\n" << r.out << r.err;
        const auto j = nlohmann::json::parse(r.out);
        for (const auto& c : j["tiles"]["assembly"]["checks"]) EXPECT_NE(c["status"], "fail") << args << " " << c.dump();
        int with_marks = 0;
        for (const auto& one : j["tiles"]["tiles"]) with_marks += one["marks"].get<bool>();
        EXPECT_EQ(with_marks, 1) << args;
    }
}

TEST(TilesCli, RefusedWhereItCannotCutYet) {
    const auto dir = test::scratchDir();
    const std::string in = test::sourcePath("examples/airports-europe.csv") + " --points x=lon,y=lat --bins 40 ";
    const std::string out = " -o " + (dir / "eu.stl").string();
    for (const std::string& extra : {std::string("--tile"), std::string("--bed 100x100 --tile --mirror"),
                                     std::string("--bed 100x100 --tile --scad ") + (dir / "eu.scad").string(),
                                     std::string("--bed 100x100 --tile --title Airports")}) {
        const auto r = test::runTsf("gen " + in + extra + out, dir);
        EXPECT_EQ(r.exit_code, test::kExitBadInput) << extra << "\n" << r.out << r.err;
        EXPECT_NE(r.err.find("--tile"), std::string::npos) << extra << "\n" << r.err;
        EXPECT_FALSE(std::filesystem::exists(dir / "eu-tile-1-1.stl")) << extra;
    }
    // The tab wider than a tile: three-bumps' follows its diagonal outline,
    // 86.6 mm from the west edge to where it joins the pillars.
    const auto r = test::runTsf("gen " + test::sourcePath("examples/three-bumps.pgm") + " --bed 80x80 --tile" + out, dir);
    EXPECT_EQ(r.exit_code, test::kExitBadInput) << r.out << r.err;
    EXPECT_NE(r.err.find("--tile: the orientation tab is 86.6 x 19.2 mm, larger than"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "eu-tile-1-1.stl"));
}

}  // namespace
}  // namespace tsf
