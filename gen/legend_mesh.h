// meshLegendPlate: the braille legend as a closed solid: a plate with the
// legend's domed dots standing on its top, every dot's base sharing its
// vertices with the plate's top (one piece, no T-junctions).
//
// Frame: the legend's (legend.h): the plate spans [0, width] x [0, depth] x
// [0, plate_height] mm; dots stand on z = plate_height.
//
// Construction (topology from indices, never welded): the top is cut into a
// grid of rectangles by lines halfway between neighbouring dot rows and
// columns, so each rectangle holds at most one dot; a rectangle with a dot
// is triangulated around the dot's base octagon (vertices at 0, 45, ..., 315
// degrees: each rectangle corner joins the three base vertices of its
// quadrant), the others as two triangles. The bottom uses the same grid;
// the four sides join top and bottom at every grid line. A dot is a
// low-poly spherical cap: the base octagon (diameter dot_base_mm),
// kDomeRings smaller octagons on the sphere, and an apex dot_height_mm above
// the plate. Positions are rounded to 1 um.
#pragma once

#include "gen/legend.h"
#include "gen/mesh.h"

namespace tsf {

/// Octagons above the base of a dome, before the apex.
inline constexpr int kDomeRings = 2;
/// Corners of a dome's base and rings.
inline constexpr int kDomeSides = 8;

/// The plate and its dots as one closed, outward-facing, 2-manifold mesh.
/// plate_height_mm > 0. An empty layout gives an empty mesh.
Mesh meshLegendPlate(const LegendLayout& layout, double plate_height_mm);

}  // namespace tsf
