// The tactile scale in a generated OpenSCAD file: the staircase tsf placed
// (gen/model/features/scale.h) as data for scad_lib/tsf_scale.scad.
#pragma once

#include <optional>

#include "gen/scad/scad_attachment.h"

namespace tsf {

struct Scene;

/// The scale's piece of the file when the Scene has one: the "Tactile
/// scale" switch and `tactile_scale = [...];` (mm) for
/// scad_lib/tsf_scale.scad, wrapping the terrain in
/// tsf_with_scale(tactile_scale, show_scale).
/// join: written for scad_lib/tsf_joined.scad when it can be (gen/scad/scad_joined.h).
std::optional<ScadAttachment> scadScale(const Scene& scene, bool join);

}  // namespace tsf
