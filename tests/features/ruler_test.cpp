// The edge ruler (gen/model/features/ruler/ruler.h): teeth along the south
// and west edges every N cells, each where the key says, joined into one
// closed solid, read back by tsf verify through the scene sidecar, drawn the
// same by both OpenSCAD engines, refused with exit 2 where it cannot stand.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <set>

#include "gen/key/model_key.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/ruler/ruler.h"
#include "gen/model/feature_records.h"
#include "gen/model/scene_json.h"
#include "gen/readers/esri_ascii_reader.h"
#include "gen/field/resample.h"
#include "gen/scad/scad_emitter.h"
#include "haptics/height_grid.h"
#include "verify/tactile.h"
#include "haptics/printed_relief.h"
#include "tests/scad_engines/engine_fixtures.h"
#include "tests/scad_engines/same_solid.h"
#include "tests/support/fields.h"
#include "tests/support/input_error.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "tests/support/verify_report.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;
using haptics::HeightGrid;
using haptics::printedRelief;
using haptics::ReliefInfo;

// A 20 x 12 raster of a gentle hill, every value above the floor.
HexField hill() {
    return test::fieldFromFunction(20, 12, [](int c, int r) { return 5.0 + std::sin(0.3 * c) + std::cos(0.4 * r); });
}

SceneParams rulerParams(std::optional<int> every = std::nullopt) {
    SceneParams p = test::smallParams();
    p.pitch_mm = 3.0;
    p.requests.set(RulerRequest{every});
    return p;
}

TEST(Ruler, TeethStandEveryNCellsFromTheSouthWestPillar) {
    const Scene s = buildScene(hill(), rulerParams());
    const SceneRuler* r = sceneRuler(s);
    ASSERT_TRUE(r);
    // 3 mm cells: 4 columns make 12 mm, the fewest at least 10 mm apart.
    EXPECT_EQ(r->every_x, 4);
    EXPECT_DOUBLE_EQ(r->spacing_x_mm, 12.0);
    EXPECT_GE(r->spacing_y_mm, 10.0);
    EXPECT_EQ(r->every_y % 2, 0);  // an even count of rows: every west line on rows that stick out
    EXPECT_LT(r->spacing_y_mm - 10.0, 2 * 3.0 * std::sqrt(3.0) / 2.0);  // two rows fewer would be closer than 10 mm
    // South: the southernmost row (11) holds every line's tooth, columns
    // 0, 4, 8, 12, 16 (a rectangle: every line has room).
    std::vector<int32_t> south_cols;
    std::set<int32_t> west_rows;
    for (const RulerTooth& t : r->teeth) {
        if (t.south) {
            south_cols.push_back(t.col);
            EXPECT_EQ(t.row, 11);
        } else {
            west_rows.insert(t.row);
            // Row 11 (odd) is shifted east: row 10's westernmost pillar sticks out.
            EXPECT_EQ((10 - t.row) % r->every_y, 0) << t.row;
            EXPECT_EQ(s.col[size_t(t.kept)], 0);
        }
    }
    EXPECT_EQ(south_cols, (std::vector<int32_t>{0, 4, 8, 12, 16}));
    EXPECT_EQ(r->lines_x, 5);
    EXPECT_GE(west_rows.size(), 2u);
    // Each tooth reaches 2 mm out from its pillar, from the bed to the floor.
    for (const RulerTooth& t : r->teeth) {
        double lo_x = INFINITY, lo_y = INFINITY;
        for (size_t i = 0; i < t.xy.size(); i += 2) {
            lo_x = std::min(lo_x, t.xy[i]);
            lo_y = std::min(lo_y, t.xy[i + 1]);
        }
        const Vec3 c = s.point(hexCentre(s.grid, t.col, t.row), 0);
        if (t.south) EXPECT_NEAR(c.y - lo_y, 3.0 / std::sqrt(3.0) + kRulerToothDepthMm, 2e-3);
        else EXPECT_NEAR(c.x - lo_x, 1.5 + kRulerToothDepthMm, 2e-3);
    }
    // The ridge stands 1 mm above the floor.
    EXPECT_EQ(r->top_units - s.floor_units, 1000);

    // --ruler 6: every six cells along both edges.
    const Scene six = buildScene(hill(), rulerParams(6));
    ASSERT_TRUE(sceneRuler(six));
    EXPECT_EQ(sceneRuler(six)->every_x, 6);
    EXPECT_EQ(sceneRuler(six)->every_y, 6);
    EXPECT_TRUE(sceneRuler(six)->every_given);
}

