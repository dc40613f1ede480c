// Exact convex hull of lattice points, and point-in-hull tests.
//
// Works on integer lattice coordinates (gen/field/hex_grid.h), so every predicate
// is exact: convexity and containment are invariant under the lattice's
// linear map to millimetres.
#pragma once

#include <span>
#include <vector>

#include "gen/field/hex_grid.h"

namespace tsf {

/// Convex hull, counter-clockwise, no repeated or collinear points (Andrew's
/// monotone chain). 0 points -> empty; all points equal -> 1 point; all
/// collinear -> the 2 extreme points.
std::vector<LatticePoint> convexHull(std::span<const LatticePoint> points);

/// True if p lies inside or on the boundary of the hull (1, 2 or more points).
bool hullContains(std::span<const LatticePoint> hull, const LatticePoint& p);

/// Euclidean distance in units of the pitch from p to the hull (0 inside).
double hullDistancePitch(std::span<const LatticePoint> hull, const LatticePoint& p);

}  // namespace tsf
