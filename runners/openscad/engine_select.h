// Choosing the OpenSCAD engine for `tsf render --engine auto|openscad|wasm`.
//
//   openscad  the desktop binary (makeOpenScadEngine): Debian's OpenSCAD
//             2021.01 by default, or the one given with --openscad PATH;
//   wasm      OpenSCAD 2025.01.19 with Manifold, compiled to WebAssembly and
//             run under Node.js (makeWasmOpenScadEngine, runners/openscad/wasm_engine.h);
//   auto      the fastest engine that is installed for the model's strategy,
//             from the measurements in docs/engines.md:
//               polyhedron (one polyhedron(), no boolean work): the desktop
//                 binary first (it starts in 0.1 s; the WebAssembly engine
//                 needs about 1 s to start and was 6-11x slower at every size);
//               csg and anything else (unions of prisms, a hand-edited file):
//                 a Manifold-capable engine first - the desktop binary when it
//                 accepts --backend=manifold, else the WebAssembly engine
//                 (2-15x faster than CGAL; 10 000 cells in 104 s, where CGAL
//                 did not finish in 15 minutes) - then CGAL;
//             and falls back to the other engine when the first is missing.
//             Manifold's csg output can fail the self-intersection check
//             (docs/engines.md); otherEngine() gives the engine to retry with.
// The choice and the reason are returned as one line for people.
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "runners/openscad/openscad_runner.h"

namespace tsf {

enum class EngineChoice { Auto, OpenScad, Wasm };

const char* toString(EngineChoice choice);  ///< "auto", "openscad", "wasm" (the CLI spellings)
/// Parses "auto", "openscad" or "wasm"; false for anything else.
bool parseEngineChoice(const std::string& text, EngineChoice& choice);

/// What a .scad file written by tsf says about itself.
struct ScadFileFacts {
    std::string strategy;  ///< "csg", "polyhedron", or "" (not a tsf model, or both)
    size_t cells = 0;      ///< cells with a pillar, from the header; 0 = unknown
};

/// Reads the facts from the text of a .scad file: the strategy from the
/// statement that draws the model (a line starting with tsf_terrain_csg( or
/// tsf_terrain_polyhedron(; a hand edit that swaps the call counts), else
/// from the header line "// Strategy:  ..."; the cell count from the header
/// line "// Grid: ..., N cells with a pillar". Unknown facts stay empty / 0.
ScadFileFacts scadFileFacts(const std::string& scad_text);

/// The engine for `choice`:
///   strategy: "polyhedron", "csg", or "" when unknown (a file not written
///             by tsf); only Auto looks at it;
///   openscad_path: the desktop binary (a path or a name in PATH; "" = "openscad");
///   cells: the model's cell count (ScadFileFacts::cells; 0 = unknown); only
///             Auto looks at it (see kCgalCsgMaxCells);
///   why (may be null): receives one line saying which engine was chosen and
///             why, e.g. "wasm: OpenSCAD version 2025.01.19 (...): csg needs
///             boolean unions, and Manifold does them 40x faster than CGAL".
/// Throws ScadEngineMissing, with the install command, when the engine asked
/// for is missing, or (Auto) when neither engine is available.
std::unique_ptr<ScadEngine> selectEngine(EngineChoice choice, const std::string& strategy,
                                         const std::string& openscad_path, std::string* why, size_t cells = 0);

/// The other engine, for a second attempt after `failed` (an engine from
/// selectEngine) produced a failed render or a mesh that failed its check:
/// the desktop binary after the WebAssembly engine and the other way round.
/// nullptr when it is not installed; *why (may be null) says which or why not.
std::unique_ptr<ScadEngine> otherEngine(const ScadEngine& failed, const std::string& openscad_path, std::string* why);

}  // namespace tsf
