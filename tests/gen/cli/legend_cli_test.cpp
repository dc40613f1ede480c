// tsf gen --title/--units/--braille-table: the braille legend on a plate
// north of the pillars, joined into one solid, known to the verifier
// through the scene sidecar, and refused where it cannot stand.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

// Three floor rows in the north (culled: outside the hull), a small relief south of them.
const char* kField =
    "0,0,0,0,0,0,0,0,0,0,0,0\n"
    "0,0,0,0,0,0,0,0,0,0,0,0\n"
    "0,0,0,0,0,0,0,0,0,0,0,0\n"
    "0,1,2.5,3,1.5,0,1,2.5,3,1.5,0,1\n"
    "1,4,2,2,0.5,1,4,2,2,0.5,1,4\n"
    "2,3.5,5,4.5,1,2,3.5,5,4.5,1,2,3.5\n"
    "0.5,2,1,3,2,0.5,2,1,3,2,0.5,2\n";

TEST(LegendCli, TitleAndRangeInBrailleOnAPlateNorthOfThePillars) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 6 --title Depth --units m --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    const auto& legend = j["scene"]["legend"];
    ASSERT_TRUE(legend.is_object()) << j["scene"].dump(2);
    ASSERT_EQ(legend["lines"].size(), 2u);
    EXPECT_EQ(legend["lines"][0]["text"], "Depth");
    EXPECT_EQ(legend["lines"][1]["text"], "0 to 5 m");
    // "Depth" in uncontracted braille: capital sign (dot 6), d (1-4-5), e (1-5), p (1-2-3-4), t (2-3-4-5), h (1-2-5).
    EXPECT_EQ(legend["lines"][0]["braille"], "\u2820\u2819\u2811\u280f\u281e\u2813");
    EXPECT_DOUBLE_EQ(legend["dot_base_mm"].get<double>(), 1.44);
    // No --layer: 0.6 mm, whole layers at the common layer heights.
    EXPECT_DOUBLE_EQ(legend["dot_height_mm"].get<double>(), 0.6);

    const Mesh m = readMesh(model);
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    // The plate reaches north of the grid; the dots stand 0.6 mm on the 2 mm floor there.
    const Bounds b = meshBounds(m);
    EXPECT_GT(b.max.y, j["scene"]["size_mm"][1].get<double>() + 10.0);
    size_t dot_tops = 0;
    for (const Vec3& p : m.positions)
        dot_tops += std::fabs(p.z - 2.6) < 1e-5 && p.y > j["scene"]["size_mm"][1].get<double>();  // STL: float32
    EXPECT_EQ(dot_tops, legend["dots"].get<size_t>());

    const auto ok = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
    EXPECT_EQ(ok.exit_code, test::kExitOk) << ok.out << ok.err;
}

TEST(LegendCli, TheVerifierKnowsThePlateCoversCulledCellsFromTheSidecar) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + test::sourcePath("examples/airports-europe.csv") +
                                    " --points x=lon,y=lat --bins 20 --title Airports --no-verify -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto ok = test::runTsf("verify " + model + " --scene " + model + ".scene.json --no-printability", dir);
    EXPECT_EQ(ok.exit_code, test::kExitOk) << ok.out << ok.err;
    // Without the legend in the sidecar the plate is material over culled cells.
    auto scene = nlohmann::json::parse(test::readText(model + ".scene.json"));
    scene["legend"] = nullptr;
    test::writeText(dir / "nolegend.json", scene.dump());
    const auto planted =
        test::runTsf("verify " + model + " --scene " + (dir / "nolegend.json").string() + " --no-printability", dir);
    EXPECT_EQ(planted.exit_code, test::kExitCheckFailed) << planted.out;
    EXPECT_NE(planted.out.find("FAIL  no material outside the kept cells"), std::string::npos) << planted.out;
}

