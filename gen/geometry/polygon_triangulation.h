// Triangulating a planar polygon with holes whose corners are mesh vertices.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

/// Triangles (counter-clockwise seen from +z) covering the region inside an
/// odd number of `rings` (an outline and its holes), using exactly the ring
/// vertices: each ring is a closed loop of indices into `positions`, whose x
/// and y are used. Rings must be simple and not cross each other (they may
/// hold collinear points). Exact predicates: a point on an edge stays on it.
std::vector<std::array<uint32_t, 3>> triangulateRings(const std::vector<Vec3>& positions,
                                                      const std::vector<std::vector<uint32_t>>& rings);

/// The same for a region given as directed or undirected segments (pairs of
/// indices into `positions`) that together form closed loops; loops may
/// touch at a vertex (a pinch), never cross. Each point must be one index.
std::vector<std::array<uint32_t, 3>> triangulateSegments(const std::vector<Vec3>& positions,
                                                         const std::vector<std::array<uint32_t, 2>>& segments);

}  // namespace tsf
