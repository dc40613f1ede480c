// Each kept pillar's span: its bottom and top, in z snap steps.
//
// Height rules (the OpenSCAD library mirrors them; keep both in step):
//   h_units   = snapUnits(mapping.heightMm(value), z_snap)   (0 for no-data cells)
//   flat:     bottom = 0,        top = snapUnits(base_mm) + h_units
//   mirrored: bottom = h_units - S,  top = bottom + T,
//             S = the least h_units of the kept cells with data (the model
//                 stands on z = 0; no-data cells count as 0 after it),
//                 less a class texture's relief (tilted tops: the
//                 lowest corner once they are resolved; cell_heights.h),
//             T = max |h_units(a) - h_units(b)| over neighbouring kept cells
//                 + snapUnits(base_mm)   (grown for halves: halves_slab.h)
// A kept cell without data is a pit: below the floor (flat), or cut from
// both faces of the slab (mirrored).
#pragma once

#include <cstdint>
#include <vector>

#include "gen/model/scene.h"

namespace tsf {

/// Sets s.top, s.bottom, s.floor_units, s.nodata_pit_units and (mirrored)
/// s.mirror_thickness_units and s.halves' slab, from the grid cells'
/// heights (h_units, by grid index, after lowerToMirroredFloor) and the
/// floor's shift (mirror_shift_units). Needs the kept cells listed.
void stackPillars(const std::vector<int64_t>& h_units, int64_t mirror_shift_units, Scene& s);

}  // namespace tsf
