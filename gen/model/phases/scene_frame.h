// The Scene's frame, before any cell is kept: the lattice, the parameters
// as resolved, how values become heights (the mapping, or a class map's
// one height and its textures) and how wide a cell is (pitch, mm, and the
// north-south stretch of a raster's rows).
#pragma once

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

/// A Scene holding the frame and its notes, no cells yet. Throws
/// InputError for a mapping or a cell size that cannot be made
/// (value_mapping.h; cells narrower than kMinPitchMm, a model over 100 m, a
/// --cell that does not fit the --width/--depth box).
Scene sceneFrame(const HexField& field, const SceneParams& params);

}  // namespace tsf
