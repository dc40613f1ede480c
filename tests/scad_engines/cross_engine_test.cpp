// Generated OpenSCAD and scad_lib give the same solid on OpenSCAD 2021.01
// (desktop, CGAL) and OpenSCAD 2025.01 (WebAssembly, Manifold): every small
// model is rendered by each engine with each strategy and compared with the
// direct mesher's mesh of the same Scene - volume within 1e-6 relative, the
// same bounding box, every cell's heights read back by the verifier, and the
// verifier's solid checks (closed, manifold, no self-intersections).
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <tuple>

#include "engine_fixtures.h"
#include "same_solid.h"
#include "tests/support/fields.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/model/features/class_textures.h"
#include "gen/model/features/scale.h"
#include "gen/mesh/halves_mesh.h"
#include "gen/mesh_io/stl_reader.h"
#include "runners/openscad/engine_output_check.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/scad/scad_emitter.h"
#include "verify/verify_model.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/legend/legend.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;
using test::engineNamed;
using test::expectSameMesh;
using test::expectSameSolid;
using test::maxAbsCoordinate;

// engine, strategy, bottom
using Case = std::tuple<std::string, std::string, Bottom>;

class CrossEngine : public ::testing::TestWithParam<Case> {};

TEST_P(CrossEngine, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    const Scene scene = buildScene(test::smallTerrain(), test::terrainParams(bottom));
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    // Both ways of shipping the library: pasted into the file, and a copy use<>d beside it.
    opts.inline_library = bottom == Bottom::Mirrored;
    const fs::path dir = test::scratchDir("cross_" + engine_name + "_" + strategy_name + "_" + toString(bottom));
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(
    EnginesStrategiesBottoms, CrossEngine,
    ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg"),
                       ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
    [](const auto& info) {
        return std::get<0>(info.param) + "_" + std::get<1>(info.param) + "_" + toString(std::get<2>(info.param));
    });

// The orientation marks (notch and triangle) drawn by scad_lib from the faces
// tsf writes: the same solid as the direct mesher's on both engines, with
// both strategies, flat and mirrored.
class CrossEngineMarks : public ::testing::TestWithParam<Case> {};

TEST_P(CrossEngineMarks, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    // A flat floor in the west for the triangle, a small terrain in the east.
    const HexField terrain = test::smallTerrain();
    HexField field;
    field.grid = {7 + terrain.grid.cols, 2 * terrain.grid.rows};
    field.values.assign(size_t(field.grid.cellCount()), 0.0);
    for (int32_t r = 0; r < field.grid.rows; ++r)
        for (int32_t c = 7; c < field.grid.cols; ++c) field.at(c, r) = terrain.at(c - 7, r % terrain.grid.rows);
    field.source = "floor and terrain";
    field.one_to_one = true;
    SceneParams p = test::terrainParams(bottom);
    p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;  // the marks in the data (the tab: CrossEngineTab)
    p.pitch_mm = 6.0;
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(scene.marks.notch.has_value());
    ASSERT_TRUE(scene.marks.triangle.has_value());
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    opts.inline_library = bottom == Bottom::Flat;
    const fs::path dir = test::scratchDir("marks_" + engine_name + "_" + strategy_name + "_" + toString(bottom));
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(
    EnginesStrategiesBottoms, CrossEngineMarks,
    ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg"),
                       ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
    [](const auto& info) {
        return std::get<0>(info.param) + "_" + std::get<1>(info.param) + "_" + toString(std::get<2>(info.param));
    });

// Tilted tops (with crossings and clamps), dimpled structural cells, a pit
// without data and the orientation marks beside tilted cells, written as data
// by tsf and drawn by scad_lib/tsf_tilt.scad: the same solid as the direct
// mesher's on both engines, flat and mirrored, with either strategy asked
// for (a shaped model is always one polyhedron).
class CrossEngineTilt : public ::testing::TestWithParam<Case> {};

TEST_P(CrossEngineTilt, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    const HexField terrain = test::smallTerrain();
    HexField field;
    field.grid = {7 + terrain.grid.cols, 2 * terrain.grid.rows};
    field.values.assign(size_t(field.grid.cellCount()), 0.0);
    for (int32_t r = 0; r < field.grid.rows; ++r)
        for (int32_t c = 7; c < field.grid.cols; ++c) field.at(c, r) = terrain.at(c - 7, r % terrain.grid.rows);
    field.source = "floor and terrain";
    field = test::asBinnedPoints(field);  // cells at the floor are empty bins: structural
    SceneParams p = test::terrainParams(bottom);
    p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;  // the marks in the data (the tab: CrossEngineTab)
    p.pitch_mm = 6.0;
    p.tilt = TiltSource::Gradient;
    p.steepness = 3.0;
    p.structural_texture = true;
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(scene.marks.notch.has_value());
    EXPECT_GT(scene.shapes.cells_tilted, 10);
    EXPECT_GT(scene.shapes.cells_clamped, 0);
    EXPECT_GT(scene.shapes.cells_textured, 0);
    int64_t crossings = 0;
    for (int64_t id : scene.shapes.crossing_top) crossings += id >= 0;
    EXPECT_GT(crossings, 0);
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    opts.inline_library = bottom == Bottom::Flat;
    const fs::path dir = test::scratchDir("tilt_" + engine_name + "_" + strategy_name + "_" + toString(bottom));
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(
    EnginesStrategiesBottoms, CrossEngineTilt,
    ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg"),
                       ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
    [](const auto& info) {
        return std::get<0>(info.param) + "_" + std::get<1>(info.param) + "_" + toString(std::get<2>(info.param));
    });

// A class map's textures (ridges both ways, dimples, bumps, level) at one
// height, with a pit without data and the orientation tab beside textured
// cells: the .scad holds the class codes under the constant mapping and the
// textures as shaped tops, and both engines draw the direct mesher's solid,
// flat and mirrored.
class CrossEngineClassTextures : public ::testing::TestWithParam<std::tuple<std::string, Bottom>> {};

TEST_P(CrossEngineClassTextures, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    // Five classes in bands of different widths, so each gets its own texture.
    HexField field = test::fieldFromFunction(9, 6, [](int c, int r) {
        if (c == 0 && r == 0) return double(NAN);
        return c < 3 ? 11.0 : c < 5 ? 41.0 : c < 7 ? (r < 3 ? 90.0 : 95.0) : (r < 2 ? 21.0 : 95.0);
    });
    field.input.categorical = true;
    field.rows_a_pitch_apart = true;  // a raster, one pillar per value: true aspect ($tsf_y_scale)
    SceneParams p = test::terrainParams(bottom);
    p.marks = MarkParams{};  // the tab, against textured walls
    p.pitch_mm = 5.0;
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE((sceneTextures(scene) != nullptr));
    EXPECT_EQ(sceneTextures(scene)->textures_used, 5);
    EXPECT_EQ(scene.y_scale, kRowsAPitchApart);
    ASSERT_TRUE(sceneTab(scene) != nullptr);
    const fs::path dir = test::scratchDir("textures_" + engine_name + "_" + toString(bottom));
    ScadOptions opts;
    opts.inline_library = bottom == Bottom::Flat;
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(EnginesBottoms, CrossEngineClassTextures,
                         ::testing::Combine(::testing::Values("openscad", "wasm"),
                                            ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" + toString(std::get<1>(info.param));
                         });

// True aspect: a raster's rows a pitch apart, the lattice stretched
// north-south ($tsf_y_scale in the file): tilted tops with their crossings,
// the notch and the triangle in the data, flat and mirrored.
class CrossEngineTrueAspect : public ::testing::TestWithParam<std::tuple<std::string, Bottom>> {};

TEST_P(CrossEngineTrueAspect, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    HexField field = test::smallTerrain();
    field.rows_a_pitch_apart = true;
    SceneParams p = test::terrainParams(bottom);
    p.marks = MarkParams{};
    p.marks.place = MarkPlace::Data;
    p.pitch_mm = 6.0;
    p.tilt = TiltSource::Gradient;
    p.steepness = 3.0;
    const Scene scene = buildScene(field, p);
    EXPECT_EQ(scene.y_scale, kRowsAPitchApart);
    ASSERT_TRUE(scene.marks.notch.has_value());
    EXPECT_GT(scene.shapes.cells_tilted, 10);
    const fs::path dir = test::scratchDir("aspect_" + engine_name + "_" + toString(bottom));
    ScadOptions opts;
    opts.inline_library = bottom == Bottom::Mirrored;
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(EnginesBottoms, CrossEngineTrueAspect,
                         ::testing::Combine(::testing::Values("openscad", "wasm"),
                                            ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
                         [](const auto& info) {
                             return std::get<0>(info.param) + "_" + toString(std::get<1>(info.param));
                         });

// The braille legend: the plate and dots tsf meshes, written as data and
// joined to the pillars by each engine, the same solid as the direct mesher's
// union (checked plane by plane with the exact kernel).
class CrossEngineLegend : public ::testing::TestWithParam<std::string> {};

TEST_P(CrossEngineLegend, RendersTheSameSolidAsTheDirectMesher) {
    const std::string engine_name = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    // Floor rows in the north (culled), the small terrain south of them, repeated east.
    const HexField terrain = test::smallTerrain();
    HexField field;
    field.grid = {2 * terrain.grid.cols, 3 + terrain.grid.rows};
    field.values.assign(size_t(field.grid.cellCount()), 0.0);
    for (int32_t r = 3; r < field.grid.rows; ++r)
        for (int32_t c = 0; c < field.grid.cols; ++c) field.at(c, r) = terrain.at(c % terrain.grid.cols, r - 3);
    field.source = "floor and terrain";
    field.one_to_one = true;
    SceneParams p = test::terrainParams(Bottom::Flat);
    p.pitch_mm = 7.0;
    p.words.title = "Depth";
    p.words.units = "m";
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(sceneLegend(scene) != nullptr);
    ScadOptions opts;
    const fs::path dir = test::scratchDir("legend_" + engine_name);
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(Engines, CrossEngineLegend, ::testing::Values("openscad", "wasm"),
                         [](const auto& info) { return info.param; });

// The tactile scale: the staircase tsf places east of the pillars, written as
// data and joined to the pillars by each engine, the same solid as the direct
// mesher's exact join. With the polyhedron strategy the tops are tilted and
// the structural cells dimpled (the foot meets tilted walls); with the CSG
// strategy they are level prisms. Five steps on a field four rows deep: the
// scale's foot grows north beyond the pillars.
class CrossEngineScale : public ::testing::TestWithParam<std::tuple<std::string, std::string>> {};

TEST_P(CrossEngineScale, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    SceneParams p = test::terrainParams(Bottom::Flat);
    p.requests.set(ScaleRequest{1.0});
    HexField field = test::smallTerrain();
    if (strategy_name == "polyhedron") {
        field = test::asBinnedPoints(field);
        p.tilt = TiltSource::Gradient;
        p.steepness = 3.0;
        p.structural_texture = true;
    }
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(sceneScale(scene));
    ASSERT_EQ(sceneScale(scene)->steps.size(), 5u);
    EXPECT_GE(sceneScale(scene)->contacts.size(), 2u);  // and a filled notch between them
    if (strategy_name == "polyhedron") {
        bool tilted_contact = false;
        for (const int32_t k : sceneScale(scene)->contacts) tilted_contact = tilted_contact || isShaped(scene.shapes, size_t(k));
        EXPECT_TRUE(tilted_contact);
    }
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    opts.inline_library = strategy_name == "csg";
    const fs::path dir = test::scratchDir("scale_" + engine_name + "_" + strategy_name);
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(EnginesStrategies, CrossEngineScale,
                         ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg")),
                         [](const auto& info) { return std::get<0>(info.param) + "_" + std::get<1>(info.param); });

// The orientation tab west of the pillars (notch and triangle on it; on a
// mirrored model in the band its pillars share, the triangle on both faces),
// written as data and joined to the pillars by each engine: the same solid
// as the direct mesher's exact join. With the polyhedron strategy the tops
// are tilted (the tab meets tilted walls); with the CSG strategy they are level prisms.
class CrossEngineTab : public ::testing::TestWithParam<Case> {};

TEST_P(CrossEngineTab, RendersTheSameSolidAsTheDirectMesher) {
    const auto& [engine_name, strategy_name, bottom] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    SceneParams p = test::terrainParams(bottom);
    p.marks = MarkParams{};  // on the tab, the default
    p.cull = Cull::None;     // a full west column: the tab stands against a run of pillars
    const HexField terrain = test::smallTerrain();
    HexField field = terrain;
    field.grid.rows = 2 * terrain.grid.rows;
    field.values.assign(size_t(field.grid.cellCount()), 0.0);
    for (int32_t r = 0; r < field.grid.rows; ++r)
        for (int32_t c = 0; c < field.grid.cols; ++c) field.at(c, r) = terrain.at(c, r % terrain.grid.rows);
    if (strategy_name == "polyhedron") {
        field = test::asBinnedPoints(field);
        p.tilt = TiltSource::Gradient;
        p.steepness = 3.0;
    }
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(sceneTab(scene) != nullptr);
    EXPECT_FALSE(scene.marks.notch.has_value());
    // Flat: two contacts and the notch filled between them; mirrored: one contact.
    if (bottom == Bottom::Flat) EXPECT_GE(sceneTab(scene)->touched.size(), 4u);
    else EXPECT_EQ(sceneTab(scene)->touched.size(), 1u);
    ScadOptions opts;
    ASSERT_TRUE(parseScadStrategy(strategy_name, opts.strategy));
    opts.inline_library = strategy_name == "polyhedron";
    EXPECT_EQ(sceneTab(scene)->under_triangle, bottom == Bottom::Mirrored);
    const fs::path dir = test::scratchDir("tab_" + engine_name + "_" + strategy_name + "_" + toString(bottom));
    writeScad(scene, opts, (dir / "model.scad").string());
    expectSameSolid(*engineNamed(engine_name).engine, scene, dir / "model.scad", dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(
    EnginesStrategiesBottoms, CrossEngineTab,
    ::testing::Combine(::testing::Values("openscad", "wasm"), ::testing::Values("polyhedron", "csg"),
                       ::testing::Values(Bottom::Flat, Bottom::Mirrored)),
    [](const auto& info) {
        return std::get<0>(info.param) + "_" + std::get<1>(info.param) + "_" + toString(std::get<2>(info.param));
    });

// The customizer's parameter sets and -D overrides recompute the model in
// OpenSCAD; on both versions the result equals the Scene built with the same
// parameters by tsf.
class CrossEngineParameters : public ::testing::TestWithParam<std::string> {};

TEST_P(CrossEngineParameters, MirroredSetEqualsTheMirroredScene) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const Scene flat = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Flat));
    const Scene mirrored = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Mirrored));
    const fs::path dir = test::scratchDir("cross_set_" + GetParam());
    writeScad(flat, ScadOptions{}, (dir / "model.scad").string());
    ScadRenderRequest rq;
    rq.parameter_file = (dir / "model.json").string();
    rq.parameter_set = "mirrored bottom";
    expectSameSolid(*engineNamed(GetParam()).engine, mirrored, dir / "model.scad", dir / "model.stl", rq);
}

TEST_P(CrossEngineParameters, HeightOverrideEqualsTheTallerScene) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const Scene scene = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Flat));
    SceneParams taller_params = test::terrainParams(Bottom::Flat);
    taller_params.max_height_mm = 18.5;
    const Scene taller = buildScene(test::smallTerrain(), taller_params);
    const fs::path dir = test::scratchDir("cross_define_" + GetParam());
    ScadOptions opts;
    opts.strategy = ScadOptions::Strategy::Csg;
    writeScad(scene, opts, (dir / "model.scad").string());
    ScadRenderRequest rq;
    rq.defines = {parseScadDefine("height=18.5")};
    expectSameSolid(*engineNamed(GetParam()).engine, taller, dir / "model.scad", dir / "model.stl", rq);
}

// A parameter the library refuses stops the render with the library's
// message on both versions (2025 would otherwise export what is left).
TEST_P(CrossEngineParameters, RefusedParameterStopsWithTheLibraryMessage) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const Scene scene = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Flat));
    const fs::path dir = test::scratchDir("cross_refused_" + GetParam());
    writeScad(scene, ScadOptions{}, (dir / "model.scad").string());
    ScadRenderRequest rq;
    rq.scad_path = (dir / "model.scad").string();
    rq.output_path = (dir / "model.stl").string();
    rq.defines = {parseScadDefine("cell=0")};
    const ScadRenderResult r = renderScad(*engineNamed(GetParam()).engine, rq);
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed) << r.summary;
    const auto errors = r.errors();
    ASSERT_FALSE(errors.empty()) << r.output;
    EXPECT_EQ(errors[0].assert_message.rfind("tsf_model: cell_mm must be", 0), 0u) << r.output;
    EXPECT_FALSE(fs::exists(dir / "model.stl"));
}

