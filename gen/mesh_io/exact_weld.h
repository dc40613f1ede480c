// weldExact: a whole list of positions given their exact vertex indices at
// once, on every core. The same numbering as inserting them one by one, in
// order, into an ExactVertexIndex (exact_vertex_index.h): equal positions
// (all three coordinates equal as doubles, -0.0 the same as +0.0) share an
// index, no others do, and the indices follow each position's first
// appearance. One by one, a position is a probe of a table larger than the
// caches (two misses each: at 1000 x 1000 about 2 s for the model rounded
// to float32); here the positions are first grouped by their hash into
// buckets that fit in a cache, and the buckets are welded on the threads.
#pragma once

#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf::mesh_io {

struct WeldedPositions {
    std::vector<Vec3> positions;     ///< each distinct position once, in order of first appearance (-0.0 as +0.0)
    std::vector<uint32_t> index_of;  ///< for each position given, its index in `positions`
};

/// Welds `points` (no NaN; fewer than 2^32 - 1). `workers` 0: one per core.
WeldedPositions weldExact(std::vector<Vec3> points, unsigned workers = 0);

}  // namespace tsf::mesh_io
