// The tactile scale in a generated OpenSCAD file: the staircase tsf placed
// (gen/model/features/scale.h) as data for scad_lib/tsf_scale.scad.
#pragma once

#include <string>

namespace tsf {

struct Scene;

/// Appends the "Tactile scale" customizer switch and `tactile_scale = [...];`
/// (mm) when the Scene has a scale; nothing otherwise.
void emitScaleData(std::string& out, const Scene& scene);

/// "tsf_with_scale(tactile_scale, show_scale) " when the Scene has a scale
/// (it prefixes the terrain call), "" otherwise.
std::string scaleCallPrefix(const Scene& scene);

}  // namespace tsf
