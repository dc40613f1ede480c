#include "gen/scad/scad_scale.h"

#include <string>
#include <vector>

#include "gen/field/hex_grid.h"
#include "gen/mesh_io/number_text.h"
#include "gen/model/scene.h"
#include "gen/util/number_format.h"
#include "gen/model/features/scale.h"
#include "gen/scad/scad_joined.h"

namespace tsf {
namespace {

// joined: the staircase as tsf_joined.scad joins it; null: boxes to union.
void emitScaleData(std::string& o, const Scene& s, const Attachment* joined) {
    const SceneScale& sc = *sceneScale(s);
    o += "/* [Tactile scale] */\n"
         "// A staircase east of the pillars: each tread at the height of a value (docs/model.md).\n"
         "show_scale = true;\n\n"
         "/* [Hidden] */\n"
         "// The scale as tsf placed it, in mm, for the parameters as generated (it does not\n"
         "// follow cell, height or base; regenerate with tsf gen to change it): one step\n"
         "// every " + formatShortest(sc.step) + " from the floor (" + formatShortest(s.mapping.baseline) + "), treads for";
    for (const ScaleStep& st : sc.steps) o += " " + formatShortest(st.value);
    if (joined) {
        o += ".\n// The walls it stands against and its body, joined into the pillars' polyhedron (tsf_joined.scad).\n"
             "tactile_scale = " + scadJoinedData(s, *joined) + ";\n" +
             scadJoinedAssert(s, "show_scale", "the tactile scale");
        return;
    }
    o += ".\ntactile_scale = [[" + formatShortest(sc.x0_mm) + ", " + formatShortest(sc.xs_mm) + ", " + formatShortest(sc.x1_mm) + "], [" +
         formatShortest(sc.y0_mm) + ", " + formatShortest(sc.y1_mm) + "], " + formatShortest(s.zMm(sc.foot_top_units)) + ", [\n";
    for (size_t k = 0; k < sc.steps.size(); ++k) {
        const ScaleStep& st = sc.steps[k];
        o += "  [" + formatShortest(st.y_south_mm) + ", " + formatShortest(st.y_north_mm) + ", " + formatShortest(s.zMm(st.top_units)) +
             (k + 1 < sc.steps.size() ? "],\n" : "]\n");
    }
    // The notches between contacts the foot fills: [x, y] corners counter-clockwise.
    o += "], [\n";
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
    for (size_t n = 0; n < notches.size(); ++n) o += notches[n] + (n + 1 < notches.size() ? ",\n" : "\n");
    o += "]];\n\n";
}

}  // namespace

std::optional<ScadAttachment> scadScale(const Scene& s, bool join) {
    if (!sceneScale(s)) return std::nullopt;
    ScadAttachment a;
    a.placed_switch = "show_scale";
    const std::optional<Attachment> joined = join ? scaleAttachment(s, Assembly::OnePiece) : std::nullopt;
    if (joined && scadCanJoin(s, *joined)) {
        a.library_file = "tsf_joined.scad";
        emitScaleData(a.data, s, &*joined);
        a.joined = "show_scale ? tactile_scale : []";
        return a;
    }
    a.library_file = "tsf_scale.scad";
    emitScaleData(a.data, s, nullptr);
    a.call_prefix = "tsf_with_scale(tactile_scale, show_scale) ";
    return a;
}

}  // namespace tsf
