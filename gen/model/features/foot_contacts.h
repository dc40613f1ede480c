// Which pillars a foot may stand against: the tactile scale's foot (east of
// the pillars, gen/model/features/scale.h) and the orientation tab (west of
// them, gen/model/features/tab/orientation_tab.h) cover some hexagon walls from
// z = 0 to the floor, as a neighbour from 0 to the floor would.
#pragma once

#include <cstdint>

#include "gen/model/scene.h"

namespace tsf {

/// True when a foot may stand against kept cell k's walls from 0 to the
/// floor: the cell is kept (k >= 0), drawn as a hexagon (not by a mark's
/// face) and rises to the floor at every corner (not a pit, not a tilted top
/// dipping below it).
bool footCanTouch(const Scene& scene, int32_t k);

/// The kept index of the cell whose centre is at lattice (i, j), or -1 (no
/// centre there, not kept, or beyond the grid).
int32_t keptAtCentre(const Scene& scene, int64_t i, int64_t j);

}  // namespace tsf