TEST(LegendCli, WhereTheLegendCannotStandTheCommandSaysWhatToChange) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string field = (dir / "f.csv").string(), model = (dir / "m.stl").string();
    const auto halves = test::runTsf("gen " + field + " --cell 6 --mirror --halves --title Depth -o " + model, dir);
    EXPECT_EQ(halves.exit_code, test::kExitBadInput) << halves.err;
    EXPECT_NE(halves.err.find("Leave out --halves"), std::string::npos) << halves.err;
    const auto table = test::runTsf("gen " + field + " --cell 6 --title Depth --braille-table nope.ctb -o " + model, dir);
    EXPECT_EQ(table.exit_code, test::kExitBadInput) << table.err;
    EXPECT_NE(table.err.find("nope.ctb"), std::string::npos) << table.err;
    const auto wide = test::runTsf("gen " + field + " --cell 6 --title Pneumonoultramicroscopicsilicovolcanoconiosis -o " +
                                       model, dir);
    EXPECT_EQ(wide.exit_code, test::kExitBadInput) << wide.err;
    EXPECT_NE(wide.err.find("give a shorter --title"), std::string::npos) << wide.err;
    EXPECT_FALSE(std::filesystem::exists(model));
}

// A mirrored model takes a legend: its plate lies in the z band every
// pillar it stands against holds (there is no floor), its dots on top; the
// model verifies against its sidecar, tilted too.
TEST(LegendCli, AMirroredModelTakesALegendInTheBandItsPillarsShare) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", kField);
    const std::string field = (dir / "f.csv").string(), model = (dir / "m.stl").string();
    for (const std::string extra : {"", " --tilt gradient", " --units mm --layer 0.2"}) {
        const auto r = test::runTsf("gen " + field + " --cell 6 --mirror --title Depth" + extra + " -o " + model, dir);
        ASSERT_EQ(r.exit_code, test::kExitOk) << extra << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("legend    braille"), std::string::npos) << r.out;
        std::string out = r.out;  // the summary's lines joined back (it wraps them at about 100 characters)
        for (size_t at; (at = out.find("\n            ")) != std::string::npos;) out.replace(at, 13, " ");
        EXPECT_NE(out.find("mm north of the pillars, from z = "), std::string::npos) << r.out;
        const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json", dir);
        EXPECT_EQ(v.exit_code, test::kExitOk) << extra << "\n" << v.out;
        EXPECT_NE(v.out.find("PASS  the legend plate and every braille dot at its height"), std::string::npos) << v.out;
        const nlohmann::json scene = nlohmann::json::parse(test::readText(model + ".scene.json"));
        const int64_t bottom = scene["legend"]["plate_bottom_units"], top = scene["legend"]["plate_top_units"];
        EXPECT_GT(bottom, 0) << "the plate floats in the band, off the bed";
        EXPECT_GT(top, bottom);
    }
}

