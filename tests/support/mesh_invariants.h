// Mesh invariants checked without any of the mesher's logic: only the
// indexed triangles and positions are read.
#pragma once

#include <string>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf::test {

struct Invariants {
    size_t vertices = 0, edges = 0, faces = 0;
    long euler = 0;                  ///< V - E + F; 2 for a sphere-like solid
    size_t components = 0;           ///< connected components of triangles (via shared edges)
    size_t unpaired_edges = 0;       ///< directed edges without their reverse (open or T-junction)
    size_t repeated_edges = 0;       ///< a directed edge used twice (non-manifold or flipped face)
    size_t nonmanifold_vertices = 0; ///< vertices whose faces do not form one fan
    size_t degenerate_faces = 0;     ///< repeated index, or area below kMinArea
    size_t duplicate_positions = 0;  ///< two vertex indices at the same point (should be one vertex)
    size_t unused_vertices = 0;
    double volume = 0;               ///< signed, mm^3

    bool closedManifold() const {
        return unpaired_edges == 0 && repeated_edges == 0 && nonmanifold_vertices == 0 && degenerate_faces == 0 &&
               duplicate_positions == 0 && unused_vertices == 0;
    }
    std::string describe() const;
};

/// Area (mm^2) under which a triangle counts as degenerate: far below one
/// snap step squared (1 um x 1 um = 1e-6 mm^2).
inline constexpr double kMinArea = 1e-9;

Invariants checkInvariants(const Mesh& mesh);

}  // namespace tsf::test
