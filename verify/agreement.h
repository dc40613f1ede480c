// Agreement: are two meshes the same solid?
//
// Compares the model with a reference (e.g. the OpenSCAD path's STL against
// the direct mesher's), however each is triangulated, in three steps:
//   1. Exact comparison of the two surfaces (verify/surface_chains.h): plane
//      by plane, the boundaries of the two meshes' parts must cancel. Equal
//      means the same oriented surface, proven in integer arithmetic: the
//      Hausdorff distance is 0 (also when some planes coincide facing the
//      other way: an inside-out copy). Otherwise it names the planes where the
//      surfaces differ; every triangle in another plane lies on the other
//      surface (distance 0).
//      Where they differ, both meshes are rounded (to float32, then to the
//      coarsest power-of-two grid moving them by at most half the tolerance)
//      and compared again: a triangle whose rounded copy lies on the other
//      rounded surface is within delta of the other surface, delta = the
//      largest vertex move of both roundings, measured.
//   2. Distances where step 1 could not prove 0: the triangles in differing
//      planes (and zero-area ones) are sampled so that every point of them is
//      within r of a sample (verify/triangle_samples.h), and each sample's
//      distance to the other mesh is measured (verify/triangle_bvh.h).
//      The distance to a surface is 1-Lipschitz, so each direction's true
//      Hausdorff distance h satisfies  figure <= h <= figure + r,  with
//      figure = the largest sampled distance. r is the smallest radius whose
//      samples fit in the budget, but not below the finest radius asked for.
//      Every other vertex of both meshes is measured too, as a check on step
//      1's premise (see below).
//   3. The difference of the volumes (divergence theorem).
//
// [reference_distance] passes when both directions are proven within the
// tolerance (max(delta, figure + r) <= tolerance), fails when a sampled point is farther
// than the tolerance (a proven difference), and warns otherwise: within the
// tolerance where sampled, but the sampling budget did not give a radius small
// enough to prove it.
// [reference_volume] passes iff |volume difference| <= area * tolerance: two
// closed surfaces within that distance of each other cannot differ by more
// than (about) a shell that thick. It is what catches an inside-out copy (the
// same point set, so distance 0, with the opposite volume).
//
// Premise of step 1's "distance 0": neither mesh has triangles overlapping
// each other (a self-intersection; the model's own is checked by the solid
// checks). If a vertex of a triangle proven to lie on the other surface (or
// the centroid of one matched after rounding) is found off it by more than
// the finest sampling radius plus delta (rounding is ~1e-10 mm), the premise
// is broken, and that mesh is sampled everywhere (noted).
//
// Everything is bounded: step 1 is O(n log n); step 2 measures at most
// max(sample_budget, the vertices of the sampled triangles) samples, plus
// each other vertex once. No time limit is needed; times in
// docs/verifier.md. Units: millimetres.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "verify/report.h"

namespace tsf {

/// Default distance within which two meshes count as the same solid: the xy
/// grid step of every tsf model (1 um).
inline constexpr double kDefaultAgreementToleranceMm = 0.001;
/// Finest sampling radius as a fraction of the tolerance: small enough that
/// a pass is decided by the distance, not by the bound; finer would only cost
/// samples.
inline constexpr double kHausdorffBoundFraction = 0.1;
/// Default number of distance samples (both directions together) on the
/// triangles that the exact comparison could not place on the other surface:
/// about half a second of closest-point queries (docs/verifier.md).
inline constexpr size_t kDefaultAgreementSampleBudget = 1'000'000;

struct AgreementOptions {
    double distance_tolerance_mm = kDefaultAgreementToleranceMm;
    /// Finest sampling radius (the smallest Hausdorff error bound worth
    /// paying for); 0 = distance_tolerance_mm * kHausdorffBoundFraction.
    double error_bound_mm = 0;
    size_t sample_budget = kDefaultAgreementSampleBudget;
    size_t max_offenders = 10;
    bool fail_on_warnings = false;  ///< an unproven distance fails instead of warning (for --strict)
};

struct AgreementResult {
    AgreementFigures figures;
    std::vector<Check> checks;  ///< "reference_distance", "reference_volume"
    std::vector<Stage> stages;  ///< "reference_exact", "reference_distances"
};

/// Compares `model` with `reference` (named `reference_name` in the report).
/// An empty mesh or a non-finite coordinate on either side fails both checks.
/// A tolerance that is not a positive number (or a negative error bound) is a
/// tsf::InputError.
AgreementResult compareMeshes(const Mesh& model, const Mesh& reference, const std::string& reference_name,
                              const AgreementOptions& options);

}  // namespace tsf
