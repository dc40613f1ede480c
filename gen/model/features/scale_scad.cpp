// The tactile scale's piece of a generated OpenSCAD file (gen/model/feature.h:
// ScadPiece): the staircase tsf placed as data for scad_lib/tsf_scale.scad.
#include <string>
#include <vector>

#include "gen/field/hex_grid.h"
#include "gen/model/features/scale.h"
#include "gen/util/number_format.h"

namespace tsf {

std::optional<ScadPiece> scaleScadPiece(const Scene& s) {
    const SceneScale* scale = sceneScale(s);
    if (!scale) return std::nullopt;
    const SceneScale& sc = *scale;
    ScadPiece piece;
    piece.show_switch = "show_scale";
    piece.variable = "tactile_scale";
    piece.what = "the tactile scale";
    piece.library_file = "tsf_scale.scad";
    piece.module_call = "tsf_with_scale(tactile_scale, show_scale) ";
    std::string& o = piece.header;
    o += "/* [Tactile scale] */\n"
         "// A staircase east of the pillars: each tread at the height of a value (docs/model.md).\n"
         "show_scale = true;\n\n"
         "/* [Hidden] */\n"
         "// The scale as tsf placed it, in mm, for the parameters as generated (it does not\n"
         "// follow cell, height or base; regenerate with tsf gen to change it): one step\n"
         "// every " + formatShortest(sc.step) + " from the floor (" + formatShortest(s.mapping.baseline) + "), treads for";
    for (const ScaleStep& st : sc.steps) o += " " + formatShortest(st.value);

    // [[x0, xs, x1], [y0, y1], foot_top, steps, notches] (scad_lib/tsf_scale.scad).
    std::string& v = piece.value;
    v = "[[" + formatShortest(sc.x0_mm) + ", " + formatShortest(sc.xs_mm) + ", " + formatShortest(sc.x1_mm) + "], [" +
        formatShortest(sc.y0_mm) + ", " + formatShortest(sc.y1_mm) + "], " + formatShortest(s.zMm(sc.foot_top_units)) + ", [\n";
    for (size_t k = 0; k < sc.steps.size(); ++k) {
        const ScaleStep& st = sc.steps[k];
        v += "  [" + formatShortest(st.y_south_mm) + ", " + formatShortest(st.y_north_mm) + ", " + formatShortest(s.zMm(st.top_units)) +
             (k + 1 < sc.steps.size() ? "],\n" : "]\n");
    }
    // The notches between contacts the foot fills: [x, y] corners counter-clockwise.
    v += "], [\n";
    auto xy = [&](int32_t k, int e) {
        const Vec3 p = s.point(hexCorner(s.grid, s.col[size_t(k)], s.row[size_t(k)], e), 0);
        return "[" + formatShortest(p.x) + ", " + formatShortest(p.y) + "]";
    };
    std::vector<std::string> notches;
    for (size_t n = 0; n + 1 < sc.contacts.size(); ++n) {
        if (sc.fillers[n] < 0) continue;  // further apart than a notch: the foot stands free between them
        const int32_t lower = sc.contacts[n], upper = sc.contacts[n + 1];
        notches.push_back("  [" + xy(lower, 1) + ", " + xy(upper, 0) + ", " + xy(upper, 5) + ", " + xy(lower, 2) + "]");
    }
    for (size_t n = 0; n < notches.size(); ++n) v += notches[n] + (n + 1 < notches.size() ? ",\n" : "\n");
    v += "]]";
    return piece;
}

}  // namespace tsf
