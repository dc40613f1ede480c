// Tilts read back: does each tilted top (and mirrored bottom) lean as the
// Scene says (gen/model/features/tilt.h)?
//
// For every kept cell whose Scene slope is not level, vertical rays are cast
// at its centre and halfway along each of the six spokes from the centre to
// a corner (on the spokes the fan's height is the straight line between the
// centre and the corner, whatever crossings its edges carry). The slope is
// the least-squares plane through the centre and the six points:
//   g = sum (z_e - z_centre) d_e / (3 |d|^2),  |d| = R / 2,  R = pitch / sqrt 3,
// measured from above on the top and, mirrored, from below on the bottom
// (a mirrored bottom is the top moved down by the slab: the same slope).
//
// Tolerance per cell (mm per mm, on the length of the slope error vector):
//   4 (z_snap / 4 + |g| * kXYSnapMm + 2 * max|z| * 2^-24) / R
// from: each corner rounded to the z grid (half a step, halved at the
// midpoint of a spoke), the corner's xy rounded to 1 um (|g| um of height
// each), the float32 rounding of the sample and of the centre in an STL; the
// plane fit turns a height error e into at most 2 e / |d| of slope.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/column_grid.h"
#include "verify/report.h"

namespace tsf {

struct TiltReadbackResult {
    TiltReadbackFigures figures;
    std::vector<Check> checks;  ///< "tilts_read_back"
    std::vector<Stage> stages;
};

/// Reads the tilt of every tilted cell back from `mesh` through `caster`.
/// A Scene without tilted cells gives no check.
TiltReadbackResult readBackTilt(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster);

}  // namespace tsf
