// Tops that are not level hexagons: tilted (--tilt), dimpled (structural
// cells of a point table) or textured (a class map's classes), decided
// once as corner heights and fan centres (gen/model/features/top_shapes.h).
// A tilted mirrored model then comes down to stand on its lowest corner.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf {

/// Shapes the tops the parameters ask for, with their notes. h_units: the
/// cells' heights by grid index (a structural cell is a kept data cell at
/// height 0 that no input value fell in). After the marks, the halves and
/// a tile's code pits (they keep their cells level), before the legend and
/// the tab (they take their z from the cells).
void shapeTops(const HexField& field, const std::vector<int64_t>& h_units, const SceneParams& params, Scene& s);

}  // namespace tsf
