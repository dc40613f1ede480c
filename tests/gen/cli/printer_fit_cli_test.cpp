// tsf gen --bed / --nozzle / --layer: the model is shaped for one printer
// (fitted into the bed less its margins, heights on whole layers, raster
// cells a nozzle prints as pillars), and a model larger than the bed is
// refused with what does fit: the --cell that would (never below 3 mm), or
// the bed it needs.
#include <gtest/gtest.h>

#include <cmath>
#include <regex>
#include <string>

#include <nlohmann/json.hpp>

#include "gen/mesh_io/mesh_reader.h"
#include "tests/support/files.h"
#include "tests/support/run.h"

namespace tsf {
namespace {

const std::string kAirports = "--points x=lon,y=lat --bins 40";

std::string airports() { return test::sourcePath("examples/airports-europe.csv"); }

TEST(PrinterFitCli, BedWithoutWidthFitsTheModelInsideTheMargins) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + airports() + " " + kAirports + " --bed 120x100 --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const Bounds b = meshBounds(readMesh(model));
    EXPECT_LE(b.max.x - b.min.x, 110.0 + 1e-9);  // 120 less 5 mm on each side
    EXPECT_LE(b.max.y - b.min.y, 90.0 + 1e-9);
    // It fills the bed in one direction: the default 150 mm box would not fit.
    EXPECT_GT(std::max(b.max.x - b.min.x - 105.0, b.max.y - b.min.y - 85.0), 0.0);
    const auto j = nlohmann::json::parse(r.out);
    // The orientation tab west of the pillars does not grow with the cell: the pillars get the rest.
    ASSERT_EQ(j["printer"].size(), 2u) << j["printer"].dump();
    EXPECT_NE(j["printer"][0].get<std::string>().find("the orientation tab 23 mm"), std::string::npos) << j["printer"].dump();
    EXPECT_NE(j["printer"][1].get<std::string>().find("87 x 90 mm: the 120 x 100 mm bed"), std::string::npos) << j["printer"].dump();
}

TEST(PrinterFitCli, LayerSnapsEveryHeightToWholeLayersUnlessSnapIsGiven) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + airports() + " " + kAirports + " --layer 0.25 --no-verify -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    const Mesh m = readMesh(model);
    size_t off_layer = 0, levels_above_base = 0;
    for (const Vec3& p : m.positions) {
        const double layers = p.z / 0.25;
        if (std::fabs(layers - std::round(layers)) > 1e-6) ++off_layer;
        if (p.z > 2.0 + 1e-9) ++levels_above_base;
    }
    EXPECT_EQ(off_layer, 0u);
    EXPECT_GT(levels_above_base, 0u);

    // --snap wins over --layer.
    const auto snapped = test::runTsf("gen " + airports() + " " + kAirports + " --layer 0.25 --snap 0.1 --no-verify -o " + model, dir);
    ASSERT_EQ(snapped.exit_code, test::kExitOk) << snapped.out << snapped.err;
    size_t off = 0;
    for (const Vec3& p : readMesh(model).positions) off += std::fabs(p.z / 0.25 - std::round(p.z / 0.25)) > 1e-6;
    EXPECT_GT(off, 0u);
}

TEST(PrinterFitCli, AModelLargerThanTheBedIsRefusedWithACellThatFits) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const auto big = test::runTsf("gen " + airports() + " " + kAirports + " --bed 220x220 --cell 6 -o " + model, dir);
    EXPECT_EQ(big.exit_code, test::kExitBadInput) << big.out << big.err;
    EXPECT_NE(big.err.find("larger than the 220 x 220 mm bed"), std::string::npos) << big.err;
    // The pillars scale with the cell, the 23 mm tab beside them does not:
    // 40 columns of 6 mm are 243 of the 266 mm, 210 - 23 = 187 mm are left,
    // 6 x 187 / 243 = 4.6 mm; the model at that cell was made and fits.
    EXPECT_NE(big.err.find("give --cell 4.61 or less (tried: it fits)"), std::string::npos) << big.err;
    EXPECT_FALSE(std::filesystem::exists(model));
    // The suggestion works, and fills the bed's width.
    const auto fits = test::runTsf("gen " + airports() + " " + kAirports + " --bed 220x220 --cell 4.61 --no-verify -o " + model, dir);
    EXPECT_EQ(fits.exit_code, test::kExitOk) << fits.out << fits.err;
    EXPECT_GT(meshBounds(readMesh(model)).max.x - meshBounds(readMesh(model)).min.x, 205.0);

    const auto wide = test::runTsf("gen " + airports() + " " + kAirports + " --bed 120x100 --width 150 -o " + model, dir);
    EXPECT_EQ(wide.exit_code, test::kExitBadInput) << wide.err;
    EXPECT_NE(wide.err.find("give --width 110 or less"), std::string::npos) << wide.err;

    const auto bad = test::runTsf("gen " + airports() + " " + kAirports + " --bed 120 -o " + model, dir);
    EXPECT_EQ(bad.exit_code, test::kExitBadInput) << bad.err;
    EXPECT_NE(bad.err.find("--bed: expected WIDTHxDEPTH"), std::string::npos) << bad.err;
}

