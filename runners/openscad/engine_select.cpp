#include "runners/openscad/engine_select.h"

#include <algorithm>
#include <cctype>
#include <sstream>

#include "runners/process_runner.h"
#include "runners/openscad/wasm_engine.h"

namespace tsf {
namespace {

// Unions of more cells than this take minutes on every engine (docs/engines.md:
// 1 600 cells took 7 s with Manifold and 100 s with CGAL; 10 000 cells 104 s
// with Manifold, more than 15 minutes with CGAL).
constexpr size_t kCsgMinutesCells = 1600;

// A cell count in a header longer than this is not one tsf wrote.
constexpr size_t kMaxCellDigits = 12;

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

// A warning for csg models big enough to take minutes on every engine.
std::string slowCsgNote(const std::string& strategy, size_t cells) {
    if (strategy == "polyhedron" || cells <= kCsgMinutesCells) return "";
    return ". Note: the csg strategy with " + std::to_string(cells) +
           " cells takes minutes (10 000 cells: 2 minutes with Manifold, more than 15 with CGAL); the polyhedron "
           "strategy renders the same solid in seconds";
}

std::string backendNote(bool manifold) {
    return manifold ? "with the Manifold backend" : "CGAL backend only (no --backend=manifold)";
}

std::string trimLeft(const std::string& s) {
    size_t i = 0;
    while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
    return s.substr(i);
}

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

}  // namespace

ScadFileFacts scadFileFacts(const std::string& scad_text) {
    ScadFileFacts facts;
    bool calls_csg = false, calls_polyhedron = false;
    std::string header_strategy;
    std::istringstream lines(scad_text);
    for (std::string raw; std::getline(lines, raw);) {
        const std::string line = trimLeft(raw);
        if (startsWith(line, "tsf_terrain_csg(")) calls_csg = true;
        else if (startsWith(line, "tsf_terrain_polyhedron(")) calls_polyhedron = true;
        else if (startsWith(line, "// Strategy:")) {
            const std::string rest = trimLeft(line.substr(12));
            if (startsWith(rest, "csg")) header_strategy = "csg";
            else if (startsWith(rest, "polyhedron")) header_strategy = "polyhedron";
        } else if (startsWith(line, "// Grid:") && facts.cells == 0) {
            const size_t at = line.find(" cells with a pillar");
            size_t begin = at;
            while (begin != std::string::npos && begin > 0 && std::isdigit(static_cast<unsigned char>(line[begin - 1])))
                --begin;
            if (at != std::string::npos && begin < at && at - begin <= kMaxCellDigits)
                facts.cells = std::stoull(line.substr(begin, at - begin));
        }
    }
    if (calls_csg != calls_polyhedron) facts.strategy = calls_csg ? "csg" : "polyhedron";
    else if (!calls_csg) facts.strategy = header_strategy;
    return facts;
}

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

std::unique_ptr<ScadEngine> selectEngine(EngineChoice choice, const std::string& strategy,
                                         const std::string& openscad_path, std::string* why, size_t cells) {
    auto say = [&](const std::string& text) {
        if (why) *why = text + slowCsgNote(strategy, cells);
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
    const std::string what = strategy.empty() ? std::string("this model") : "the " + strategy + " strategy";
    Native n = tryNative(openscad_path);
    if (n.engine && (polyhedron || n.manifold)) {
        say("openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold) + "; " +
            (polyhedron ? "a single polyhedron needs no boolean work, and the desktop binary renders it fastest "
                          "(6-11x faster than the WebAssembly engine)"
                        : "its Manifold backend does the unions of " + what + " fastest"));
        return std::move(n.engine);
    }
    std::string wasm_missing;
    if (std::unique_ptr<ScadEngine> wasm = tryWasm(wasm_missing)) {
        std::string reason;
        if (polyhedron)
            reason = "the desktop openscad is not available (" + n.missing + ")";
        else
            reason = what + " needs boolean unions, which Manifold does 2-15x faster than the CGAL backend of " +
                     (n.engine ? n.engine->version() : std::string("the desktop openscad")) +
                     " (its output is checked: Manifold can leave a self-touching corner)";
        say("wasm: " + describe(*wasm) + "; " + reason);
        return wasm;
    }
    if (n.engine) {
        say("openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold) +
            "; the WebAssembly engine is not installed (" + wasm_missing + ")" +
            (polyhedron ? std::string() : "; CGAL unions take minutes from about 1 600 cells"));
        return std::move(n.engine);
    }
    throw ScadEngineMissing("no OpenSCAD engine is available.\n  openscad: " + n.missing + "\n  wasm: " + wasm_missing);
}

std::unique_ptr<ScadEngine> otherEngine(const ScadEngine& failed, const std::string& openscad_path, std::string* why) {
    const auto say = [&](const std::string& text) {
        if (why) *why = text;
    };
    if (failed.name() == "openscad") {
        std::string missing;
        std::unique_ptr<ScadEngine> wasm = tryWasm(missing);
        say(wasm ? "trying wasm: " + describe(*wasm) : "no other engine to try: " + missing);
        return wasm;
    }
    Native n = tryNative(openscad_path);
    say(n.engine ? "trying openscad: " + describe(*n.engine) + ", " + backendNote(n.manifold)
                 : "no other engine to try: " + n.missing);
    return std::move(n.engine);
}

}  // namespace tsf
