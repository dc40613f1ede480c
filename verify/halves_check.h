// The halves of a cut mirrored model (gen/model/features/halves.h) checked as a pair.
//
// Each half is checked alone by verifyModel (closed, manifold, outward, its
// heights read back against halfScene, no overhang as it prints). This file
// checks what only the pair shows:
//   [halves_one_way]  the hole centres admit no rotation or reflection onto
//                     themselves with the pins' play (isChiralLayout with a
//                     tolerance of 2 x kPinClearanceMm): they join one way;
//   [halves_volume]   volume(upper) + volume(lower) = volume(whole model) -
//                     2 x the holes' volume, the holes' volume computed from
//                     the Scene's rings (prism + cone), not from the meshes;
//   [halves_surface]  put back together (the upper half raised to the cut,
//                     the lower half turned back), every surface of the
//                     halves except the cut faces and the holes lies on the
//                     whole model's surface, and every point of the whole
//                     model's surface lies on one of the halves: sampled both
//                     ways (a covering of each triangle, radius a quarter of
//                     the pitch), within kHalvesSurfaceToleranceMm.
// The volumes and the two surface directions together say the joined pair is
// the whole model less the holes: same outer surface, same material.
// Units: millimetres.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/report.h"

namespace tsf {

/// Distance within which a reassembled half's surface is on the whole
/// model's: the 1 um grid, with room for the float sums of a reassembly.
inline constexpr double kHalvesSurfaceToleranceMm = 0.0011;

struct HalvesJoinFigures {
    double upper_volume_mm3 = 0, lower_volume_mm3 = 0, whole_volume_mm3 = 0;
    double holes_volume_mm3 = 0;     ///< both faces' holes, from the Scene
    double volume_error_mm3 = 0;     ///< upper + lower - (whole - holes)
    double max_distance_mm = 0;      ///< largest sampled distance, both ways
    size_t samples = 0;
};

struct HalvesCheckResult {
    HalvesJoinFigures figures;
    std::vector<Check> checks;  ///< "halves_one_way", "halves_volume", "halves_surface"
    bool passed() const;
};

/// Checks the printed halves (gen/mesh/halves_mesh.h meshHalf) of `scene` (with
/// halves) against `whole`, the whole model's mesh (meshScene(scene)).
HalvesCheckResult checkHalves(const Scene& scene, const Mesh& whole, const Mesh& upper, const Mesh& lower);

}  // namespace tsf
