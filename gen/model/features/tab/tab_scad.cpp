// The orientation tab's piece of a generated OpenSCAD file
// (gen/model/feature.h: ScadPiece): the tab tsf placed, as data for
// scad_lib/tsf_tab.scad, with its own assert (on a mirrored model it lies
// in the band its pillars span, which every height parameter moves).
#include <string>

#include "gen/model/features/tab/orientation_tab.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

// The tab as the closed body tsf meshes it (meshTabBody), every face a
// triangle: OpenSCAD then takes each corner as written, where a polygon
// face it must tessellate itself would have its corners moved to its
// 2^-20 mm grid (and the union with them).
std::string tabBodyValue(const Scene& s) {
    const JoinedBody body = meshTabBody(s, /*joined=*/false);
    std::string o = "[[";
    for (size_t v = 0; v < body.mesh.positions.size(); ++v) {
        const Vec3& p = body.mesh.positions[v];
        o += std::string(v ? ", " : "") + "[" + formatShortest(p.x) + ", " + formatShortest(p.y) + ", " + formatShortest(p.z) + "]";
    }
    o += "], [";
    for (size_t t = 0; t < body.mesh.triangles.size(); ++t) {
        const auto& f = body.mesh.triangles[t];
        o += std::string(t ? ", " : "") + "[" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + "]";
    }
    return o + "]]";
}

// The tab stands against the pillars' walls where tsf put them: another
// cell, base, snap or mirror would move the walls away from it; on a
// mirrored model it lies in the band its pillar spans, which every
// parameter moves.
std::string tabAssert(const Scene& s) {
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    const std::string names = mirrored ? "[cell, height, transfer, baseline, value_max, snap, base, mirror]" : "[cell, base, snap, mirror]";
    const std::string values =
        mirrored ? "[" + formatShortest(s.pitch_mm) + ", " + formatShortest(s.mapping.max_height_mm) + ", \"" +
                       toString(s.mapping.transfer) + "\", " + formatShortest(s.mapping.baseline) + ", " +
                       formatShortest(s.mapping.value_max) + ", " + formatShortest(s.z_snap_mm) + ", " +
                       formatShortest(s.params.base_mm) + ", true]"
                 : "[" + formatShortest(s.pitch_mm) + ", " + formatShortest(s.params.base_mm) + ", " +
                       formatShortest(s.z_snap_mm) + ", false]";
    return "assert(!show_orientation_tab || " + names + " == " + values + ",\n       \"the orientation tab was placed by tsf for the " +
           (mirrored ? std::string("values and parameters") : std::string("cell, base, snap and mirror")) +
           " it wrote: set show_orientation_tab = false, or run tsf gen again to change them\");\n\n";
}

}  // namespace

std::optional<ScadPiece> tabScadPiece(const Scene& s) {
    if (!sceneTab(s)) return std::nullopt;
    ScadPiece piece;
    piece.show_switch = "show_orientation_tab";
    piece.variable = "orientation_tab";
    piece.what = "the orientation tab";
    piece.library_file = "tsf_tab.scad";
    piece.module_call = "tsf_with_tab(orientation_tab, show_orientation_tab) ";
    piece.header = "/* [Orientation marks] */\n"
                   "// The tab west of the pillars: the notch cut into its south-west corner, the\n"
                   "// triangle (right angle south-west, the longer leg east) on its top (docs/model.md).\n"
                   "show_orientation_tab = true;\n\n"
                   "/* [Hidden] */\n"
                   "// The tab as tsf placed it, for the parameters as generated (it does not\n"
                   "// follow cell, base, snap or mirror; regenerate with tsf gen to change them):\n";
    piece.joined_lead = "// the walls it stands against and its body, joined into the pillars' polyhedron (tsf_joined.scad).\n";
    piece.value_lead = "// [points, triangles] (mm) of a closed body, triangles counter-clockwise seen from outside.\n";
    piece.value = tabBodyValue(s);
    piece.own_assert = tabAssert(s);
    return piece;
}

}  // namespace tsf
