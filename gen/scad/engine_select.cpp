#include "gen/scad/engine_select.h"

#include <algorithm>
#include <cctype>

#include "gen/scad/process_runner.h"
#include "gen/scad/wasm_engine.h"

namespace tsf {
namespace {

// `openscad --help` prints its options and exits at once.
constexpr double kHelpTimeoutS = 30.0;

std::string lower(std::string s) {
    for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}

std::string describe(const ScadEngine& engine) {
    return engine.name() + " (" + engine.version() + ", " + engine.executable() + ")";
}

// The desktop engine, and whether it has the Manifold backend.
struct Native {
    std::unique_ptr<ScadEngine> engine;
    bool manifold = false;
    std::string missing;  ///< why there is none
};

Native tryNative(const std::string& openscad_path) {
    Native n;
    try {
        n.engine = makeOpenScadEngine(openscad_path);
        n.manifold = openScadHasManifoldBackend(n.engine->executable());
    } catch (const ScadEngineMissing& e) {
        n.missing = e.what();
    }
    return n;
}

std::unique_ptr<ScadEngine> tryWasm(std::string& missing) {
    try {
        return makeWasmOpenScadEngine();
    } catch (const ScadEngineMissing& e) {
        missing = e.what();
        return nullptr;
    }
}

std::string backendNote(bool manifold) {
    return manifold ? "with the Manifold backend" : "CGAL backend only (no --backend=manifold)";
}

}  // namespace

const char* toString(EngineChoice choice) {
    switch (choice) {
        case EngineChoice::OpenScad: return "openscad";
        case EngineChoice::Wasm: return "wasm";
        default: return "auto";
    }
}

bool parseEngineChoice(const std::string& text, EngineChoice& choice) {
    if (text == "auto") choice = EngineChoice::Auto;
    else if (text == "openscad") choice = EngineChoice::OpenScad;
    else if (text == "wasm") choice = EngineChoice::Wasm;
    else return false;
    return true;
}

bool openScadHasManifoldBackend(const std::string& executable) {
    ProcessOptions po;
    po.timeout_s = kHelpTimeoutS;
    const ProcessResult pr = runProcess({executable, "--help"}, po);
    if (pr.end != ProcessResult::End::Exited) return false;
    const std::string help = lower(pr.output);
    const size_t at = help.find("--backend");
    return at != std::string::npos && help.find("manifold", at) != std::string::npos;
}

std::unique_ptr<ScadEngine> selectEngine(EngineChoice choice, const std::string& strategy,
                                         const std::string& openscad_path, std::string* why) {
    auto say = [&](const std::string& text) {
        if (why) *why = text;
    };
    if (choice == EngineChoice::OpenScad) {
        Native n = tryNative(openscad_path);
        if (!n.engine) throw ScadEngineMissing(n.missing);
        say("openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold) + " (asked for with --engine openscad)");
        return std::move(n.engine);
    }
    if (choice == EngineChoice::Wasm) {
        std::unique_ptr<ScadEngine> wasm = makeWasmOpenScadEngine();
        say("wasm: " + describe(*wasm) + " (asked for with --engine wasm)");
        return wasm;
    }

    // Auto.
    const bool polyhedron = strategy == "polyhedron";
    Native n = tryNative(openscad_path);
    if (n.engine && (polyhedron || n.manifold)) {
        say("openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold) + "; " +
            (polyhedron ? "a single polyhedron needs no boolean work, and the desktop binary renders it fastest"
                        : "it has the Manifold backend, which does the unions of the " +
                              (strategy.empty() ? std::string("model") : strategy + " strategy") + " fastest"));
        return std::move(n.engine);
    }
    std::string wasm_missing;
    if (std::unique_ptr<ScadEngine> wasm = tryWasm(wasm_missing)) {
        std::string reason;
        if (polyhedron)
            reason = "the desktop openscad is not available (" + n.missing + ")";
        else
            reason = std::string(strategy.empty() ? "the model" : "the " + strategy + " strategy") +
                     " needs boolean unions, which Manifold does about 40x faster than the CGAL backend of " +
                     (n.engine ? n.engine->version() : std::string("the desktop openscad"));
        say("wasm: " + describe(*wasm) + "; " + reason);
        return wasm;
    }
    if (n.engine) {
        say("openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold) +
            "; the faster WebAssembly engine is not installed (" + wasm_missing +
            "); unions of many cells will take minutes");
        return std::move(n.engine);
    }
    throw ScadEngineMissing("no OpenSCAD engine is available.\n  openscad: " + n.missing + "\n  wasm: " + wasm_missing);
}

}  // namespace tsf
