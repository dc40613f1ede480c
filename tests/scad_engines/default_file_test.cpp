// The generated .scad as its users run it: the file `tsf gen --scad` writes
// by default (the orientation tab on, the polyhedron strategy), rendered by
// OpenSCAD 2021.01 and the 2025 WebAssembly engine, with the tab shown and
// hidden with its customizer switch. Every render must be clean (closed,
// manifold, one piece, no self-intersection, no zero-area triangle: a
// defect is a failure, never a tolerance) and the direct mesher's solid of
// the same Scene, plane by plane. Besides the list of models, a
// true-aspect grid of topography and bathymetry: its stretched hexagons are
// where OpenSCAD 2021's union once wrote intersecting and zero-area
// triangles. The tab, the legend's plate and the scale are joined into the
// terrain's one polyhedron (scad_lib/tsf_joined.scad): no boolean, so
// OpenSCAD 2021 never turns the model into Nef polyhedra.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <tuple>

#include "engine_fixtures.h"
#include "same_solid.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/scale.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/readers/load_field.h"
#include "gen/scad/scad_emitter.h"
#include "gen/model/features/legend/legend.h"
#include "tests/scad/scad_test_support.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

// A model of the list, as SceneParams and a field.
struct DefaultModel {
    std::string name;
    HexField field;
    SceneParams params;
};

// The defaults of `tsf gen` (the tab carries the marks), flat or mirrored.
SceneParams defaults(Bottom bottom = Bottom::Flat) {
    SceneParams p;
    p.bottom = bottom;
    return p;
}

DefaultModel modelNamed(const std::string& name) {
    if (name == "near_equal")  // 40 x 40, neighbours one snap step or less apart in places
        return {name, test::fieldFromFunction(40, 40, [](int c, int r) {
                    return 100.0 + 0.002 * ((c * 7 + r * 13) % 5) + 0.5 * std::sin(c * 0.2) * std::cos(r * 0.15);
                }),
                defaults()};
    if (name == "nodata")  // holes without data inside the hull
        return {name, test::fieldFromFunction(40, 40, [](int c, int r) {
                    return (c * 3 + r * 5) % 11 == 0 ? test::kNaN : 10.0 + std::hypot(c - 20.0, r - 20.0);
                }),
                defaults()};
    if (name == "checkerboard")
        return {name, test::fieldFromFunction(20, 20, [](int c, int r) { return (c + r) % 2 ? 10.0 : 0.0; }), defaults()};
    if (name == "islands")  // sparse points: a few islands of bins with points, empty bins between them
        return {name, test::asBinnedPoints(test::fieldFromFunction(30, 24, [](int c, int r) {
                    const bool island = (std::hypot(c - 5.0, r - 5.0) < 3) || (std::hypot(c - 20.0, r - 8.0) < 4) ||
                                        (std::hypot(c - 12.0, r - 18.0) < 3);
                    return island ? 5.0 + (c + r) % 4 : 0.0;
                })),
                defaults()};
    if (name == "mirrored_points")  // binned points, a mirrored bottom
        return {name, test::asBinnedPoints(test::fieldFromFunction(24, 20, [](int c, int r) {
                    return double((c * c + 3 * r) % 9);
                })),
                defaults(Bottom::Mirrored)};
    if (name == "true_aspect") {  // topography and bathymetry, one pillar per value (stretched hexagons)
        HexField f = test::fieldFromFunction(40, 40, [](int c, int r) {
            return 40.0 * std::sin(c * 0.17) * std::cos(r * 0.11) + 0.3 * ((c * 5 + r * 3) % 4) - 10.0;
        });
        f.rows_a_pitch_apart = true;
        SceneParams p = defaults();
        p.pitch_mm = 3.0;
        return {name, f, p};
    }
    // the volcano with --title --units --scale
    FieldLoadOptions in;
    in.input = test::sourcePath("examples/volcano.csv");
    SceneParams p = defaults();
    p.words.title = "Volcano";
    p.words.units = "m";
    p.requests.set(ScaleRequest{});
    return {name, loadField(in), p};
}

// The Scene without its tab: what the file draws with show_orientation_tab = false.
Scene withoutTab(Scene s) {
    s.features.reset<OrientationTab>();
    return s;
}

// model, engine, tab shown
using Case = std::tuple<std::string, std::string, bool>;

class DefaultScadFile : public ::testing::TestWithParam<Case> {};

