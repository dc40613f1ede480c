// tsf print-check end to end with the real PrusaSlicer: a pillar model from
// tsf gen prints without supports in height / layer layers; a solid with a
// slab overhanging a stem needs supports; bad input and a missing slicer
// give their exit codes.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "tests/support/meshes.h"
#include "tests/support/run.h"
#include "runners/process_runner.h"
#include "tests/support/required_tools.h"

namespace tsf {
namespace {

bool haveSlicer() { return !findExecutable("prusa-slicer").empty(); }

#define REQUIRE_SLICER() TSF_NEED_TOOL(haveSlicer(), "prusa-slicer")

nlohmann::json printCheck(const std::string& args, const std::filesystem::path& dir) {
    const test::RunResult r = test::runTsf("print-check " + args + " --json", dir);
    EXPECT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    return r.exit_code == 0 ? nlohmann::json::parse(r.out) : nlohmann::json::object();
}

TEST(PrintCheckCli, PillarModelPrintsWithoutSupportsInHeightOverLayerLayers) {
    REQUIRE_SLICER();
    const auto dir = test::scratchDir();
    test::writeText(dir / "field.csv", "1,2,3\n2,3,4\n3,4,5\n");
    const std::string model = (dir / "pillars.stl").string();
    const auto gen = test::runTsf("gen " + (dir / "field.csv").string() + " --width 30 --depth 30 --height 6 -o " + model, dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.out << gen.err;
    const Bounds b = meshBounds(readMesh(model));
    const double height_mm = b.max.z - b.min.z;

    for (const double layer_mm : {0.2, 0.3}) {
        const auto j = printCheck(model + " --layer " + std::to_string(layer_mm), dir);
        ASSERT_TRUE(j.contains("layers")) << j.dump(2);
        EXPECT_EQ(j["layers"].get<int>(), int(std::ceil(height_mm / layer_mm - 1e-6))) << "height " << height_mm;
        EXPECT_EQ(j["repair_needed"], false);
        EXPECT_EQ(j["parts"], 1);
        EXPECT_EQ(j["supports_needed"], false);
        EXPECT_EQ(j["with_supports"]["support_extruded"], false);
        EXPECT_GT(j["filament_mm"].get<double>(), 0);
        EXPECT_GT(j["filament_cm3"].get<double>(), 0);
        // Mass = volume x the density given to the slicer (1.24 g/cm3 by default).
        EXPECT_NEAR(j["filament_g"].get<double>(), 1.24 * j["filament_cm3"].get<double>(), 0.02);
        EXPECT_GT(j["print_time_s"].get<double>(), 60);
        EXPECT_NEAR(j["without_supports"]["max_z_mm"].get<double>(), height_mm, layer_mm);
    }
    // Halving the layer height means more layers and more time.
    const auto fine = printCheck(model + " --layer 0.1", dir);
    const auto coarse = printCheck(model + " --layer 0.2", dir);
    EXPECT_GT(fine["layers"].get<int>(), coarse["layers"].get<int>());
    EXPECT_GT(fine["print_time_s"].get<double>(), coarse["print_time_s"].get<double>());
}

TEST(PrintCheckCli, SlabOverAStemNeedsSupportsAndSaysHowMuchMore) {
    REQUIRE_SLICER();
    const auto dir = test::scratchDir();
    // A 6 x 6 x 10 mm stem carrying a 30 x 30 x 2 mm slab: 864 mm^2 hang in the air.
    const Mesh table =
        test::append(test::box({12, 12, 0}, {18, 18, 10}), test::box({0, 0, 10}, {30, 30, 12}));
    const std::string model = (dir / "table.stl").string();
    writeMesh(table, model);
    const auto j = printCheck(model, dir);
    ASSERT_TRUE(j.contains("supports_needed")) << j.dump(2);
    EXPECT_EQ(j["supports_needed"], true);
    EXPECT_EQ(j["with_supports"]["support_extruded"], true);
    EXPECT_GT(j["with_supports"]["filament_cm3"].get<double>(), j["without_supports"]["filament_cm3"].get<double>());
    EXPECT_EQ(j["layers"].get<int>(), 60);  // 12 mm at 0.2 mm

    const auto text = test::runTsf("print-check " + model, dir);
    EXPECT_EQ(text.exit_code, 0) << text.out << text.err;
    EXPECT_NE(text.out.find("supports:          NEEDED"), std::string::npos) << text.out;
}

TEST(PrintCheckCli, BadInputIsExitTwoAndAMissingSlicerExitThree) {
    const auto dir = test::scratchDir();
    test::writeText(dir / "junk.stl", "solid x\n  facet normal 0 0 1\n    outer loop\n");
    const auto junk = test::runTsf("print-check " + (dir / "junk.stl").string(), dir);
    EXPECT_EQ(junk.exit_code, test::kExitBadInput) << junk.out << junk.err;
    EXPECT_NE(junk.err.find("junk.stl"), std::string::npos) << junk.err;

    const std::string wide = (dir / "wide.stl").string();
    writeMesh(test::box({0, 0, 0}, {260, 20, 5}), wide);
    const auto big = test::runTsf("print-check " + wide + " --bed 250x210", dir);
    EXPECT_EQ(big.exit_code, test::kExitBadInput) << big.out << big.err;
    EXPECT_NE(big.err.find("larger than the 250 x 210 mm bed"), std::string::npos) << big.err;

    const auto bad_bed = test::runTsf("print-check " + wide + " --bed 250", dir);
    EXPECT_EQ(bad_bed.exit_code, test::kExitBadInput) << bad_bed.err;

    const std::string small = (dir / "small.stl").string();
    writeMesh(test::box({0, 0, 0}, {20, 20, 5}), small);
    const auto none = test::runTsf("print-check " + small + " --slicer " + (dir / "no-such-slicer").string(), dir);
    EXPECT_EQ(none.exit_code, test::kExitToolFailed) << none.out << none.err;
    EXPECT_NE(none.err.find("prusa-slicer"), std::string::npos) << none.err;
}

// tsf gen --parts --parts-layout prusaslicer --print-check: PrusaSlicer
// loads the 3MF as ONE object (its --info prints one block) whose volumes
// are the parts, and the gen summary carries the print check (time,
// filament). The portable layout (the default) is three objects to
// PrusaSlicer, sliced in place: the same layers, time and filament.
TEST(PrintCheckCli, MultiPart3mfIsOneObjectToPrusaSlicerAndGenPrintChecksIt) {
    REQUIRE_SLICER();
    const auto dir = test::scratchDir();
    std::string csv;
    for (int r = 0; r < 10; ++r) {  // a varied strip in the north, a flat region for the triangle
        for (int c = 0; c < 14; ++c) csv += (c ? "," : "") + std::to_string(r >= 3 ? 4 : (c + r) % 3);
        csv += "\n";
    }
    test::writeText(dir / "field.csv", csv);
    const std::string model = (dir / "parts.3mf").string();
    const auto gen = test::runTsf("gen " + (dir / "field.csv").string() +
                                      " --cell 4 --height 4 --title T --parts --parts-layout prusaslicer --print-check "
                                      "--layer 0.3 --json -o " + model,
                                  dir);
    ASSERT_EQ(gen.exit_code, test::kExitOk) << gen.out << gen.err;
    const auto j = nlohmann::json::parse(gen.out);
    ASSERT_TRUE(j.contains("print_check")) << j.dump(2);
    ASSERT_EQ(j["verify"]["parts"]["parts"].size(), 3u);  // pillars, marks, legend
    EXPECT_EQ(j["print_check"]["objects"], 1);
    EXPECT_EQ(j["print_check"]["repair_needed"], false);
    EXPECT_GT(j["print_check"]["print_time_s"].get<double>(), 0);
    EXPECT_GT(j["print_check"]["filament_g"].get<double>(), 0);
    EXPECT_DOUBLE_EQ(j["print_check"]["settings"]["layer_mm"].get<double>(), 0.3);  // --layer reaches the slicer

    // PrusaSlicer's own --info: one object of all the parts' triangles.
    const auto info = test::runCommand("prusa-slicer --loglevel 1 --datadir " + (dir / "ps").string() + " --info " + model);
    ASSERT_EQ(info.exit_code, 0) << info.output;
    size_t blocks = 0;
    for (size_t at = info.output.find("number_of_facets"); at != std::string::npos;
         at = info.output.find("number_of_facets", at + 1))
        ++blocks;
    EXPECT_EQ(blocks, 1u) << info.output;
    size_t triangles = 0;
    for (const MeshPart& p : readMeshParts(model)) triangles += p.mesh.triangleCount();
    EXPECT_NE(info.output.find("number_of_facets = " + std::to_string(triangles)), std::string::npos) << info.output;

    const std::string portable = (dir / "portable.3mf").string();
    const auto gen2 = test::runTsf("gen " + (dir / "field.csv").string() +
                                       " --cell 4 --height 4 --title T --parts --print-check --layer 0.3 --json -o " + portable,
                                   dir);
    ASSERT_EQ(gen2.exit_code, test::kExitOk) << gen2.out << gen2.err;
    const auto j2 = nlohmann::json::parse(gen2.out);
    EXPECT_EQ(j2["print_check"]["objects"], 3);
    EXPECT_EQ(j2["print_check"]["layers"], j["print_check"]["layers"]);
    EXPECT_NEAR(j2["print_check"]["print_time_s"].get<double>(), j["print_check"]["print_time_s"].get<double>(),
                0.01 * j["print_check"]["print_time_s"].get<double>());
    EXPECT_NEAR(j2["print_check"]["filament_g"].get<double>(), j["print_check"]["filament_g"].get<double>(),
                0.01 * j["print_check"]["filament_g"].get<double>());
}

// tsf coupon's piece prints in under an hour at 0.2 mm layers (PrusaSlicer's estimate).
TEST(PrintCheckCli, TheCalibrationCouponPrintsInUnderAnHour) {
    REQUIRE_SLICER();
    const auto dir = test::scratchDir();
    const std::string model = (dir / "coupon.stl").string();
    const test::RunResult c = test::runTsf("coupon -o " + model, dir);
    ASSERT_EQ(c.exit_code, 0) << c.out << c.err;
    const nlohmann::json j = printCheck(model, dir);
    ASSERT_TRUE(j.contains("print_time_s")) << j.dump();
    EXPECT_LT(j["print_time_s"].get<double>(), 3600.0) << j.dump();
    EXPECT_GT(j["print_time_s"].get<double>(), 600.0) << "a real piece, not an empty one: " << j.dump();
}

// The tiles of tsf gen --tile checked together: each piece reported, and
// the total is the sum of the pieces' own figures.
TEST(PrintCheckCli, TilesAreEachReportedAndSummed) {
    REQUIRE_SLICER();
    const auto dir = test::scratchDir();
    std::string csv;
    for (int r = 0; r < 12; ++r) {
        for (int c = 0; c < 24; ++c) csv += (c ? "," : "") + std::to_string((c * 3 + r * 5) % 7 + 1);
        csv += "\n";
    }
    test::writeText(dir / "field.csv", csv);
    const auto gen = test::runTsf("gen " + (dir / "field.csv").string() +
                                      " --cell 4 --height 4 --bed 70x70 --tile --json -o " + (dir / "m.stl").string(),
                                  dir);
    ASSERT_EQ(gen.exit_code, 0) << gen.out << gen.err;
    const auto files = nlohmann::json::parse(gen.out)["tiles"]["files"];
    ASSERT_GE(files.size(), 2u);
    std::string args;
    for (const auto& f : files) args += f.get<std::string>() + " ";
    const auto j = printCheck(args + "--bed 70x70", dir);
    ASSERT_EQ(j["pieces"].size(), files.size()) << j.dump(2);
    double time = 0, grams = 0;
    for (const auto& p : j["pieces"]) {
        EXPECT_EQ(p["supports_needed"], false) << p["model"];  // flat tiles, code pits printed face down
        time += p["print_time_s"].get<double>();
        grams += p["filament_g"].get<double>();
    }
    EXPECT_EQ(j["total"]["pieces"], files.size());
    EXPECT_NEAR(j["total"]["print_time_s"].get<double>(), time, 1e-6);
    EXPECT_NEAR(j["total"]["filament_g"].get<double>(), grams, 1e-6);
    EXPECT_EQ(j["total"]["pieces_needing_supports"], 0);
}

}  // namespace
}  // namespace tsf