TEST(Ruler, OneClosedSolidWhoseTeethStandWhereTheSceneSays) {
    const Scene s = buildScene(hill(), rulerParams());
    const Mesh m = meshScene(s);
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    // The teeth add their prisms to the pillars' volume, no more.
    double teeth = 0;
    for (const RulerTooth& t : sceneRuler(s)->teeth) {
        double a = 0;
        for (size_t i = 0; i < t.xy.size(); i += 2) {
            const size_t j = (i + 2) % t.xy.size();
            a += t.xy[i] * t.xy[j + 1] - t.xy[j] * t.xy[i + 1];
        }
        double ridge = 0;
        for (size_t i = 0; i < t.ridge.size(); i += 2) {
            const size_t j = (i + 2) % t.ridge.size();
            ridge += t.ridge[i] * t.ridge[j + 1] - t.ridge[j] * t.ridge[i + 1];
        }
        teeth += 0.5 * a * s.zMm(s.floor_units) + 0.5 * ridge * kRulerToothRiseMm;
    }
    Scene without = buildScene(hill(), test::smallParams());
    EXPECT_FALSE(sceneRuler(without));
    EXPECT_NEAR(signedVolume(m), test::sceneVolume(s) + teeth, 1e-6 * test::sceneVolume(s));
}

TEST(Ruler, TheKeySaysWhichColumnAndRowEachToothMarks) {
    const Scene s = buildScene(hill(), rulerParams());
    std::string text;
    for (const std::string& line : modelKeyParagraphs(s, {})) text += line + "\n";
    EXPECT_NE(text.find("the teeth mark columns 1, 5, 9, 13 and 17 of 20, counted from the west (every 4, 12 "
                        "millimetres apart)"),
              std::string::npos)
        << text;
    std::string rows;
    std::vector<int32_t> listed;
    for (const RulerTooth& t : sceneRuler(s)->teeth)
        if (!t.south) listed.push_back(s.grid.rows - t.row);
    ASSERT_GE(listed.size(), 2u);
    EXPECT_NE(text.find("the teeth mark rows " + std::to_string(listed[0]) + ", "), std::string::npos) << text;
}

// An ESRI grid says where its cells lie: the key gives the x and y each
// tooth marks, the centres of the cells the teeth stand at, worked out
// here from the header (one pillar per value: pixel (c, r) is centred at
// xllcorner + (c + 0.5) cellsize, yllcorner + (rows - r - 0.5) cellsize).
// A field without coordinates gives only the columns and rows.
TEST(Ruler, TheKeySaysTheDataCoordinatesEachToothMarks) {
    std::string grid = "ncols 20\nnrows 12\nxllcorner 987.5\nyllcorner 4987.5\ncellsize 25\n";
    for (int r = 0; r < 12; ++r) {
        for (int c = 0; c < 20; ++c) grid += std::to_string(5.0 + std::sin(0.3 * c) + std::cos(0.4 * r)) + " ";
        grid += "\n";
    }
    const HexField f = rasterOneToOne(parseEsriAscii(grid, "hill.asc"));
    const Scene s = buildScene(f, rulerParams());
    std::string text;
    for (const std::string& line : modelKeyParagraphs(s, {})) text += line + "\n";
    // Columns 1, 5, 9, 13 and 17: x 987.5 + 12.5 + 25 * (column - 1).
    EXPECT_NE(text.find("the teeth mark columns 1, 5, 9, 13 and 17 of 20, counted from the west (every 4, 12 "
                        "millimetres apart). They stand at x 1000, 1100, 1200, 1300 and 1400, 100 apart."),
              std::string::npos)
        << text;
    // Row k counted from the south: y 4987.5 + 25 * (k - 0.5).
    std::string rows = "They stand at y ";
    std::vector<int32_t> listed;
    for (const RulerTooth& t : sceneRuler(s)->teeth)
        if (!t.south) listed.push_back(s.grid.rows - t.row);
    ASSERT_GE(listed.size(), 2u);
    for (size_t k = 0; k < listed.size(); ++k)
        rows += (k == 0 ? "" : k + 1 == listed.size() ? " and " : ", ") +
                std::to_string(int(4987.5 + 25 * (listed[k] - 0.5)));  // four digits: no comma (formatForReader)
    EXPECT_NE(text.find(rows + ", 100 apart."), std::string::npos) << text;

    // The summary's JSON says the same to a program.
    nlohmann::json facts;
    for (const FeatureFacts& f : featureFacts())
        if (std::string(f.path) == "ruler") facts = f.json(s);
    ASSERT_TRUE(facts.is_object());
    EXPECT_EQ(facts["data_axes"]["x"], "x");
    EXPECT_DOUBLE_EQ(facts["south_teeth"][1]["x"].get<double>(), 1100.0);
    EXPECT_DOUBLE_EQ(facts["west_teeth"][0]["y"].get<double>(), 4987.5 + 25 * (listed[0] - 0.5));

    std::string plain;
    for (const std::string& line : modelKeyParagraphs(buildScene(hill(), rulerParams()), {})) plain += line + "\n";
    EXPECT_EQ(plain.find("They stand at"), std::string::npos) << plain;
}

