// The generated .scad text and the files beside it, read as a person or a
// script would read them (no OpenSCAD run here; see scad_render_test.cpp).
#include <gtest/gtest.h>

#include <charconv>
#include <filesystem>
#include <map>
#include <regex>

#include <nlohmann/json.hpp>

#include "gen/model/features/tab/tab_state.h"
#include "gen/util/error.h"
#include "gen/scad/scad_emitter.h"
#include "gen/scad/scad_library.h"
#include "scad_test_support.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/legend/legend.h"

namespace tsf {
namespace {
namespace fs = std::filesystem;
using namespace test;

Scene bumpyScene(Bottom bottom = Bottom::Flat) { return buildScene(bumpyField(9, 8), smallParams(bottom)); }

ScadOptions options(ScadOptions::Strategy strategy = ScadOptions::Strategy::Polyhedron) {
    ScadOptions o;
    o.strategy = strategy;
    o.source = "field.csv";
    o.command = "tsf gen field.csv --scad model.scad";
    return o;
}

bool contains(const std::string& text, const std::string& what) { return text.find(what) != std::string::npos; }

TEST(ScadEmitter, HeaderSaysWhereItCameFromAndHowToRenderIt) {
    const std::string text = emitScad(bumpyScene(), options(), "model.scad");
    EXPECT_TRUE(contains(text, "// Source:    field.csv"));
    EXPECT_TRUE(contains(text, "// Command:   tsf gen field.csv --scad model.scad"));
    EXPECT_TRUE(contains(text, "tsf " TSF_VERSION));
    EXPECT_TRUE(contains(text, "openscad -o model.stl --export-format binstl model.scad"));
    EXPECT_TRUE(contains(text, "tsf render model.scad -o model.stl"));
    EXPECT_TRUE(contains(text, "-p model.json -P \"mirrored bottom\""));
}

// Customizer: sections in order, each parameter with a description line above
// it and, for sliders, a range that contains the value.
TEST(ScadEmitter, ParametersAreInCustomizerSectionsWithRangesHoldingTheirValues) {
    const Scene scene = bumpyScene();
    const std::vector<std::string> lines = splitLines(emitScad(scene, options(), "model.scad"));
    std::vector<std::string> sections;
    std::map<std::string, std::string> value_of;
    const std::regex section(R"(^/\* \[(.+)\] \*/$)");
    const std::regex param(R"(^([a-z_]+) = ([^;]+);(\s*// \[(.*)\])?$)");
    for (size_t i = 0; i < lines.size(); ++i) {
        std::smatch m;
        if (std::regex_match(lines[i], m, section)) {
            sections.push_back(m[1]);
            if (m[1] == "Hidden") break;
            continue;
        }
        if (!std::regex_match(lines[i], m, param)) continue;
        value_of[m[1]] = m[2];
        ASSERT_GT(i, 0u);
        EXPECT_EQ(lines[i - 1].rfind("// ", 0), 0u) << "no description above " << m[1];
        if (m[4].matched && m[2].str().front() != '"') {
            double lo, step, hi;
            ASSERT_EQ(std::sscanf(m[4].str().c_str(), "%lf:%lf:%lf", &lo, &step, &hi), 3) << lines[i];
            const double v = std::stod(m[2]);
            EXPECT_LE(lo, v) << lines[i];
            EXPECT_LE(v, hi) << lines[i];
            EXPECT_GT(step, 0) << lines[i];
        }
    }
    EXPECT_EQ(sections, (std::vector<std::string>{"Model size", "Heights", "Base", "Mirror", "Hidden"}));
    std::vector<std::string> names;
    for (const std::string& n : scadParameterNames()) {
        ASSERT_TRUE(value_of.count(n)) << n << " is not a customizer parameter";
        names.push_back(n);
    }
    EXPECT_EQ(value_of.size(), names.size());
    EXPECT_EQ(std::stod(value_of["cell"]), scene.pitch_mm);
    EXPECT_EQ(std::stod(value_of["height"]), scene.mapping.max_height_mm);
    EXPECT_EQ(std::stod(value_of["value_max"]), scene.mapping.value_max);
    EXPECT_EQ(std::stod(value_of["baseline"]), scene.mapping.baseline);
    EXPECT_EQ(std::stod(value_of["snap"]), scene.z_snap_mm);
    EXPECT_EQ(std::stod(value_of["base"]), scene.params.base_mm);
    EXPECT_EQ(value_of["transfer"], "\"linear\"");
    EXPECT_EQ(value_of["mirror"], "false");
}

// One grid row per line; culled cells undef, kept cells without data nodata,
// numbers that read back to exactly the Scene's values.
TEST(ScadEmitter, ValuesAreOneRowPerLineWithUndefAndNodata) {
    const Scene scene = bumpyScene();
    ASSERT_GT(scene.cells_nodata_kept, 0);
    ASSERT_LT(int64_t(scene.keptCount()), scene.grid.cellCount());
    const std::vector<std::string> lines = splitLines(emitScad(scene, options(), "model.scad"));
    const ValuesBlock block = readValuesBlock(lines);
    ASSERT_EQ(block.cells.size(), size_t(scene.grid.rows));
    EXPECT_TRUE(contains(lines[block.line_index.front()], "// row 0 (north)"));
    EXPECT_TRUE(contains(lines[block.line_index.back()], "(south)"));
    int64_t undefs = 0, nodatas = 0;
    for (int32_t r = 0; r < scene.grid.rows; ++r) {
        ASSERT_EQ(block.cells[size_t(r)].size(), size_t(scene.grid.cols)) << "row " << r;
        for (int32_t c = 0; c < scene.grid.cols; ++c) {
            const std::string& text = block.cells[size_t(r)][size_t(c)];
            const int32_t k = scene.keptAt(c, r);
            if (k < 0) {
                EXPECT_EQ(text, "undef");
                ++undefs;
            } else if (std::isnan(scene.value[size_t(k)])) {
                EXPECT_EQ(text, "nodata");
                ++nodatas;
            } else {
                double v = 0;
                const auto res = std::from_chars(text.data(), text.data() + text.size(), v);
                ASSERT_EQ(res.ptr, text.data() + text.size()) << text;
                EXPECT_EQ(v, scene.value[size_t(k)]) << "cell " << c << "," << r;
            }
        }
    }
    EXPECT_EQ(undefs, scene.grid.cellCount() - int64_t(scene.keptCount()));
    EXPECT_EQ(nodatas, scene.cells_nodata_kept);
}

// Only what the chosen strategy needs is pasted and called; never the marks.
TEST(ScadEmitter, InlinesAndCallsOnlyTheModulesTheStrategyNeeds) {
    const Scene scene = bumpyScene();
    const std::string poly = emitScad(scene, options(ScadOptions::Strategy::Polyhedron), "m.scad");
    EXPECT_TRUE(contains(poly, "\ntsf_terrain_polyhedron(model);\n"));
    EXPECT_TRUE(contains(poly, "module tsf_terrain_polyhedron("));
    EXPECT_TRUE(contains(poly, "function tsf_model("));
    EXPECT_FALSE(contains(poly, "module tsf_terrain_csg("));
    EXPECT_FALSE(contains(poly, "tsf_terrain_csg(model)"));
    EXPECT_FALSE(contains(poly, "module tsf_hex_pillar("));
    EXPECT_FALSE(contains(poly, "module tsf_orientation_notch("));
    EXPECT_FALSE(contains(poly, "\nuse <"));
    EXPECT_FALSE(contains(poly, "\ninclude <"));

    const std::string csg = emitScad(scene, options(ScadOptions::Strategy::Csg), "m.scad");
    EXPECT_TRUE(contains(csg, "\ntsf_terrain_csg(model);\n"));
    EXPECT_TRUE(contains(csg, "module tsf_terrain_csg("));
    EXPECT_TRUE(contains(csg, "module tsf_hex_pillar("));
    EXPECT_TRUE(contains(csg, "module tsf_hull_base("));
    EXPECT_FALSE(contains(csg, "tsf_terrain_polyhedron(model)"));
    EXPECT_FALSE(contains(csg, "tsf_orientation"));
}

TEST(ScadEmitter, LibraryBesideIsACopyUsedByTheFile) {
    const std::string dir = scratchDir("emitter_beside");
    ScadOptions o = options();
    o.inline_library = false;
    const std::string path = dir + "/model.scad";
    writeScad(bumpyScene(), o, path);
    const std::string text = readText(path);
    EXPECT_TRUE(contains(text, "use <tsf_lib/tsf.scad>"));
    EXPECT_FALSE(contains(text, "module "));
    EXPECT_FALSE(contains(text, "function "));
    const std::string lib = scadLibraryDir();
    const std::vector<std::string> files = scadLibraryFiles(lib);
    ASSERT_FALSE(files.empty());
    for (const std::string& name : files)
        EXPECT_EQ(readText(dir + "/tsf_lib/" + name), readText(lib + "/" + name)) << name;
    const std::vector<std::string> outputs = scadOutputPaths(o, path);
    EXPECT_EQ(outputs.size(), 2 + files.size());
    for (const std::string& p : outputs) EXPECT_TRUE(fs::is_regular_file(p)) << p;
}

TEST(ScadEmitter, ParameterSetsAreOpenScadJsonWithStringValues) {
    const Scene scene = bumpyScene();
    const nlohmann::json doc = nlohmann::json::parse(emitScadParameterSets(scene));
    EXPECT_EQ(doc.at("fileFormatVersion"), "1");
    const nlohmann::json& sets = doc.at("parameterSets");
    for (const char* name : {"as generated", "layer steps 0.2 mm", "mirrored bottom", "half size"})
        EXPECT_TRUE(sets.contains(name)) << name;
    for (const auto& [name, set] : sets.items())
        for (const auto& [param, value] : set.items()) EXPECT_TRUE(value.is_string()) << name << " " << param;
    for (const std::string& n : scadParameterNames()) EXPECT_TRUE(sets["as generated"].contains(n)) << n;
    EXPECT_EQ(std::stod(sets["half size"]["cell"].get<std::string>()), scene.pitch_mm / 2);
    // A mirrored model offers the way back instead.
    const nlohmann::json mirrored = nlohmann::json::parse(emitScadParameterSets(bumpyScene(Bottom::Mirrored)));
    EXPECT_TRUE(mirrored["parameterSets"].contains("flat bottom"));
    EXPECT_EQ(mirrored["parameterSets"]["flat bottom"]["mirror"], "false");
}

// The orientation tab stands where tsf placed it for the parameters as
// generated, and the file asserts them: every other set leaves the tab out,
// so each set renders; the generated file names the tab's body and the check.
TEST(ScadEmitter, ParameterSetsLeaveTheOrientationTabOutWhereItWouldNotStand) {
    SceneParams p = smallParams(Bottom::Flat);
    p.marks = MarkParams{};
    const Scene scene = buildScene(bumpyField(9, 8), p);
    ASSERT_TRUE(sceneTab(scene) != nullptr);
    const nlohmann::json sets = nlohmann::json::parse(emitScadParameterSets(scene))["parameterSets"];
    EXPECT_EQ(sets["as generated"]["show_orientation_tab"], "true");
    for (const char* name : {"layer steps 0.2 mm", "mirrored bottom", "half size"})
        EXPECT_EQ(sets[name]["show_orientation_tab"], "false") << name;
    // The polyhedron strategy joins the tab into the terrain's one polyhedron
    // (its walls and open body, tsf_joined.scad); the CSG strategy unions the closed body.
    ScadOptions poly = options();
    poly.strategy = ScadOptions::Strategy::Polyhedron;
    const std::string scad = emitScad(scene, poly, "model.scad");
    EXPECT_TRUE(contains(scad, "orientation_tab = [\n  // walls [col, row, edge, bottom, top] (z steps)")) << scad;
    EXPECT_TRUE(contains(scad, "assert(!show_orientation_tab || [cell, base, snap, mirror] == ["));
    EXPECT_TRUE(contains(scad, "tsf_terrain_polyhedron(model, joined = [show_orientation_tab ? orientation_tab : []]);"));
    EXPECT_FALSE(contains(scad, "tsf_with_tab("));
    ScadOptions csg = options();
    csg.strategy = ScadOptions::Strategy::Csg;
    const std::string unioned = emitScad(scene, csg, "model.scad");
    EXPECT_TRUE(contains(unioned, "orientation_tab = [[")) << unioned;
    EXPECT_TRUE(contains(unioned, "assert(!show_orientation_tab || [cell, base, snap, mirror] == ["));
    EXPECT_TRUE(contains(unioned, "tsf_with_tab(orientation_tab, show_orientation_tab) "));
}

// The legend's plate too: drawn for the parameters as generated (a mirrored
// model's lies in its pillars' band), left out of every other set.
TEST(ScadEmitter, ParameterSetsLeaveTheLegendOutWhereItWouldNotStand) {
    for (const Bottom bottom : {Bottom::Flat, Bottom::Mirrored}) {
        SceneParams p = smallParams(bottom);
        p.base_mm = 3;  // a mirrored plate needs a band of 1.6 mm its pillars share
        p.words.title = "Depth";
        const Scene scene = buildScene(bumpyField(12, 10), p);
        ASSERT_TRUE(sceneLegend(scene) != nullptr);
        const nlohmann::json sets = nlohmann::json::parse(emitScadParameterSets(scene))["parameterSets"];
        EXPECT_EQ(sets["as generated"]["braille_legend"], "true");
        for (const auto& [name, set] : sets.items())
            if (name != "as generated") EXPECT_EQ(set["braille_legend"], "false") << name;
    }
}

TEST(ScadEmitter, WritesTheFileAndItsParameterSetsAtomically) {
    const std::string dir = scratchDir("emitter_write");
    const Scene scene = bumpyScene();
    writeScad(scene, options(), dir + "/model.scad");
    EXPECT_EQ(readText(dir + "/model.scad"), emitScad(scene, options(), dir + "/model.scad"));
    EXPECT_EQ(readText(dir + "/model.json"), emitScadParameterSets(scene));
    // Nothing but the two files: no temporary left behind.
    size_t n = 0;
    for (const auto& e : fs::directory_iterator(dir)) n += e.is_regular_file();
    EXPECT_EQ(n, 2u);
}

TEST(ScadEmitter, RefusesAWrongExtensionAndAnEmptySceneWithoutWritingAnything) {
    const std::string dir = scratchDir("emitter_refuse");
    EXPECT_THROW(writeScad(bumpyScene(), options(), dir + "/model.stl"), InputError);
    EXPECT_THROW(writeScad(bumpyScene(), options(), dir + "/no/such/folder/model.scad"), InputError);
    Scene empty = bumpyScene();
    empty.col.clear();
    empty.row.clear();
    empty.value.clear();
    empty.top.clear();
    empty.bottom.clear();
    std::fill(empty.kept_index.begin(), empty.kept_index.end(), -1);
    EXPECT_THROW(writeScad(empty, options(), dir + "/model.scad"), InputError);
    EXPECT_TRUE(fs::is_empty(dir));
}

TEST(ScadEmitter, StrategyNamesRoundTrip) {
    ScadOptions::Strategy s{};
    for (auto want : {ScadOptions::Strategy::Polyhedron, ScadOptions::Strategy::Csg}) {
        ASSERT_TRUE(parseScadStrategy(toString(want), s));
        EXPECT_EQ(s, want);
    }
    EXPECT_FALSE(parseScadStrategy("union", s));
}

TEST(ScadLibrary, IsFoundAndAnExplicitWrongFolderIsAnError) {
    const std::string dir = scadLibraryDir();
    EXPECT_TRUE(fs::is_regular_file(fs::path(dir) / kScadLibraryEntry));
    setenv("TSF_SCAD_LIB", "/nonexistent/scad_lib", 1);
    EXPECT_THROW(scadLibraryDir(), std::runtime_error);
    setenv("TSF_SCAD_LIB", dir.c_str(), 1);
    EXPECT_EQ(scadLibraryDir(), fs::path(dir).lexically_normal().string());
    unsetenv("TSF_SCAD_LIB");
}

}  // namespace
}  // namespace tsf
