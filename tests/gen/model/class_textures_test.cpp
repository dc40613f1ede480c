// Class textures (gen/model/features/class_textures.h): a class map's
// classes stand at one height and are told apart by the feel of their tops.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <set>
#include <tuple>

#include <nlohmann/json.hpp>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene_scale.h"
#include "gen/model/features/class_textures.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene_json.h"
#include "gen/util/error.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "tests/support/run.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

using test::fieldFromFunction;

// Three classes over 10 x 6 cells: 41 on 30 cells (west half), 11 on 18
// (east, north rows), 90 on 12 (east, south rows).
HexField threeClasses() {
    HexField f = fieldFromFunction(10, 6, [](int c, int r) { return c < 5 ? 41.0 : r < 2 ? 90.0 : 11.0; });
    f.input.categorical = true;
    return f;
}

void expectVerified(const Scene& s, const char* what) {
    const Mesh mesh = meshScene(s);
    VerifyOptions vo;
    const VerifyReport r = verifyModel(mesh, &s, vo);
    EXPECT_TRUE(r.passed()) << what << "\n" << formatReport(r);
}

TEST(ClassTextures, TheCommonestClassesGetTheTexturesInTurnAtOneHeight) {
    const Scene s = buildScene(threeClasses(), test::smallParams());
    ASSERT_TRUE(sceneTextures(s));
    ASSERT_EQ(sceneTextures(s)->classes.size(), 3u);
    EXPECT_EQ(sceneTextures(s)->classes[0].code, 41.0);
    EXPECT_EQ(sceneTextures(s)->classes[0].texture, Texture::Level);
    EXPECT_EQ(sceneTextures(s)->classes[1].code, 11.0);
    EXPECT_EQ(sceneTextures(s)->classes[1].texture, Texture::RidgesEastWest);
    EXPECT_EQ(sceneTextures(s)->classes[2].code, 90.0);
    EXPECT_EQ(sceneTextures(s)->classes[2].texture, Texture::Dimples);
    EXPECT_EQ(sceneTextures(s)->textures_used, 3);
    // 5 mm cells: the full 1 mm relief leans atan(1 / 2.5) = 21.8 degrees at
    // most, under the 26.6 a top may; every class 2 mm above the 2 mm base.
    EXPECT_EQ(sceneTextures(s)->relief_units, 1000);
    EXPECT_EQ(sceneTextures(s)->height_units, 2000);
    for (size_t k = 0; k < s.keptCount(); ++k) EXPECT_EQ(s.top[k], 4000) << "one height for every class";

    for (size_t k = 0; k < s.keptCount(); ++k) {
        const double code = s.value[k];
        const auto& dz = s.shapes.top_dz[k];
        if (code == 41.0) {
            // Level (a cell beside a ridge is drawn as a fan only for the crossings on its edges).
            EXPECT_EQ(s.shapes.top_centre_dz[k], 0);
            for (int e = 0; e < kHexCorners; ++e) EXPECT_EQ(dz[size_t(e)], 0);
        } else if (code == 90.0) {
            EXPECT_EQ(s.shapes.top_centre_dz[k], -1000);
            for (int e = 0; e < kHexCorners; ++e) EXPECT_EQ(dz[size_t(e)], 0);
        } else {
            // A ramp rising north: the top corner 2/3 of the relief up, the
            // bottom corner 2/3 down, the side corners a third.
            EXPECT_EQ(dz[2], 667);
            EXPECT_EQ(dz[5], -667);
            EXPECT_EQ(dz[1], 333);
            EXPECT_EQ(dz[4], -333);
            EXPECT_EQ(s.shapes.top_centre_dz[k], 0);
        }
    }
    // Where a ridged row meets the ridged row north of it, the step is the relief.
    const int32_t south = s.keptAt(7, 4), north = s.keptAt(7, 3);
    ASSERT_GE(south, 0);
    ASSERT_GE(north, 0);
    const int64_t shared = hexCornerId(s.grid, 7, 4, 2);  // the top corner of the southern cell
    EXPECT_NEAR(double(cornerTopAt(s, size_t(south), shared) - cornerTopAt(s, size_t(north), shared)), 1000.0, 1.0);
    expectVerified(s, "flat");
}

