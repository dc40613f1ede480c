#include "gen/scad/scad_scale.h"

#include "gen/field/hex_grid.h"
#include "gen/mesh_io/number_text.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

std::string shortest(double v) {
    std::string s;
    mesh_io::appendShortest(s, v);
    return s;
}

}  // namespace

void emitScaleData(std::string& o, const Scene& s) {
    if (!s.scale) return;
    const SceneScale& sc = *s.scale;
    o += "/* [Tactile scale] */\n"
         "// A staircase east of the pillars: each tread at the height of a value (docs/model.md).\n"
         "show_scale = true;\n\n"
         "/* [Hidden] */\n"
         "// The scale as tsf placed it, in mm, for the parameters as generated (it does not\n"
         "// follow cell, height or base; regenerate with tsf gen to change it): one step\n"
         "// every " + shortest(sc.step) + " from the floor (" + shortest(s.mapping.baseline) + "), treads for";
    for (const ScaleStep& st : sc.steps) o += " " + shortest(st.value);
    o += ".\ntactile_scale = [[" + shortest(sc.x0_mm) + ", " + shortest(sc.xs_mm) + ", " + shortest(sc.x1_mm) + "], [" +
         shortest(sc.y0_mm) + ", " + shortest(sc.y1_mm) + "], " + shortest(s.zMm(sc.foot_top_units)) + ", [\n";
    for (size_t k = 0; k < sc.steps.size(); ++k) {
        const ScaleStep& st = sc.steps[k];
        o += "  [" + shortest(st.y_south_mm) + ", " + shortest(st.y_north_mm) + ", " + shortest(s.zMm(st.top_units)) +
             (k + 1 < sc.steps.size() ? "],\n" : "]\n");
    }
    // The notches between contacts the foot fills: [x, y] corners counter-clockwise.
    o += "], [\n";
    auto xy = [&](int32_t k, int e) {
        const Vec3 p = s.point(hexCorner(s.grid, s.col[size_t(k)], s.row[size_t(k)], e), 0);
        return "[" + shortest(p.x) + ", " + shortest(p.y) + "]";
    };
    for (size_t n = 0; n + 1 < sc.contacts.size(); ++n) {
        const int32_t lower = sc.contacts[n], upper = sc.contacts[n + 1];
        o += "  [" + xy(lower, 1) + ", " + xy(upper, 0) + ", " + xy(upper, 5) + ", " + xy(lower, 2) +
             (n + 2 < sc.contacts.size() ? "],\n" : "]\n");
    }
    o += "]];\n\n";
}

std::string scaleCallPrefix(const Scene& s) { return s.scale ? "tsf_with_scale(tactile_scale, show_scale) " : ""; }

}  // namespace tsf