INSTANTIATE_TEST_SUITE_P(Engines, CrossEngineParameters, ::testing::Values("openscad", "wasm"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tsf

namespace tsf {
namespace {

// The support-free halves of a mirrored model (gen/model/features/halves.h): each engine
// cuts the model at the Scene's plane and the Scene's pin holes out of it
// (scad_lib/tsf_halves.scad, piece = "upper" / "lower") and draws the same
// solid as the direct mesher's half, the lower half turned over as it prints.
using HalfCase = std::tuple<std::string, HalfKind>;
class CrossEngineHalves : public ::testing::TestWithParam<HalfCase> {};

TEST_P(CrossEngineHalves, RendersTheSameHalfAsTheDirectMesher) {
    const auto& [engine_name, kind] = GetParam();
    TSF_NEED_ENGINE(engineNamed(engine_name));
    // The small terrain (with its no-data pit) three times east and twice north: room for three pin holes.
    const HexField terrain = test::smallTerrain();
    HexField field;
    field.grid = {3 * terrain.grid.cols, 2 * terrain.grid.rows};
    field.values.assign(size_t(field.grid.cellCount()), 0.0);
    for (int32_t r = 0; r < field.grid.rows; ++r)
        for (int32_t c = 0; c < field.grid.cols; ++c) field.at(c, r) = terrain.at(c % terrain.grid.cols, r % terrain.grid.rows);
    field.source = "terrain x 6";
    field.one_to_one = true;
    SceneParams p = test::terrainParams(Bottom::Mirrored);
    p.marks = MarkParams{};  // on the tab, which each half carries its side of
    p.pitch_mm = 6.0;
    p.halves = true;
    const Scene scene = buildScene(field, p);
    ASSERT_TRUE(scene.halves.has_value());
    ASSERT_TRUE(sceneTab(scene) != nullptr);
    const bool upper = kind == HalfKind::Upper;
    const std::string piece = upper ? "upper" : "lower";
    const fs::path dir = test::scratchDir("halves_" + engine_name + "_" + piece);
    writeScad(scene, ScadOptions{}, (dir / "model.scad").string());
    ScadRenderRequest rq;
    rq.scad_path = (dir / "model.scad").string();
    rq.output_path = (dir / "model.stl").string();
    rq.timeout_s = 300;
    rq.defines.push_back({"piece", "\"" + piece + "\""});
    const Mesh printed = meshHalf(scene, kind);
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(*engineNamed(engine_name).engine, rq, {}, {signedVolume(printed)}, &check);
    ASSERT_TRUE(r.ok()) << engine_name << ": " << r.summary << "\n" << r.output;
    EXPECT_TRUE(check.ok) << check.problem;
    const Mesh rendered = readStl(rq.output_path);
    // As it prints: the same bounds and volume as the direct mesher's piece.
    const Bounds a = meshBounds(rendered), b = meshBounds(printed);
    const double rounding_mm = maxAbsCoordinate(printed) * kStlCoordinateRoundoff + 1e-6;
    EXPECT_NEAR(a.min.y, b.min.y, rounding_mm);
    EXPECT_NEAR(a.max.z, b.max.z, rounding_mm);
    // In the half's Scene frame (the lower half turned back): the same solid, every cell read back.
    const Scene half = halfScene(scene, kind);
    expectSameMesh(engine_name, upper ? rendered : turnLowerHalf(rendered, scene), half, meshScene(half),
                   dir / "model.stl");
}

INSTANTIATE_TEST_SUITE_P(EnginesPieces, CrossEngineHalves,
                         ::testing::Combine(::testing::Values("openscad", "wasm"),
                                            ::testing::Values(HalfKind::Upper, HalfKind::Lower)),
                         [](const auto& info) {
                             return std::get<0>(info.param) + (std::get<1>(info.param) == HalfKind::Upper ? "_upper" : "_lower");
                         });

}  // namespace
}  // namespace tsf