TEST(ClassTextures, EveryClassHasOneTopAndNoMoreTopsThanClasses) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        const Scene s = buildScene(threeClasses(), test::smallParams(bottom));
        std::map<double, std::set<std::tuple<int64_t, std::array<int32_t, 6>, int32_t>>> tops;
        for (size_t k = 0; k < s.keptCount(); ++k)
            tops[s.value[k]].insert({s.top[k], s.shapes.top_dz[k], s.shapes.top_centre_dz[k]});
        std::set<std::tuple<int64_t, std::array<int32_t, 6>, int32_t>> all;
        for (const auto& [code, shapes] : tops) {
            EXPECT_EQ(shapes.size(), 1u) << "class " << code;
            all.insert(shapes.begin(), shapes.end());
        }
        EXPECT_EQ(all.size(), 3u);
        if (bottom == Bottom::Mirrored) {
            // The slab keeps its thickness: the bottom moves as the top does.
            for (size_t k = 0; k < s.keptCount(); ++k) {
                EXPECT_EQ(s.shapes.bottom_centre_dz[k], s.shapes.top_centre_dz[k]);
                EXPECT_EQ(s.shapes.bottom_dz[k], s.shapes.top_dz[k]);
            }
        }
        expectVerified(s, bottom == Bottom::Flat ? "flat" : "mirrored");
    }
}

TEST(ClassTextures, RarerClassesShareTheLastTexture) {
    // Seven classes: 7 on 20 cells, 6 on 12, 1 on 8, and 2 to 5 on 4 each.
    HexField f = fieldFromFunction(14, 4, [](int c, int) { return c < 5 ? 7.0 : c < 8 ? 6.0 : std::max(1.0, 13.0 - c); });
    f.input.categorical = true;
    SceneParams p = test::smallParams();
    const Scene all = buildScene(f, p);
    ASSERT_TRUE(sceneTextures(all));
    EXPECT_EQ(sceneTextures(all)->textures_used, kTextureCount);
    size_t shared = 0;
    for (const ClassTexture& c : sceneTextures(all)->classes) {
        shared += c.shared;
        if (c.shared) EXPECT_EQ(c.texture, Texture::Bumps);
    }
    EXPECT_EQ(sceneTextures(all)->classes.size(), 7u);
    EXPECT_EQ(shared, 3u) << "seven classes, five textures: the three rarest share the fifth";

    p.requests.set(ClassTextureRequest{true, 2});
    const Scene two = buildScene(f, p);
    EXPECT_EQ(sceneTextures(two)->textures_used, 2);
    EXPECT_EQ(sceneTextures(two)->classes[0].texture, Texture::Level);
    EXPECT_FALSE(sceneTextures(two)->classes[0].shared);
    for (size_t i = 1; i < sceneTextures(two)->classes.size(); ++i) {
        EXPECT_EQ(sceneTextures(two)->classes[i].texture, Texture::RidgesEastWest);
        EXPECT_TRUE(sceneTextures(two)->classes[i].shared);
    }
    expectVerified(two, "two textures");

    for (const int bad : {0, 6}) {
        p.requests.set(ClassTextureRequest{true, bad});
        EXPECT_THROW(buildScene(f, p), InputError) << bad;
    }
}

TEST(ClassTextures, SmallCellsGetALowerReliefAndTheSummarySaysWhenItIsHardToFeel) {
    SceneParams p = test::smallParams();
    p.pitch_mm = 3.0;
    const Scene three = buildScene(threeClasses(), p);
    // tan(26.57 deg) x 1.5 mm, less a z step: 0.749 mm.
    EXPECT_EQ(sceneTextures(three)->relief_units, 749);
    p.pitch_mm = 1.5;
    const Scene small = buildScene(threeClasses(), p);
    EXPECT_EQ(sceneTextures(small)->relief_units, 374);
    bool said = false;
    for (const std::string& n : small.notes) said = said || n.find("class textures rise only") != std::string::npos;
    EXPECT_TRUE(said);
    expectVerified(small, "1.5 mm cells");
}

