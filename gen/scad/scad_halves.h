// The support-free halves in a generated OpenSCAD file: the cut and the pin
// holes tsf placed (gen/model/features/halves.h) as data for scad_lib/tsf_halves.scad, so
// both engines cut the very holes of tsf's own mesh.
#pragma once

#include <optional>

#include "gen/scad/scad_attachment.h"

namespace tsf {

struct Scene;

/// The halves' piece of the file when the Scene has them: the "Halves"
/// choice (`piece`), `halves = [cut_z, depth_y, holes, hole_depth,
/// hole_tip];` and `halves_thickness` (the grown slab, z steps) for
/// scad_lib/tsf_halves.scad; tsf_model() takes `min_thickness_units =
/// halves_thickness` and tsf_half(piece, halves) wraps the terrain.
std::optional<ScadAttachment> scadHalves(const Scene& scene);

}  // namespace tsf
