// ScadRenderCost: what rendering a generated .scad file will cost, from the
// number of cells, before anyone waits for it.
//
// OpenSCAD evaluates the library's functions for every cell, so time and
// memory grow linearly with the cells; the constants are measured (wall time
// on the 2-core reference machine, peak resident memory; docs/engines.md,
// "Size limits"). `tsf gen --scad` warns with these figures when a file
// exceeds what an engine renders in reasonable time or memory.
#pragma once

#include <string>

#include "gen/scad/scad_emitter.h"
#include "gen/model/scene.h"

namespace tsf {

struct ScadEngineCost {
    double seconds = 0;   ///< estimated wall time of the render
    double peak_mb = 0;   ///< estimated peak memory, MB
    bool within = true;   ///< within kScadReasonableSeconds and the engine's memory limit
};

struct ScadRenderCost {
    size_t cells = 0;
    ScadEngineCost desktop_2021;  ///< OpenSCAD 2021.01, CGAL
    ScadEngineCost wasm_2025;     ///< OpenSCAD 2025.01 WebAssembly, Manifold (4 GB address space)
};

/// A render that takes longer than this (s) is called unreasonable.
inline constexpr double kScadReasonableSeconds = 120.0;
/// Memory a desktop render may use before it is called unreasonable (MB).
inline constexpr double kScadReasonableDesktopMb = 4096.0;
/// The WebAssembly engine cannot address more than 4 GB; with its own heap
/// and the module, a render fails well before that (MB).
inline constexpr double kScadWasmLimitMb = 3500.0;

/// Estimated cost of rendering the file writeScad makes of `scene` with `strategy`.
ScadRenderCost estimateScadRender(const Scene& scene, ScadOptions::Strategy strategy);

/// A warning for the user when an engine is estimated over its limits, with
/// the numbers; "" when both are within them.
std::string scadRenderWarning(const ScadRenderCost& cost, const std::string& scad_path);

}  // namespace tsf
