// The braille legend in a generated OpenSCAD file: the plate tsf meshed
// (gen/model/features/legend_scene.h) as data for scad_lib/tsf_legend.scad, so both engines
// draw the very dots of tsf's own mesh.
#pragma once

#include <string>

namespace tsf {

struct Scene;

/// Appends the "Braille legend" customizer switch and `legend_plate =
/// [points, faces];` (mm; faces clockwise from outside, as polyhedron()
/// wants) when the Scene has a legend; nothing otherwise.
void emitLegendData(std::string& out, const Scene& scene);

/// "tsf_with_legend(legend_plate, braille_legend) " when the Scene has a
/// legend (it prefixes the terrain call), "" otherwise.
std::string legendCallPrefix(const Scene& scene);

}  // namespace tsf