TEST(Ruler, TsfFeelFeelsEachToothBesideTheEdge) {
    const Scene s = buildScene(hill(), rulerParams());
    ReliefInfo info;
    const HeightGrid g = printedRelief(s, &info);
    const double side = info.sample_mm, max_mm = s.mapping.max_height_mm;
    auto feltAt = [&](double x_mm, double y_mm) {  // mm above the floor
        const auto i = int32_t(std::floor(x_mm / side)) + info.origin_i, j = int32_t(std::floor(y_mm / side)) + info.origin_j;
        EXPECT_TRUE(i >= 0 && i < g.cols && j >= 0 && j < g.rows) << x_mm << ", " << y_mm;
        return double(g.at(std::clamp(i, 0, g.cols - 1), std::clamp(j, 0, g.rows - 1))) * max_mm;
    };
    const SceneRuler& r = *sceneRuler(s);
    int felt = 0;
    for (const RulerTooth& t : r.teeth) {
        // The ridge's middle: 1 mm above the floor.
        const double x = 0.25 * (t.ridge[0] + t.ridge[2] + t.ridge[4] + t.ridge[6]);
        const double y = 0.25 * (t.ridge[1] + t.ridge[3] + t.ridge[5] + t.ridge[7]);
        EXPECT_NEAR(feltAt(x, y), kRulerToothRiseMm, 1e-4) << x << ", " << y;
        if (!t.south) continue;
        // Half way to the next line, at the same y: nothing, felt as the floor.
        EXPECT_NEAR(feltAt(x + 0.5 * r.spacing_x_mm, y), 0.0, 1e-6);
        ++felt;
    }
    EXPECT_GE(felt, 2);
}

TEST(Ruler, TheTactileCheckProvesEachRidgeAsPrinted) {
    Scene s = buildScene(hill(), rulerParams());
    const Mesh m = meshScene(s);
    const auto featureCheck = [&](const Scene& scene, double layer_mm) {
        TactileOptions o;
        o.layer_mm = layer_mm;
        for (const Check& c : checkTactile(m, &scene, o).checks)
            if (c.id == "tactile_features") return c;
        ADD_FAILURE() << "no tactile_features check";
        return Check{};
    };
    EXPECT_EQ(featureCheck(s, 0.2).status, CheckStatus::Pass);
    EXPECT_EQ(featureCheck(s, 0.3).status, CheckStatus::Pass);  // 1 mm prints 0.9 mm: found
    // A ridge 0.3 mm high: one 0.2 mm layer... less than 0.5 mm, and none at 0.4 mm layers.
    s.features.get<SceneRuler>()->top_units = s.floor_units + 300;
    const Check low = featureCheck(s, 0.4);
    EXPECT_EQ(low.status, CheckStatus::Fail);
    EXPECT_EQ(low.count, sceneRuler(s)->teeth.size());
    ASSERT_FALSE(low.worst.empty());
    EXPECT_NE(low.worst[0].detail.find("tooth of"), std::string::npos) << low.worst[0].detail;
}

TEST(Ruler, TheSidecarHoldsTheTeethAsPlaced) {
    const Scene s = buildScene(hill(), rulerParams(5));
    const fs::path dir = test::scratchDir("ruler_sidecar");
    writeSceneJson(s, (dir / "m.scene.json").string());
    const Scene back = readSceneJson((dir / "m.scene.json").string());
    ASSERT_TRUE(sceneRuler(back));
    ASSERT_EQ(sceneRuler(back)->teeth.size(), sceneRuler(s)->teeth.size());
    for (size_t k = 0; k < sceneRuler(s)->teeth.size(); ++k) {
        EXPECT_EQ(sceneRuler(back)->teeth[k].xy, sceneRuler(s)->teeth[k].xy);
        EXPECT_EQ(sceneRuler(back)->teeth[k].kept, sceneRuler(s)->teeth[k].kept);
    }
    EXPECT_EQ(meshScene(back).positions, meshScene(s).positions);
}