// With --layer 0.2 the relief is whole layers: three (0.6 mm, leaning
// 0.6 / 1.5 = 0.4 under tan(26.57 deg) = 0.5) on 3 mm cells, not two; on
// 2 mm cells only two fit the slope (0.4 mm), and the summary says why.
TEST(ClassTextures, AtLayersOfPointTwoTheReliefIsThreeWholeLayersWhereTheCellsAllowIt) {
    SceneParams p = test::smallParams();
    p.pitch_mm = 3.0;
    p.z_snap_mm = 0.2;
    const Scene three = buildScene(threeClasses(), p);
    EXPECT_EQ(sceneTextures(three)->relief_units, 3);
    expectVerified(three, "3 mm cells at 0.2 mm layers");
    p.pitch_mm = 2.0;
    const Scene two = buildScene(threeClasses(), p);
    EXPECT_EQ(sceneTextures(two)->relief_units, 2);
    bool said = false;
    for (const std::string& n : two.notes) said = said || n.find("class textures rise only 0.4 mm") != std::string::npos;
    EXPECT_TRUE(said);
}

TEST(ClassTextures, OrderedClassesAndMeasurementsStandAtHeights) {
    HexField ordered = threeClasses();
    ordered.input.class_order = {41, 11, 90};
    EXPECT_FALSE(sceneTextures(buildScene(ordered, test::smallParams())));
    HexField measured = threeClasses();
    measured.input.categorical = false;
    EXPECT_FALSE(sceneTextures(buildScene(measured, test::smallParams())));
    SceneParams off = test::smallParams();
    off.requests.set(ClassTextureRequest{false, kTextureCount});
    EXPECT_FALSE(sceneTextures(buildScene(threeClasses(), off)));
}

TEST(ClassTextures, WhatCannotBeCombinedWithTexturesIsRefused) {
    SceneParams tilt = test::smallParams();
    tilt.tilt = TiltSource::Gradient;
    SceneParams halves = test::smallParams(Bottom::Mirrored);
    halves.halves = true;
    SceneParams scale = test::smallParams();
    scale.requests.set(ScaleRequest{});
    for (const SceneParams& p : {tilt, halves, scale}) {
        try {
            buildScene(threeClasses(), p);
            ADD_FAILURE() << "accepted";
        } catch (const InputError& e) {
            EXPECT_NE(std::string(e.what()).find("--class-order"), std::string::npos) << e.what();
        }
    }
}

TEST(ClassTextures, TheSidecarHoldsTheTexturesAsDecided) {
    const Scene s = buildScene(threeClasses(), test::smallParams());
    const auto dir = test::scratchDir("class_textures_sidecar");
    writeSceneJson(s, (dir / "m.scene.json").string());
    const Scene back = readSceneJson((dir / "m.scene.json").string());
    ASSERT_TRUE(sceneTextures(back));
    EXPECT_EQ(sceneTextures(back)->relief_units, sceneTextures(s)->relief_units);
    EXPECT_EQ(sceneTextures(back)->height_units, sceneTextures(s)->height_units);
    ASSERT_EQ(sceneTextures(back)->classes.size(), sceneTextures(s)->classes.size());
    for (size_t i = 0; i < sceneTextures(s)->classes.size(); ++i) {
        EXPECT_EQ(sceneTextures(back)->classes[i].code, sceneTextures(s)->classes[i].code);
        EXPECT_EQ(sceneTextures(back)->classes[i].texture, sceneTextures(s)->classes[i].texture);
    }
    expectVerified(back, "read back");
    // A texture the sidecar does not know is an error naming where it is.
    std::string text = test::readText(dir / "m.scene.json");
    const size_t at = text.find("\"dimples\"");
    ASSERT_NE(at, std::string::npos);
    text.replace(at, 9, "\"stripes\"");
    test::writeText(dir / "bad.scene.json", text);
    try {
        readSceneJson((dir / "bad.scene.json").string());
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("class_textures.classes[2]"), std::string::npos) << e.what();
    }
}

