// The braille legend in a generated OpenSCAD file: the plate tsf meshed
// (gen/model/features/legend_scene.h) as data for scad_lib/tsf_legend.scad, so both engines
// draw the very dots of tsf's own mesh.
#pragma once

#include <optional>

#include "gen/scad/scad_attachment.h"

namespace tsf {

struct Scene;

/// The legend's piece of the file when the Scene has one: the "Braille
/// legend" switch and `legend_plate = [points, faces];` (mm; faces clockwise
/// from outside, as polyhedron() wants) for scad_lib/tsf_legend.scad,
/// wrapping the terrain in tsf_with_legend(legend_plate, braille_legend).
/// join: written for scad_lib/tsf_joined.scad when it can be (gen/scad/scad_joined.h).
std::optional<ScadAttachment> scadLegend(const Scene& scene, bool join);

}  // namespace tsf
