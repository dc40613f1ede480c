// The braille legend on the model: where it goes (placeLegend, called by
// buildScene). How it joins the pillars is gen/mesh/legend_join.h.
//
// Placement (decided once, stored as Scene::legend): the legend stands on a
// plate grown NORTH of the pillars, away from the orientation notch at the
// south-west corner and clear of every pillar top. The plate spans the grid
// box's width (x from 0 to gridWidth), its top is the floor (the base's top,
// so it reads as "not data"). It reaches south, below the floor, over the
// cells culled at the model's northern corners, to the first row whose kept
// cells span 60 % of the columns (never over a whole row with a no-data pit),
// so it holds on along much of its length. Its south edge runs along the line
// through the upper side corners of that row, which meets hexagon walls only
// at their corners: every new edge of the union lies on lattice corners and
// the floor height, on the model's grid. Pillars under it keep their height
// (their tops are above the floor). The
// braille starts north of the hexagons' tips: the title on the first line,
// the value range of the data with its units on the next, lines broken to
// fit the model's width.
//
// Limits (InputError saying what to change): a mirrored model (no flat floor
// to stand the plate on), or a word wider than the model.
#pragma once

namespace tsf {

struct Scene;

/// Places the legend params.legend asks for (none when it asks for nothing).
void placeLegend(Scene& scene);

}  // namespace tsf