TEST(Ruler, WhereItCannotStandItIsRefused) {
    SceneParams mirrored = rulerParams();
    mirrored.bottom = Bottom::Mirrored;
    EXPECT_NE(std::string(test::catchInputError([&] { buildScene(hill(), mirrored); }).what()).find("--mirror"),
              std::string::npos);
    const auto dir = test::scratchDir("ruler_refused");
    test::writeText(dir / "f.csv", "1,2\n3,4\n");
    const auto r = test::runTsf("gen " + (dir / "f.csv").string() + " --ruler 1 -o " + (dir / "m.stl").string(), dir);
    EXPECT_EQ(r.exit_code, test::kExitBadInput) << r.out << r.err;
    EXPECT_NE(r.err.find("--ruler"), std::string::npos) << r.err;
    EXPECT_FALSE(fs::exists(dir / "m.stl"));
    // A model cut into tiles cannot carry it: the message names the option.
    std::string csv;
    for (int r = 0; r < 40; ++r)
        for (int c = 0; c < 40; ++c) csv += std::to_string(1 + (c + r) % 7) + (c < 39 ? "," : "\n");
    test::writeText(dir / "big.csv", csv);
    const auto t = test::runTsf("gen " + (dir / "big.csv").string() + " --cell 4 --ruler --bed 100x100 --tile -o " +
                                (dir / "t.stl").string(), dir);
    EXPECT_EQ(t.exit_code, test::kExitBadInput) << t.out << t.err;
    EXPECT_NE(t.err.find("leave out --ruler"), std::string::npos) << t.err;
}

TEST(RulerCli, GenWritesTheTeethAndVerifyReadsThemBack) {
    const auto dir = test::scratchDir("ruler_cli");
    std::string csv;
    for (int r = 0; r < 16; ++r)
        for (int c = 0; c < 16; ++c) csv += std::to_string(2 + (c * 7 + r * 3) % 11) + (c < 15 ? "," : "\n");
    test::writeText(dir / "f.csv", csv);
    const std::string model = (dir / "m.stl").string();
    const auto g = test::runTsf("gen " + (dir / "f.csv").string() + " --cell 4 --ruler --json -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.out << g.err;
    const auto j = nlohmann::json::parse(g.out);
    const auto& ruler = j["scene"]["ruler"];
    ASSERT_TRUE(ruler.is_object()) << j["scene"].dump(2);
    EXPECT_EQ(ruler["every"][0].get<int>(), 3);  // 4 mm cells: 12 mm
    EXPECT_GE(ruler["south_teeth"].size(), 2u);

    const Mesh m = readMesh(model);
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --json", dir);
    ASSERT_EQ(v.exit_code, test::kExitOk) << v.out << v.err;
    EXPECT_EQ(test::checkStatus(v.out, "ruler_read_back"), "pass") << v.out;
}

// The teeth written as data and joined to the pillars by each engine: the
// same solid as the direct mesher's exact join, with the polyhedron
// strategy (joined into the terrain's polyhedron) and the CSG one (a union
// of prisms, scad_lib/tsf_ruler.scad).
class RulerOpenScad : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(RulerOpenScad, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name] = GetParam();
    TSF_NEED_ENGINE(test::engineNamed(engine_name));
    const Scene scene = buildScene(test::fieldFromFunction(9, 7, [](int c, int r) { return 1.0 + (c + 2 * r) % 5; }),
                                   rulerParams(2));
    ASSERT_TRUE(sceneRuler(scene));
    ASSERT_GE(sceneRuler(scene)->teeth.size(), 4u);
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    opts.inline_library = strategy_name == "csg";
    const fs::path dir = test::scratchDir("ruler_" + engine_name + "_" + strategy_name);
    writeScad(scene, opts, (dir / "model.scad").string());
    test::expectSameSolid(*test::engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(EnginesStrategies, RulerOpenScad,
                         ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg")),
                         [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

}  // namespace
}  // namespace tsf
