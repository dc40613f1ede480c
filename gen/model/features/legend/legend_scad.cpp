// The braille legend's piece of a generated OpenSCAD file (gen/model/feature.h:
// ScadPiece): the plate tsf meshed (legend_scene.h) as data for
// scad_lib/tsf_legend.scad, so both engines draw the very dots of tsf's own
// mesh.
#include <string>

#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_join.h"
#include "gen/util/number_format.h"

namespace tsf {

std::optional<ScadPiece> legendScadPiece(const Scene& s) {
    const SceneLegend* legend = sceneLegend(s);
    if (!legend) return std::nullopt;
    ScadPiece piece;
    piece.show_switch = "braille_legend";
    piece.variable = "legend_plate";
    piece.what = "the braille legend";
    piece.library_file = "tsf_legend.scad";
    piece.module_call = "tsf_with_legend(legend_plate, braille_legend) ";
    std::string& o = piece.header;
    o += "/* [Braille legend] */\n"
         "// Title and value range in braille on a plate north of the pillars (docs/printing.md).\n"
         "braille_legend = true;\n\n"
         "/* [Hidden] */\n"
         "// The legend plate and its dots as tsf meshed them, in mm, for the parameters as\n"
         "// generated (the plate does not follow cell, base or mirror; regenerate with tsf\n"
         "// gen to change it). Lines:";
    for (const std::string& line : legend->layout.text) o += " \"" + line + "\"";
    // A list of lines in quotes: the sentence ends without a full stop.
    piece.header_end = "";

    // [points, faces] (mm; faces clockwise from outside, as polyhedron() wants).
    const Mesh plate = legendPlateMesh(s);
    std::string& v = piece.value;
    v = "[[\n";
    for (size_t k = 0; k < plate.positions.size(); ++k) {
        const Vec3& p = plate.positions[k];
        v += "  [" + formatShortest(p.x) + ", " + formatShortest(p.y) + ", " + formatShortest(p.z) + "]";
        v += k + 1 < plate.positions.size() ? ",\n" : "\n";
    }
    v += "], [\n";
    for (size_t k = 0; k < plate.triangles.size(); ++k) {
        const auto& t = plate.triangles[k];
        // polyhedron() wants faces clockwise seen from outside: reversed.
        v += "  [" + std::to_string(t[0]) + ", " + std::to_string(t[2]) + ", " + std::to_string(t[1]) +
             (k + 1 < plate.triangles.size() ? "],\n" : "]\n");
    }
    v += "]]";
    return piece;
}

}  // namespace tsf
