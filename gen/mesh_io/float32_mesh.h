// The mesh a float32 file holds: what STL and 3MF store and what tsf's own
// readers (and a slicer) read back from them. Every coordinate is rounded to
// the nearest float32; positions that became equal are one vertex (as the
// readers weld them, exactly, and numbered alike: mesh_io's weldExact).
// Triangles keep their order; one whose corners merged is kept, so a check
// sees it.
//
// Verifying this mesh, not the double-precision one it came from, is
// verifying what is written: rounding moves a vertex by up to 2^-24 of its
// coordinates, which can turn a sliver over (an exact union's leftover
// vertex 0.2 um from a grid point did, at x = 120 mm) or merge two vertices
// a few nanometres apart, while the double mesh is sound.
#pragma once

#include "gen/geometry/mesh.h"

namespace tsf {

/// `mesh` as a float32 file stores it and a reader reads it back.
Mesh float32Mesh(const Mesh& mesh);

}  // namespace tsf
