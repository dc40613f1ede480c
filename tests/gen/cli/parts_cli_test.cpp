// tsf gen --parts: a 3MF of pillars, marks and legend, verified part by part
// and as an assembly by tsf gen and again by tsf verify; refused for formats
// that hold one solid.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

// 16 x 12 values: a varied strip in the north, the rest one flat value (the triangle's region).
std::string partsField() {
    std::string csv;
    for (int r = 0; r < 12; ++r) {
        for (int c = 0; c < 16; ++c) csv += (c ? "," : "") + std::to_string(r >= 4 ? 5 : (c + r) % 4);
        csv += "\n";
    }
    return csv;
}

TEST(PartsCli, GenWritesOneObjectInPartsAndVerifyJudgesEachPartAndTheAssembly) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", partsField());
    const std::string model = (dir / "m.3mf").string();
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() +
                                    " --cell 4 --height 10 --title Test --units m --parts --json -o " + model,
                                dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const auto j = nlohmann::json::parse(r.out);
    EXPECT_EQ(j["verify"]["parts"]["passed"], true);
    ASSERT_EQ(j["verify"]["parts"]["parts"].size(), 3u);
    EXPECT_NE(j["outputs"][0]["kind"].get<std::string>().find("3 parts: pillars, marks, legend"), std::string::npos)
        << j["outputs"].dump();

    const std::vector<MeshPart> parts = readMeshParts(model);
    ASSERT_EQ(parts.size(), 3u);
    for (const MeshPart& p : parts) {
        const test::Invariants inv = test::checkInvariants(p.mesh);
        EXPECT_TRUE(inv.closedManifold()) << p.name << ": " << inv.describe();
    }

    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --json", dir);
    ASSERT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
    const auto vj = nlohmann::json::parse(v.out);
    EXPECT_EQ(vj["format"], "tsf-verify-parts-report");
    EXPECT_EQ(vj["parts"][0]["name"], "pillars");
    EXPECT_EQ(vj["parts"][1]["name"], "marks");
    EXPECT_EQ(vj["parts"][2]["name"], "legend");
    EXPECT_EQ(vj["passed"], true);
    bool overlap = false, readback = false;
    for (const auto& c : vj["assembly"]["checks"]) {
        overlap = overlap || (c["id"] == "parts_overlap" && c["status"] == "pass");
        readback = readback || (c["id"] == "values_read_back" && c["status"] == "pass");
    }
    EXPECT_TRUE(overlap) << vj["assembly"].dump(2);
    EXPECT_TRUE(readback) << vj["assembly"].dump(2);

}

// The bundled example with every model feature at once (the one-command
// print-ready model of docs/printing.md): a legend beside large level
// regions, the scale and the marks, as one solid and as parts. The legend's
// join once folded beside merged level tops on exactly this field.
TEST(PartsCli, AirportsWithLegendScaleAndMarksIsOneSolidAndFourParts) {
    const auto dir = test::scratchDir();
    const std::string input = std::string(TSF_SOURCE_DIR) + "/examples/airports-europe.csv";
    const std::string common = "gen " + input + " --points x=lon,y=lat --bins 40 --title Airports --units airports --scale";
    // As one solid in a float32 STL: written only if the file as written
    // verifies; else refused as a bug with nothing written, never exit 0
    // with a file that fails `tsf verify` (the legend's CGAL join leaves a
    // sliver here that float32 turns over).
    const std::string stl = (dir / "a.stl").string();
    const auto solid = test::runTsf(common + " -o " + stl, dir);
    if (solid.exit_code == test::kExitOk) {
        const auto v = test::runTsf("verify " + stl + " --scene " + stl + ".scene.json", dir);
        EXPECT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
    } else {
        EXPECT_EQ(solid.exit_code, test::kExitCheckFailed) << solid.out << solid.err;
        EXPECT_NE(solid.err.find("nothing was written"), std::string::npos) << solid.err;
        EXPECT_FALSE(std::filesystem::exists(stl));
    }
    const auto parts = test::runTsf(common + " --parts --json -o " + (dir / "a.3mf").string(), dir);
    ASSERT_EQ(parts.exit_code, test::kExitOk) << parts.out << parts.err;
    const auto j = nlohmann::json::parse(parts.out);
    EXPECT_EQ(j["verify"]["parts"]["passed"], true);
    EXPECT_NE(j["outputs"][0]["kind"].get<std::string>().find("4 parts: pillars, marks, legend, scale"),
              std::string::npos)
        << j["outputs"].dump();
}

TEST(PartsCli, PartsNeedA3mfAndPrintCheckAModelFile) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "f.csv", partsField());
    const auto stl = test::runTsf("gen " + (dir / "f.csv").string() + " --parts -o " + (dir / "m.stl").string(), dir);
    EXPECT_EQ(stl.exit_code, test::kExitBadInput) << stl.out << stl.err;
    EXPECT_NE(stl.err.find("--parts writes a 3MF"), std::string::npos) << stl.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "m.stl"));
    const auto scad = test::runTsf("gen " + (dir / "f.csv").string() + " --print-check --scad " + (dir / "m.scad").string(), dir);
    EXPECT_EQ(scad.exit_code, test::kExitBadInput) << scad.out << scad.err;
    EXPECT_NE(scad.err.find("--print-check slices the model file"), std::string::npos) << scad.err;
}

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

// A model is shared: it carries the input's file name, never the folders of
// the machine it was made on (STL header, 3MF object name and title).
TEST(PartsCli, AWrittenModelNamesTheInputFileNotItsFolders) {
    const auto dir = test::scratchDir();
    const std::string input = std::string(TSF_SOURCE_DIR) + "/examples/volcano.csv";
    const std::string folders = std::filesystem::path(TSF_SOURCE_DIR).filename().string() + "/examples";
    const auto stl = test::runTsf("gen " + input + " -o " + (dir / "v.stl").string(), dir);
    ASSERT_EQ(stl.exit_code, test::kExitOk) << stl.err;
    const std::string header = test::readText(dir / "v.stl").substr(0, 80);
    EXPECT_NE(header.find("volcano.csv"), std::string::npos) << header;
    EXPECT_EQ(header.find(folders), std::string::npos) << header;
    const auto tmf = test::runTsf("gen " + input + " --title Volcano --parts -o " + (dir / "v.3mf").string(), dir);
    ASSERT_EQ(tmf.exit_code, test::kExitOk) << tmf.err;
    const auto unzip = test::runCommand("unzip -p " + (dir / "v.3mf").string() + " 3D/3dmodel.model");
    ASSERT_EQ(unzip.exit_code, 0) << unzip.output;
    EXPECT_NE(unzip.output.find("volcano.csv"), std::string::npos);
    EXPECT_EQ(unzip.output.find(folders), std::string::npos) << unzip.output.substr(0, 2000);
    // And the OpenSCAD file a person edits and shares.
    const auto scad = test::runTsf("gen " + input + " --scad " + (dir / "v.scad").string(), dir);
    ASSERT_EQ(scad.exit_code, test::kExitOk) << scad.err;
    const std::string text = test::readText(dir / "v.scad");
    // Its Source line names the file; the Command line keeps the command as
    // typed, so the model can be made again.
    EXPECT_NE(text.find("// Source:    volcano.csv\n"), std::string::npos) << text.substr(0, 400);
}

}  // namespace
}  // namespace tsf
