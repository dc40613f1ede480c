// Printability: warnings about features a printer may not reproduce.
//
// Measured on the mesh with rays along the normal of each planar region
// (edge-connected coplanar triangles facing the same way), cast from the
// centroid of the region's largest triangle. This is a sampling: a feature
// narrower than the region around it can be missed. On a tsf model a region is
// one hexagonal top or one wall between two cells.
//   [wall_thickness]  steep triangles (|n_z| < 1/2), ray inwards: the material's
//                     horizontal thickness there (a one-cell ridge is one pitch wide);
//                     warns below nozzle_mm;
//   [gap_width]       steep triangles, ray outwards: the distance to the wall
//                     opposite (a one-cell valley), looked for up to ten
//                     nozzle widths away; warns below nozzle_mm;
//                     both measured where a printer draws the wall: a width
//                     under the nozzle is kept only where the wall face is at
//                     least a layer tall (less is one layer's step), and where
//                     the material or gap narrows toward the wall's top or
//                     bottom (the wedge under a tilted top's rim, thinner than
//                     any nozzle at its very edge) it is measured a layer in
//                     from that end, whose last layer is that layer's rounding;
//                     both where a printer draws the wall: a wall region less
//                     than a layer tall is not sampled (it is one layer's
//                     step), and the sample is kept at least a layer from the
//                     region's lowest and highest points (the layer at a
//                     wall's end is that layer's rounding: the wedge under a
//                     tilted top's rim is thinner than any nozzle at its very
//                     edge, and a nozzle wide one layer down);
//   [base_thickness]  flat triangles (|n_z| >= 1/2), ray inwards: the vertical
//                     thickness (flat base under the lowest pillars, the mirrored
//                     slab); warns below two layers (2 * layer_mm);
//   [overhang]        triangles facing down more than 45 degrees from the
//                     vertical, off the bed (verify/overhang.h): supports needed;
//                     warns when there are any;
//   [fits_bed]        the bounding box fits the bed, as is or turned by 90
//                     degrees about z; warns otherwise. Skipped without a bed size.
// Each is a warning (status Warn) unless fail_on_warnings, then Fail. The ray
// checks need a closed, consistently oriented mesh (inside and outside must
// mean something); otherwise they are skipped.
// Units: millimetres.
#pragma once

#include <optional>
#include <vector>

#include "gen/geometry/mesh.h"
#include "verify/column_grid.h"
#include "verify/report.h"

namespace tsf {

inline constexpr double kDefaultNozzleMm = 0.4;
inline constexpr double kDefaultLayerMm = 0.2;

struct PrintabilityOptions {
    double nozzle_mm = kDefaultNozzleMm;
    double layer_mm = kDefaultLayerMm;
    std::optional<Vec3> bed_mm;   ///< printable volume (x, y, z); none = not checked
    bool fail_on_warnings = false;
    size_t max_offenders = 10;
};

struct PrintabilityResult {
    PrintabilityFigures figures;
    std::vector<Check> checks;  ///< "wall_thickness", "gap_width", "base_thickness", "overhang", "fits_bed"
    std::vector<Stage> stages;
};

/// `closed_oriented`: the solid checks found the mesh closed, manifold and
/// consistently oriented (see SolidResult); `caster` is built on `mesh`.
PrintabilityResult checkPrintability(const Mesh& mesh, bool closed_oriented, const ColumnGrid& caster,
                                     const PrintabilityOptions& options);

}  // namespace tsf
