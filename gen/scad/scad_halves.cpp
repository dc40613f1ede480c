// The halves as data for scad_lib/tsf_halves.scad. See scad_halves.h.
#include "gen/scad/scad_halves.h"

#include <cmath>

#include "gen/model/features/halves.h"
#include "gen/mesh_io/number_text.h"
#include "gen/model/scene.h"

namespace tsf {
namespace {

void appendXy(std::string& o, const Vec3& p) {
    o += "[";
    mesh_io::appendShortest(o, p.x);
    o += ", ";
    mesh_io::appendShortest(o, p.y);
    o += "]";
}

void emitHalvesData(std::string& o, const Scene& s) {
    const SceneHalves& h = *s.halves;
    o += "/* [Halves] */\n"
         "// Which piece to draw: the whole model, or a half as it prints without supports\n"
         "// (cut face down, pin holes in it; docs/printing.md). The pins: MODEL-pins.stl.\n"
         "piece = \"whole\"; // [whole, upper, lower]\n\n"
         "/* [Hidden] */\n"
         "// The cut and the pin holes as tsf placed them, mm, for the parameters as generated:\n"
         "// [cut z, model depth (the lower half turns about its middle), holes [[centre], [corners]],\n"
         "//  straight depth of a hole, depth to its cone's tip].\n"
         "halves_thickness = " + std::to_string(s.mirror_thickness_units) + ";\n"
         "halves = [";
    mesh_io::appendShortest(o, s.zMm(h.split_units));
    o += ", ";
    mesh_io::appendShortest(o, std::round(gridDepth(s.grid, s.pitch_mm, s.y_scale) / kXYSnapMm) * kXYSnapMm);
    o += ", [\n";
    for (size_t n = 0; n < h.hole_centres.size(); ++n) {
        o += "  [";
        appendXy(o, s.point(h.hole_centres[n], 0));
        o += ", [";
        const std::vector<PlanarPoint> ring = holeRing(s, n);
        for (size_t k = 0; k < ring.size(); ++k) {
            if (k) o += ", ";
            appendXy(o, s.point(ring[k], 0));
        }
        o += n + 1 < h.hole_centres.size() ? "]],\n" : "]]\n";
    }
    o += "], ";
    mesh_io::appendShortest(o, s.zMm(h.hole_depth_units));
    o += ", ";
    mesh_io::appendShortest(o, s.zMm(h.hole_apex_units));
    o += "];\n\n";
}

}  // namespace

std::optional<ScadAttachment> scadHalves(const Scene& s) {
    if (!s.halves) return std::nullopt;
    ScadAttachment a;
    a.library_file = "tsf_halves.scad";
    emitHalvesData(a.data, s);
    a.model_argument = ",\n                  min_thickness_units = halves_thickness";
    a.call_prefix = "tsf_half(piece, halves) ";
    return a;
}

}  // namespace tsf
