// The support-free halves in a generated OpenSCAD file: the cut and the pin
// holes tsf placed (gen/model/features/halves.h) as data for scad_lib/tsf_halves.scad, so
// both engines cut the very holes of tsf's own mesh.
#pragma once

#include <string>

namespace tsf {

struct Scene;

/// Appends the "Halves" customizer choice (`piece`), `halves = [cut_z,
/// depth_y, holes, hole_depth, hole_tip];` and `halves_thickness` (the grown
/// slab, z steps) when the Scene has halves; nothing otherwise.
void emitHalvesData(std::string& out, const Scene& scene);

/// ",\n    min_thickness_units = halves_thickness" for tsf_model() when the
/// Scene has halves (the slab grew for the pin holes), "" otherwise.
std::string halvesModelArgument(const Scene& scene);

/// "tsf_half(piece, halves) " when the Scene has halves (it prefixes the
/// terrain call), "" otherwise.
std::string halvesCallPrefix(const Scene& scene);

}  // namespace tsf
