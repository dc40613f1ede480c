// Agreement: are two meshes the same solid?
//
// Compares the model with a reference (e.g. the OpenSCAD path's STL against
// the direct mesher's) by
//   - the Hausdorff distance in both directions (CGAL's
//     bounded_error_Hausdorff_distance: the figure is within error_bound_mm of
//     the true distance), and
//   - the difference of their volumes (divergence theorem).
// [reference_distance] passes iff both Hausdorff figures plus the error bound
// are within distance_tolerance_mm (so the true distance provably is).
// [reference_volume] passes iff |volume difference| <= area * distance
// tolerance: two closed surfaces within that distance of each other cannot
// differ by more than (about) a shell that thick.
// Units: millimetres. Meshes that CGAL cannot read as a polygon mesh are
// re-oriented on a copy first (noted).
#pragma once

#include <string>
#include <vector>

#include "gen/mesh.h"
#include "verify/report.h"

namespace tsf {

/// Default distance within which two meshes count as the same solid: the xy
/// grid step of every tsf model (1 um).
inline constexpr double kDefaultAgreementToleranceMm = 0.001;
/// Default Hausdorff error bound as a fraction of the tolerance: small enough
/// that a pass is decided by the distance, not by the bound.
inline constexpr double kHausdorffBoundFraction = 0.1;

struct AgreementOptions {
    double distance_tolerance_mm = kDefaultAgreementToleranceMm;
    double error_bound_mm = 0;  ///< 0 = distance_tolerance_mm * kHausdorffBoundFraction
    size_t max_offenders = 10;
};

struct AgreementResult {
    AgreementFigures figures;
    std::vector<Check> checks;  ///< "reference_distance", "reference_volume"
    std::vector<Stage> stages;
};

/// Compares `model` with `reference` (named `reference_name` in the report).
/// An empty mesh on either side fails both checks.
AgreementResult compareMeshes(const Mesh& model, const Mesh& reference, const std::string& reference_name,
                              const AgreementOptions& options);

}  // namespace tsf
