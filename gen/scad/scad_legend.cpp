#include "gen/scad/scad_legend.h"

#include "gen/model/features/legend_join.h"
#include "gen/mesh_io/number_text.h"
#include "gen/model/scene.h"
#include "gen/scad/scad_joined.h"

namespace tsf {
namespace {

// joined: the plate as tsf_joined.scad joins it; null: the closed plate.
void emitLegendData(std::string& o, const Scene& s, const Attachment* joined) {
    o += "/* [Braille legend] */\n"
         "// Title and value range in braille on a plate north of the pillars (docs/printing.md).\n"
         "braille_legend = true;\n\n"
         "/* [Hidden] */\n"
         "// The legend plate and its dots as tsf meshed them, in mm, for the parameters as\n"
         "// generated (the plate does not follow cell, base or mirror; regenerate with tsf\n"
         "// gen to change it). Lines:";
    for (const std::string& line : s.legend->layout.text) o += " \"" + line + "\"";
    if (joined) {
        o += "\n// The walls it stands against and its body, joined into the pillars' polyhedron (tsf_joined.scad).\n"
             "legend_plate = " + scadJoinedData(s, *joined) + ";\n" +
             scadJoinedAssert(s, "braille_legend", "the braille legend");
        return;
    }
    const Mesh plate = legendPlateMesh(s);
    o += "\nlegend_plate = [[\n";
    for (size_t k = 0; k < plate.positions.size(); ++k) {
        const Vec3& p = plate.positions[k];
        o += "  ";
        mesh_io::appendPoint(o, p.x, p.y, p.z);
        o += k + 1 < plate.positions.size() ? ",\n" : "\n";
    }
    o += "], [\n";
    for (size_t k = 0; k < plate.triangles.size(); ++k) {
        const auto& t = plate.triangles[k];
        // polyhedron() wants faces clockwise seen from outside: reversed.
        o += "  [" + std::to_string(t[0]) + ", " + std::to_string(t[2]) + ", " + std::to_string(t[1]) +
             (k + 1 < plate.triangles.size() ? "],\n" : "]\n");
    }
    o += "]];\n\n";
}

}  // namespace

std::optional<ScadAttachment> scadLegend(const Scene& s, bool join) {
    if (!s.legend) return std::nullopt;
    ScadAttachment a;
    a.placed_switch = "braille_legend";
    const std::optional<Attachment> joined = join ? legendAttachment(s, Assembly::OnePiece) : std::nullopt;
    if (joined && scadCanJoin(s, *joined)) {
        a.library_file = "tsf_joined.scad";
        emitLegendData(a.data, s, &*joined);
        a.joined = "braille_legend ? legend_plate : []";
        return a;
    }
    a.library_file = "tsf_legend.scad";
    emitLegendData(a.data, s, nullptr);
    a.call_prefix = "tsf_with_legend(legend_plate, braille_legend) ";
    return a;
}

}  // namespace tsf
