// The ring of a round hole into the flat bottom (a half's pin hole, a
// tile's code pit): a kHoleSides-gon in lattice coordinates.
#pragma once

#include <vector>

#include "gen/model/scene.h"

namespace tsf {

/// kHoleSides points counter-clockwise from above, `vertex_radius_mm` from
/// `centre` in mm however the lattice is stretched (Scene::point snaps them
/// to the 1 um grid).
std::vector<PlanarPoint> bottomHoleRing(const Scene& scene, const LatticePoint& centre, double vertex_radius_mm);

}  // namespace tsf