// On a bed too small for the pillars at the 3 mm a fingertip tells apart,
// tsf never advises a smaller cell: it gives the model's size at 3 mm and
// the bed that holds it (tried), or --tile.
TEST(PrinterFitCli, NeverAdvisesACellBelowTheTactileMinimum) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const auto small = test::runTsf("gen " + airports() + " " + kAirports + " --bed 120x100 --cell 4 -o " + model, dir);
    EXPECT_EQ(small.exit_code, test::kExitBadInput) << small.out << small.err;
    EXPECT_EQ(small.err.find("give --cell"), std::string::npos) << small.err;
    // 40 columns at 3 mm are 121.5 mm, with the 23 mm tab 144.5 mm: a bed of 155 mm (5 mm margins) holds it.
    EXPECT_NE(small.err.find("at --cell 3, the smallest a fingertip tells apart"), std::string::npos) << small.err;
    std::smatch advised;
    ASSERT_TRUE(std::regex_search(small.err, advised, std::regex(R"(\(--bed (155)x(\d+)\))"))) << small.err;
    EXPECT_NE(small.err.find("--tile"), std::string::npos) << small.err;
    EXPECT_NE(small.err.find("takes 23 mm of the width"), std::string::npos) << small.err;
    // The bed it names holds the model: tried here, as tsf tried it.
    const std::string bed = advised[1].str() + "x" + advised[2].str();
    const auto there = test::runTsf("gen " + airports() + " " + kAirports + " --bed " + bed + " --cell 3 --no-verify -o " + model, dir);
    EXPECT_EQ(there.exit_code, test::kExitOk) << there.out << there.err;
}

// A raster taller than the bed with the legend north and the scale east:
// what stands beside the pillars takes the bed's depth and width from them,
// and the raster is resampled again for what is left, to fewer cells at
// least 3 mm across (not the same cells squeezed narrower), and fits.
TEST(PrinterFitCli, TheBedFitCountsWhatStandsBesideAndKeepsCellsReadable) {
    const auto dir = test::scratchDir();
    std::string csv;
    for (int r = 0; r < 100; ++r) {
        for (int c = 0; c < 30; ++c) csv += (c ? "," : "") + std::to_string(100 + (c * 7 + r * 3) % 50);
        csv += "\n";
    }
    test::writeText(dir / "tall.csv", csv);
    const std::string model = (dir / "m.stl").string();
    const auto r = test::runTsf("gen " + (dir / "tall.csv").string() + " --scale --title T --units m --bed 220x220 --json -o " + model, dir);
    ASSERT_EQ(r.exit_code, test::kExitOk) << r.out << r.err;
    EXPECT_GE(nlohmann::json::parse(r.out)["scene"]["pitch_mm"].get<double>(), 3.0 - 1e-9) << r.out;
    const Bounds b = meshBounds(readMesh(model));
    EXPECT_LE(b.max.x - b.min.x, 210.0);
    EXPECT_LE(b.max.y - b.min.y, 210.0);
}

TEST(PrinterFitCli, AWideNozzleMakesRasterCellsFourNozzleWidthsAcross) {
    const auto dir = test::scratchDir();
    const std::string model = (dir / "m.stl").string();
    const std::string volcano = test::sourcePath("examples/volcano.csv");
    const auto plain = test::runTsf("gen " + volcano + " --no-verify --json -o " + model, dir);
    ASSERT_EQ(plain.exit_code, test::kExitOk) << plain.err;
    const double plain_cell = nlohmann::json::parse(plain.out)["scene"]["pitch_mm"].get<double>();
    const auto wide = test::runTsf("gen " + volcano + " --nozzle 1.0 --no-verify --json -o " + model, dir);
    ASSERT_EQ(wide.exit_code, test::kExitOk) << wide.err;
    const double wide_cell = nlohmann::json::parse(wide.out)["scene"]["pitch_mm"].get<double>();
    EXPECT_LT(plain_cell, 4.0);
    EXPECT_GE(wide_cell, 4.0);

    // Cells asked for narrower than that are noted, not refused.
    const auto narrow = test::runTsf("gen " + volcano + " --nozzle 1.0 --cell 2 --no-verify -o " + model, dir);
    EXPECT_EQ(narrow.exit_code, test::kExitOk) << narrow.err;
    EXPECT_NE(narrow.out.find("narrower than 4 widths of the 1 mm nozzle"), std::string::npos) << narrow.out;
}

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

TEST(PrinterFitCli, LayerErrorsNameTheOptionsTheUserGave) {
    const auto dir = test::scratchDir();
    const std::string in = test::sourcePath("examples/volcano.csv"), out = (dir / "m.stl").string();
    // The help's range is what is accepted: a 2 mm layer is refused as --layer, not as a --snap never given.
    const auto tall = test::runTsf("gen " + in + " --layer 2 -o " + out, dir);
    EXPECT_EQ(tall.exit_code, test::kExitBadInput);
    EXPECT_NE(tall.err.find("--layer"), std::string::npos) << tall.err;
    EXPECT_EQ(tall.err.find("snap"), std::string::npos) << tall.err;
    const auto thin = test::runTsf("gen " + in + " --layer 1 --base 0.5 -o " + out, dir);
    EXPECT_EQ(thin.exit_code, test::kExitBadInput);
    EXPECT_NE(thin.err.find("--layer 1"), std::string::npos) << thin.err;
    EXPECT_NE(thin.err.find("--base 0.5"), std::string::npos) << thin.err;
    EXPECT_FALSE(std::filesystem::exists(out));
}

}  // namespace
}  // namespace tsf
