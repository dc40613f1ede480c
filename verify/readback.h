// Values read back: does each pillar stand at the height its value asks for?
//
// For every kept cell of the Scene a vertical ray is cast at the cell centre
// (hexCentre + Scene::point, mm) from above the mesh downwards; the first
// surface met is the cell's top. A second ray from below upwards meets its
// bottom. The measured z is compared with the Scene's z (Scene::zMm(top[k]),
// Scene::zMm(bottom[k])) and the difference is also expressed in data units by
// inverting the value -> height transfer (ValueMapping::valueAt):
//   top:    h = z - zero, zero = floor (flat) or the mirror thickness (mirrored)
//   bottom: h = z                     (mirrored; a flat bottom carries no data)
//   value_read = valueAt(h), value_error = value_read - value clamped to
//   [baseline, value_max]. Cells without data (NaN) are compared by height only.
//
// Tolerance. The Scene's heights are integer multiples of z_snap_mm, so a
// correct mesh has each surface exactly on its step; a surface passes when it
// is within half a step (it rounds to the right step; a whole step off is a
// different height) plus the float32 rounding of a coordinate written to STL:
//   tolerance = z_snap_mm / 2 + max|z| * 2^-24.
// ReadbackOptions::height_tolerance_mm overrides the half step.
//
// A second check casts rays at the centres of grid cells that are NOT kept:
// they must meet nothing (no material where the Scene has none).
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/column_grid.h"
#include "verify/report.h"

namespace tsf {

/// Largest relative rounding of a double stored as float32 (unit roundoff, 2^-24).
inline constexpr double kFloat32UnitRoundoff = 5.9604644775390625e-8;

struct ReadbackOptions {
    double height_tolerance_mm = 0;  ///< 0 = half the Scene's z snap step
    size_t max_offenders = 10;
    bool check_outside_cells = true;
};

struct ReadbackResult {
    ReadbackFigures figures;
    std::vector<Check> checks;  ///< "values_read_back", "outside_cells_empty"
    std::vector<Stage> stages;
};

/// Reads every kept cell's heights back from `mesh` through `caster` (built on
/// the same mesh). Empty Scene: nothing to check, both checks pass.
ReadbackResult readBack(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster, const ReadbackOptions& options);

}  // namespace tsf