// From the command line: an ESRI grid of codes read with --categorical.
TEST(ClassTextures, TheCommandLineSaysEachClassesTextureAndVerifiesItAsATactileGraphic) {
    const auto dir = test::scratchDir("class_textures_cli");
    std::string grid = "ncols 12\nnrows 8\nxllcorner 0\nyllcorner 0\ncellsize 30\nNODATA_value -9999\n";
    for (int r = 0; r < 8; ++r) {
        for (int c = 0; c < 12; ++c) grid += std::string(c ? " " : "") + (c < 6 ? "4" : r < 3 ? "8" : r < 6 ? "2" : "9");
        grid += "\n";
    }
    test::writeText(dir / "cover.asc", grid);
    const std::string in = (dir / "cover.asc").string(), model = (dir / "cover.stl").string();
    const auto run = test::runTsf("gen " + in + " --categorical --cell 5 --classes 3 -o " + model + " --json");
    ASSERT_EQ(run.exit_code, test::kExitOk) << run.output;
    const nlohmann::json j = nlohmann::json::parse(run.output.substr(run.output.find('{')));
    ASSERT_EQ(j["classes"].size(), 4u) << j["classes"].dump();
    // Commonest first: 4 (48 cells) level, 2 (18) ridges east-west, 8 (18)
    // and 9 (12) share dimples.
    EXPECT_EQ(j["classes"][0]["code"], 4.0);
    EXPECT_EQ(j["classes"][0]["texture"], "level");
    EXPECT_EQ(j["classes"][1]["code"], 2.0);
    EXPECT_EQ(j["classes"][1]["texture"], "ridges east-west");
    EXPECT_EQ(j["classes"][2]["texture"], "dimples");
    EXPECT_EQ(j["classes"][3]["texture"], "dimples");
    EXPECT_TRUE(j["classes"][3]["texture_shared"].get<bool>());
    EXPECT_EQ(j["scene"]["class_textures"]["shared"], nlohmann::json({8.0, 9.0}));
    EXPECT_DOUBLE_EQ(j["scene"]["class_textures"]["relief_mm"].get<double>(), 1.0);
    const std::string key = test::readText(dir / "cover.key.txt");
    EXPECT_NE(key.find("dimples (a dimple in the middle of each hexagon): class 8, class 9 (these classes share it)"),
              std::string::npos)
        << key;
    const auto tactile = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --layer 0.2");
    EXPECT_EQ(tactile.exit_code, test::kExitOk) << tactile.output;
    EXPECT_NE(tactile.output.find("told apart by 3 textures 1 mm deep"), std::string::npos) << tactile.output;

    // The braille plate names the classes by texture, each on a line of its own.
    const auto titled = test::runTsf("gen " + in + " --categorical --cell 14 --classes 3 --title Cover -o " +
                                     (dir / "titled.stl").string() + " --json");
    ASSERT_EQ(titled.exit_code, test::kExitOk) << titled.output;
    const nlohmann::json tj = nlohmann::json::parse(titled.output.substr(titled.output.find('{')));
    std::vector<std::string> lines;
    for (const auto& l : tj["scene"]["legend"]["lines"]) lines.push_back(l["text"].get<std::string>());
    EXPECT_EQ(lines, (std::vector<std::string>{"Cover", "4 classes", "level: 4", "ridges east-west: 2", "dimples: 8, 9"}));

    const auto bad = test::runTsf("gen " + in + " --categorical --classes 9 -o " + model);
    EXPECT_EQ(bad.exit_code, test::kExitBadInput) << bad.output;
    EXPECT_NE(bad.output.find("--classes must be 1 to 5"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace tsf
