// STL and 3MF store float32 coordinates: a model written to them needs a z
// grid float32 resolves at the model's highest z. When the grid asked for
// is finer, the Scene is built again on a coarser one.
#pragma once

#include <optional>

#include "gen/model/scene.h"

namespace tsf {

/// The highest z the mesh reaches, mm: tops with their tilted corners and
/// the orientation triangle, and a braille dot's height above a legend's plate.
double highestZMm(const Scene& s);

/// For a Scene to be stored as float32 (params.stored_as_float32): the
/// coarser z snap step, mm, it needs (the finest 1, 2 or 5 x 10^k mm grid
/// whose steps float32 keeps apart at highestZMm); none when its own step
/// is fine enough. Throws InputError when even kMaxSnapMm is too fine.
std::optional<double> float32SnapMm(const SceneParams& params, const Scene& s);

/// The parameters of the build again on the coarser grid.
SceneParams coarserSnap(const SceneParams& params, double snap_mm);

/// The rebuilt Scene says it is stored as float32 and why its heights
/// snap to snap_mm rather than the step asked for.
void noteCoarserSnap(const SceneParams& params, double snap_mm, Scene& again);

}  // namespace tsf
