// checkScene: does a Scene hold the invariants the direct mesher builds on?
//
// buildScene (gen/model/scene.h) makes every Scene it returns hold them; a Scene
// that comes from anywhere else (a library user, an edited sidecar read by
// readSceneJson) is checked by meshScene with this before it is meshed, so
// a bad Scene is a tsf::InputError, never an assertion or a broken mesh:
//   - the cell lists (col, row, value, top, bottom) have one entry per kept
//     cell, each inside the grid, and kept_index maps each back to it;
//   - pitch_mm is finite and at least 50 xy snap steps (buildScene's smallest
//     cell), z_snap_mm is positive and finite;
//   - every kept cell has bottom < top;
//   - the z intervals of two neighbouring kept cells overlap by at least one
//     snap step (else the union is not a 2-manifold);
//   - the kept cells form one edge-connected piece;
//   - flat bottom: every bottom is 0 and the kept region has no holes (its
//     bottom is one polygon).
//   - shaped tops (gen/model/features/top_shapes.h): checkTopShapes.
#pragma once

#include "gen/model/scene.h"

namespace tsf {

/// Throws tsf::InputError naming the first broken invariant (listed above)
/// and the cell where it is broken. An empty Scene (no kept cells) passes.
void checkScene(const Scene& scene);

}  // namespace tsf