TEST_P(DefaultScadFile, RendersCleanAndEqualToTheDirectMesh) {
    const auto& [model_name, engine_name, tab_shown] = GetParam();
    TSF_NEED_ENGINE(test::engineNamed(engine_name));
    const DefaultModel m = modelNamed(model_name);
    const Scene scene = buildScene(m.field, m.params);
    ASSERT_TRUE(sceneTab(scene) != nullptr) << "the default model carries the tab";
    if (model_name == "true_aspect") EXPECT_EQ(scene.y_scale, kRowsAPitchApart);
    if (model_name == "volcano") {
        ASSERT_TRUE(sceneLegend(scene) != nullptr);
        ASSERT_TRUE(sceneScale(scene));
    }
    const fs::path dir = test::scratchDir("default_" + model_name + "_" + engine_name + (tab_shown ? "_tab" : "_notab"));
    writeScad(scene, ScadOptions{}, (dir / "model.scad").string());
    // One polyhedron: no union of the tab, the plate or the scale with the pillars.
    const std::string text = test::readText(dir / "model.scad");
    EXPECT_EQ(text.find("tsf_with_tab("), std::string::npos);
    EXPECT_EQ(text.find("tsf_with_legend("), std::string::npos);
    EXPECT_EQ(text.find("tsf_with_scale("), std::string::npos);
    EXPECT_NE(text.find("tsf_terrain_polyhedron(model, joined = ["), std::string::npos);
    EXPECT_NE(text.find("show_orientation_tab ? orientation_tab : []"), std::string::npos);
    ScadRenderRequest rq;
    if (!tab_shown) rq.defines.push_back({"show_orientation_tab", "false"});
    test::expectSameSolid(*test::engineNamed(engine_name).engine, tab_shown ? scene : withoutTab(scene), dir / "model.scad",
                          dir / "model.stl", rq);
}

INSTANTIATE_TEST_SUITE_P(
    ModelsEnginesTab, DefaultScadFile,
    ::testing::Combine(::testing::Values("near_equal", "nodata", "checkerboard", "islands", "mirrored_points", "true_aspect",
                                         "volcano"),
                       ::testing::Values("openscad", "wasm"), ::testing::Bool()),
    [](const auto& info) {
        return std::get<0>(info.param) + "_" + std::get<1>(info.param) + (std::get<2>(info.param) ? "_tab" : "_no_tab");
    });

// Hand-editing the default file: a value of a pillar the tab stands against
// is changed; the render moves exactly that pillar (its wall above the tab
// follows it), is clean, and is the direct mesh of the edited field; the
// verifier names the cell against the Scene as generated.
class DefaultScadFileEdit : public ::testing::TestWithParam<std::string> {};

TEST_P(DefaultScadFileEdit, AValueBesideTheTabMovesOnlyItsPillar) {
    const std::string engine_name = GetParam();
    TSF_NEED_ENGINE(test::engineNamed(engine_name));
    HexField field = test::fieldFromFunction(10, 8, [](int c, int r) { return 2.0 + (c * 3 + r * 5) % 7; });
    const SceneParams params = defaults();
    const Scene scene = buildScene(field, params);
    ASSERT_TRUE(sceneTab(scene) != nullptr);
    ASSERT_FALSE(sceneTab(scene)->touched.empty());
    const size_t k = size_t(sceneTab(scene)->touched.front().first);
    const int32_t col = scene.col[k], row = scene.row[k];
    const fs::path dir = test::scratchDir("default_edit_" + engine_name);
    writeScad(scene, ScadOptions{}, (dir / "model.scad").string());
    const double new_value = field.at(col, row) > 5 ? 2.5 : 8.5;
    test::writeText(dir / "model.scad", test::withValue(test::readText(dir / "model.scad"), col, row,
                                                        new_value > 5 ? "8.5" : "2.5"));
    ScadRenderRequest rq;
    rq.scad_path = (dir / "model.scad").string();
    rq.output_path = (dir / "model.stl").string();
    rq.timeout_s = 300;
    field.at(col, row) = new_value;
    SceneParams edited = params;
    edited.baseline_mode = BaselineMode::Value;
    edited.baseline_value = scene.mapping.baseline;
    edited.value_max = scene.mapping.value_max;
    const Scene edited_scene = buildScene(field, edited);
    const Mesh direct = meshScene(edited_scene);
    EngineOutputCheck check;
    const ScadRenderResult r =
        renderScadChecked(*test::engineNamed(engine_name).engine, rq, {}, {signedVolume(direct)}, &check);
    ASSERT_TRUE(r.ok()) << r.summary << "\n" << r.output;
    EXPECT_TRUE(check.ok) << check.problem;
    const Mesh rendered = readStl(rq.output_path);
    test::expectSameMesh(engine_name, rendered, edited_scene, direct, dir / "model.stl");

    VerifyOptions vo;
    vo.printability = false;
    vo.max_offenders = 5;
    const VerifyReport against_old = verifyModel(rendered, &scene, vo);
    ASSERT_TRUE(against_old.readback.has_value());
    ASSERT_EQ(against_old.readback->over_tolerance, 1u);
    EXPECT_EQ(against_old.readback->worst.front().col, col);
    EXPECT_EQ(against_old.readback->worst.front().row, row);
}

INSTANTIATE_TEST_SUITE_P(Engines, DefaultScadFileEdit, ::testing::Values("openscad", "wasm"),
                         [](const auto& info) { return info.param; });

}  // namespace
}  // namespace tsf
