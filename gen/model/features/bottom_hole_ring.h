// The ring of a round hole into the flat bottom (a half's pin hole, a
// tile's code pit): a kHoleSides-gon in lattice coordinates, and the
// material it takes away.
#pragma once

#include <vector>

#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// kHoleSides points counter-clockwise from above, `vertex_radius_mm` from
/// `centre` in mm however the lattice is stretched (Scene::point snaps them
/// to the 1 um grid).
std::vector<PlanarPoint> bottomHoleRing(const Scene& scene, const LatticePoint& centre, double vertex_radius_mm);

/// The volume of a cut into the bottom (its prism and cone), mm^3, from its
/// ring as the mesher places it (snapped): the material it takes away.
double bottomHoleVolumeMm3(const Scene& scene, const BottomHole& hole);

}  // namespace tsf
