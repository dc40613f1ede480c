// Tilt: a second statistic on each pillar top (thesis 3.3, eq. 3.1).
//
// Each data pillar's top becomes a plane through its centre at the cell's
// height, so the value still reads at the centre; its corners move
// vertically only (the top view stays hexagonal). Sources (docs/model.md):
//   - Points: the bin's regression plane (gen/field/bin_regression.h): for a count,
//     the least-squares linear density of its points, scaled so the plane is
//     at the top's height at the centre (slope = height x relative slope /
//     pitch); for a sum or mean of weights, the least-squares plane of the
//     weight on position, turned into mm by the value -> height mapping's
//     derivative at the cell's value (a sum: times the bin's point count).
//   - Gradient: the field's own gradient, the least-squares plane through the
//     cell's height and its neighbours' with data (all six: the mean of the
//     three central differences along the lattice's directions; at an edge or
//     beside cells without data, the neighbours there are; fewer than two
//     neighbours not on one line: level).
// The slope is multiplied by the steepness, then limited per cell (the
// clamp): no corner goes below the floor (every corner keeps the base under
// it, and a mirrored model's underside stays above z = 0), and no edge next to
// an orientation mark crosses the mark's top or bottom. Marked cells, cells
// without data and structural cells stay level.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/bin_regression.h"
#include "gen/model/scene.h"

namespace tsf {

/// Per kept cell of `scene` (cells, heights and marks set), the slope its top
/// should take, mm per mm (x east, y north), before the steepness and the
/// clamp; {0, 0} = level. Throws InputError for TiltSource::Points on a field
/// without point moments (a raster).
std::vector<PlaneSlope> tiltSlopes(const HexField& field, const Scene& scene, TiltSource source);

/// Fills scene.shapes: corner offsets of each tilted top (slopes times
/// `steepness`, clamped as the file comment says, rounded to the z grid),
/// the dimple of each structural cell (structural: per kept cell), the
/// mirrored thickness grown to cover the corners' steps, then the crossings
/// (buildTopShapeGeometry). Adds a note when tilts were clamped.
/// `centre_dz` (empty, or per kept cell, z units) raises or lowers the
/// centre of a data cell's top (a class texture's bump or dimple; mirrored,
/// its bottom's centre the same, so the slab keeps its thickness).
void resolveTopShapes(Scene& scene, const std::vector<PlaneSlope>& slopes, double steepness,
                      const std::vector<uint8_t>& structural, const std::vector<int32_t>& centre_dz = {});

}  // namespace tsf
