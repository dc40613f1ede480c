// estimateScadRender: linear in the cells, with measured constants. See scad_render_cost.h.
#include "gen/scad/scad_render_cost.h"

#include <cstdio>

namespace tsf {
namespace {

// Per cell and fixed costs, measured on the 2-core reference machine
// (docs/engines.md, "Size limits"): seconds and MB per cell, and the engine's
// start-up time and memory.
struct Rate {
    double s_per_cell, mb_per_cell, s_fixed, mb_fixed;
};
// One polyhedron() evaluated by the library: the evaluation of the cells'
// triangles dominates, and the point list it builds (three points a triangle).
constexpr Rate kPolyhedron2021{0.00068, 0.0184, 0.1, 35};
constexpr Rate kPolyhedron2025{0.0035, 0.0240, 1.0, 130};
// A union of one prism per cell: CGAL (2021) grows faster than linearly and
// did not finish 10 000 cells in 15 minutes; Manifold (2025) took 104 s and
// 1.9 GB for 10 000 cells.
constexpr Rate kCsg2021{0.0625, 0.17, 0.1, 35};
constexpr Rate kCsg2025{0.0104, 0.19, 1.0, 130};

ScadEngineCost cost(const Rate& r, size_t cells, double limit_mb) {
    ScadEngineCost c;
    c.seconds = r.s_fixed + r.s_per_cell * double(cells);
    c.peak_mb = r.mb_fixed + r.mb_per_cell * double(cells);
    c.within = c.seconds <= kScadReasonableSeconds && c.peak_mb <= limit_mb;
    return c;
}

std::string describe(const char* engine, const ScadEngineCost& c, double limit_mb) {
    char buf[256];
    std::snprintf(buf, sizeof buf, "%s about %.0f s and %.1f GB%s", engine, c.seconds, c.peak_mb / 1024.0,
                  c.peak_mb > limit_mb ? " (over its memory limit: it will fail)"
                  : c.seconds > kScadReasonableSeconds ? " (slow)"
                                                        : "");
    return buf;
}

}  // namespace

ScadRenderCost estimateScadRender(const Scene& scene, ScadOptions::Strategy strategy) {
    ScadRenderCost c;
    c.cells = scene.keptCount();
    const bool csg = strategy == ScadOptions::Strategy::Csg;
    c.desktop_2021 = cost(csg ? kCsg2021 : kPolyhedron2021, c.cells, kScadReasonableDesktopMb);
    c.wasm_2025 = cost(csg ? kCsg2025 : kPolyhedron2025, c.cells, kScadWasmLimitMb);
    return c;
}

std::string scadRenderWarning(const ScadRenderCost& cost, const std::string& scad_path) {
    if (cost.desktop_2021.within && cost.wasm_2025.within) return "";
    return scad_path + " has " + std::to_string(cost.cells) + " cells; rendering it takes " +
           describe("OpenSCAD 2021.01", cost.desktop_2021, kScadReasonableDesktopMb) + ", " +
           describe("the 2025 WebAssembly engine", cost.wasm_2025, kScadWasmLimitMb) +
           " (measured rates, docs/engines.md); fewer cells (--bins, --cell) render faster";
}

}  // namespace tsf
