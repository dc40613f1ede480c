#include "gen/scad/scad_tab.h"

#include "gen/model/features/orientation_tab.h"
#include "gen/model/scene.h"
#include "gen/scad/scad_joined.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

void emitTabBody(std::string& o, const Scene& s) {
    // The tab as the closed body tsf meshes it (gen/model/features/orientation_tab.h:
    // meshTabBody), every face a triangle: OpenSCAD then takes each corner as
    // written, where a polygon face it must tessellate itself would have its
    // corners moved to its 2^-20 mm grid (and the union with them).
    const JoinedBody body = meshTabBody(s, /*joined=*/false);
    o += "// [points, triangles] (mm) of a closed body, triangles counter-clockwise seen from outside.\n"
         "orientation_tab = [[";
    for (size_t v = 0; v < body.mesh.positions.size(); ++v) {
        const Vec3& p = body.mesh.positions[v];
        o += std::string(v ? ", " : "") + "[" + formatShortest(p.x) + ", " + formatShortest(p.y) + ", " + formatShortest(p.z) + "]";
    }
    o += "], [";
    for (size_t t = 0; t < body.mesh.triangles.size(); ++t) {
        const auto& f = body.mesh.triangles[t];
        o += std::string(t ? ", " : "") + "[" + std::to_string(f[0]) + ", " + std::to_string(f[1]) + ", " + std::to_string(f[2]) + "]";
    }
    o += "]];\n";
}

void emitTabAssert(std::string& o, const Scene& s) {
    // The tab stands against the pillars' walls where tsf put them: another
    // cell, base, snap or mirror would move the walls away from it; on a
    // mirrored model it lies in the band its pillar spans, which every
    // parameter moves.
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    const std::string names = mirrored ? "[cell, height, transfer, baseline, value_max, snap, base, mirror]" : "[cell, base, snap, mirror]";
    const std::string values =
        mirrored ? "[" + formatShortest(s.pitch_mm) + ", " + formatShortest(s.mapping.max_height_mm) + ", \"" +
                       toString(s.mapping.transfer) + "\", " + formatShortest(s.mapping.baseline) + ", " +
                       formatShortest(s.mapping.value_max) + ", " + formatShortest(s.z_snap_mm) + ", " +
                       formatShortest(s.params.base_mm) + ", true]"
                 : "[" + formatShortest(s.pitch_mm) + ", " + formatShortest(s.params.base_mm) + ", " +
                       formatShortest(s.z_snap_mm) + ", false]";
    o += "assert(!show_orientation_tab || " + names + " == " + values + ",\n       \"the orientation tab was placed by tsf for the " +
         (mirrored ? std::string("values and parameters") : std::string("cell, base, snap and mirror")) +
         " it wrote: set show_orientation_tab = false, or run tsf gen again to change them\");\n\n";
}

// joined: the tab as tsf_joined.scad joins it; null: the closed body.
void emitTabData(std::string& o, const Scene& s, const Attachment* joined) {
    o += "/* [Orientation marks] */\n"
         "// The tab west of the pillars: the notch cut into its south-west corner, the\n"
         "// triangle (right angle south-west, the longer leg east) on its top (docs/model.md).\n"
         "show_orientation_tab = true;\n\n"
         "/* [Hidden] */\n"
         "// The tab as tsf placed it, for the parameters as generated (it does not\n"
         "// follow cell, base, snap or mirror; regenerate with tsf gen to change them):\n";
    if (joined) {
        o += "// the walls it stands against and its body, joined into the pillars' polyhedron (tsf_joined.scad).\n"
             "orientation_tab = " + scadJoinedData(s, *joined) + ";\n";
    } else {
        emitTabBody(o, s);
    }
    emitTabAssert(o, s);
}

}  // namespace

std::optional<ScadAttachment> scadTab(const Scene& s, bool join) {
    if (!s.marks.tab) return std::nullopt;
    ScadAttachment a;
    a.placed_switch = "show_orientation_tab";
    const std::optional<Attachment> joined = join ? tabAttachment(s, Assembly::OnePiece) : std::nullopt;
    if (joined && scadCanJoin(s, *joined)) {
        a.library_file = "tsf_joined.scad";
        emitTabData(a.data, s, &*joined);
        a.joined = "show_orientation_tab ? orientation_tab : []";
        return a;
    }
    a.library_file = "tsf_tab.scad";
    emitTabData(a.data, s, nullptr);
    a.call_prefix = "tsf_with_tab(orientation_tab, show_orientation_tab) ";
    return a;
}

}  // namespace tsf