// Small and odd models take a legend: the plate stands against the
// pillars' walls on shared lattice edges, so nothing is too small to join.
// Each was a failed self-check (exit 1) or a library assertion (exit 3)
// while the plate was joined by a boolean union: a 3 x 2 checkerboard
// resampled to 200 bins, three and five points, a 5 x 2 grid with units,
// one point fitted to a small bed. Each model passes `tsf verify --scene`.
TEST(LegendCli, SmallAndOddModelsTakeALegendThatVerifies) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "board.csv", "0,1\n1,0\n0,1\n");
    test::writeText(dir / "three.csv", "x,y\n0,0\n1,0\n0,1\n");
    test::writeText(dir / "five.csv", "x,y\n0,0\n1,0\n0,1\n1,1\n0.5,0.5\n");
    test::writeText(dir / "grid.csv", "1,2,3,4,5\n5,4,3,2,1\n");
    test::writeText(dir / "one.csv", "x,y\n0,0\n");
    // Two clusters far apart: the tab finds no place, the notch goes in the
    // data, and the plate's south edge must stay north of the row it cuts.
    test::writeText(dir / "clusters.csv", "x,y\n-24.999,32.0019\n-24.999,32.0001\n50.0015,4.00225\n-25.0006,32.0018\n");
    const std::string out = (dir / "o.stl").string();
    // (The checkerboard's 0.5 mm cells leave a 0.29 mm sliver of the tab at
    // its north end, which a 0.4 mm nozzle would not print: kept on purpose.)
    for (const std::string args : {"board.csv --title Rain --bins 200 --keep-unprintable", "three.csv --points x=x,y=y --title x",
                                   "five.csv --points x=x,y=y --title x", "grid.csv --units airports --bins 10",
                                   "three.csv --points x=x,y=y --title x --marks-on data",
                                   "one.csv --points x=x,y=y --units mm --marks-on data --no-triangle",
                                   "clusters.csv --points x=x,y=y --bins 22 --title T --units mm",
                                   "one.csv --points x=x,y=y --units mm --bed 100x100"}) {
        const auto r = test::runTsf("gen " + (dir / args).string() + " -o " + out, dir);
        ASSERT_EQ(r.exit_code, test::kExitOk) << args << "\n" << r.out << r.err;
        EXPECT_NE(r.out.find("legend    braille"), std::string::npos) << args << "\n" << r.out;
        const auto v = test::runTsf("verify " + out + " --scene " + out + ".scene.json", dir);
        EXPECT_EQ(v.exit_code, test::kExitOk) << args << "\n" << v.out;
        EXPECT_NE(v.out.find("PASS  the legend plate and every braille dot at its height"), std::string::npos) << args << "\n" << v.out;
    }
    // Fitted to a 100 x 100 mm bed, one point, its legend plate and its tab fit 90 x 90 mm.
    const Bounds b = meshBounds(readMesh(out));
    EXPECT_LE(b.max.x - b.min.x, 90.0 + 1e-6);
    EXPECT_LE(b.max.y - b.min.y, 90.0 + 1e-6);
}

// No-data pits beside the plate stay pits: the plate's side rises from the
// pit's top to the floor, and every corner of that side splits the plate's
// other walls at the pit's height (found by the combination fuzzer as open
// edges at a pit's corner on the plate's south edge, twice: at the end of a
// pit's edge, and where a pit meets the plate at a corner only). A two-row field
// resampled fine, with the scale beside the legend, the same.
TEST(LegendCli, NoDataPitsBesideThePlateStayPits) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "gaps.csv",
                    "3,,3,3,3,3,3,,3,\n,,3,3,3,,3,3,,\n,3,3,3,3,3,3,3,3,3\n,3,3,,3,3,3,3,3,3\n"
                    ",3,,3,3,,,3,3,\n,3,3,3,3,,,3,3,3\n3,3,,,3,3,3,3,3,3\n,,3,3,3,,,,,\n");
    test::writeText(dir / "two.csv", ",1,\n,,1\n");
    // A pit whose corner only (not an edge) meets the plate's own side on
    // its south edge: the side splits at the pit's top there too.
    test::writeText(dir / "corner.csv", "18,,\n,90,\n");
    const std::string out = (dir / "o.off").string();
    for (const std::string args : {"gaps.csv --title Rain --units u --no-triangle --height 0 --base 1 --bed 220x220",
                                   "gaps.csv --title Rain --height 5",
                                   "two.csv --bins 58 --title Rain --units airports --scale --no-texture-structural",
                                   "corner.csv --units u --transfer sqrt"}) {
        const auto r = test::runTsf("gen " + (dir / args).string() + " -o " + out, dir);
        ASSERT_EQ(r.exit_code, test::kExitOk) << args << "\n" << r.out << r.err;
        const auto v = test::runTsf("verify " + out + " --scene " + out + ".scene.json", dir);
        EXPECT_EQ(v.exit_code, test::kExitOk) << args << "\n" << v.out;
        EXPECT_NE(v.out.find("PASS  every cell at its height"), std::string::npos) << args << "\n" << v.out;
    }
}

}  // namespace
}  // namespace tsf
