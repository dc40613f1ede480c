// tsf gen --mirror --halves: two halves and the pins written beside -o,
// verified and listed in the summary; a one-piece mirrored model says it
// needs supports; --halves without --mirror is refused.
#include <gtest/gtest.h>

#include <filesystem>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/files.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "tests/support/verify_report.h"
#include "tests/support/fields.h"

namespace tsf {
namespace {

TEST(HalvesCli, WritesTwoSupportFreeHalvesAndThePins) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", test::hillCsv());
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --mirror --halves --json -o " +
                                    (dir / "m.stl").string(), dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["halves"]["files"]["upper"], (dir / "m-upper.stl").string());
    for (const auto& c : j["halves"]["pair"]["checks"]) EXPECT_EQ(c["status"], "pass") << c.dump();
    EXPECT_EQ(j["scene"]["halves"]["hole_centres_mm"].size(), 3u);
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl"));  // the one piece is not written
    for (const char* name : {"m-upper.stl", "m-lower.stl", "m-pins.stl"}) {
        ASSERT_TRUE(std::filesystem::exists(dir / name)) << name;
        const Mesh m = readMesh((dir / name).string());
        EXPECT_TRUE(test::checkInvariants(m).closedManifold()) << name;
        EXPECT_NEAR(meshBounds(m).min.z, 0.0, 1e-6) << name;
    }
    const auto up = j["halves"]["upper"]["checks"];
    EXPECT_EQ(test::checkStatusIn(j["halves"]["upper"], "overhang"), "pass") << up.dump();
    // The whole is never printed in one piece: its mirrored underside's
    // overhang is no "supports needed" warning beside halves that need none.
    const auto& whole = j["verify"];
    EXPECT_EQ(test::checkStatusIn(whole, "overhang"), "pass") << whole["checks"].dump();
    for (const auto& c : whole["checks"])
        if (c["id"] == "overhang") EXPECT_NE(c["note"].get<std::string>().find("printed as two halves"), std::string::npos) << c.dump();

    const auto text = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --mirror --halves -o " +
                                       (dir / "n.3mf").string(), dir);
    ASSERT_EQ(text.exit_code, test::kExitOk) << text.err;
    EXPECT_NE(text.out.find("n-lower.3mf"), std::string::npos) << text.out;
    EXPECT_NE(text.out.find("nothing overhangs"), std::string::npos) << text.out;
    EXPECT_EQ(text.out.find("supports needed"), std::string::npos) << text.out;
}

TEST(HalvesCli, OnePieceMirroredSaysItNeedsSupports) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", test::hillCsv());
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --mirror -o " + (dir / "m.stl").string(), dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.err;
    EXPECT_NE(r.out.find("supports  needed"), std::string::npos) << r.out;
    EXPECT_NE(r.out.find("--halves"), std::string::npos) << r.out;
    const auto flat = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 -o " + (dir / "f.stl").string(), dir);
    ASSERT_EQ(flat.exit_code, test::kExitOk) << flat.err;
    EXPECT_EQ(flat.out.find("supports  needed"), std::string::npos) << flat.out;
}

TEST(HalvesCli, RefusedWithoutMirror) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", test::hillCsv());
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --halves -o " + (dir / "m.stl").string(), dir);
    EXPECT_EQ(r.exit_code, test::kExitBadInput);
    EXPECT_NE(r.err.find("--mirror"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace tsf
