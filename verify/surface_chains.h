// Exact comparison of two triangle surfaces, however each is triangulated.
//
// A mesh's surface, as an oriented surface, is the sum of its triangles, each
// oriented by its corner order (a 2-chain). Two meshes bound the same solid
// with the same surface exactly when their chains are equal. This is decided
// without constructing anything:
//   - the part of a chain lying in one plane is a planar 2-chain, and a planar
//     2-chain is determined by its boundary (its multiplicity at a point is
//     the winding number of the boundary around it), so the chains are equal
//     iff, plane by plane, the boundaries of their parts are equal;
//   - the boundary of a plane's part is the sum of its triangles' directed
//     edges (shared edges cancel), and a sum of directed segments on one line
//     is zero iff its multiplicity jumps by zero at every segment end: each
//     directed edge p -> q adds +1 at p and -1 at q (the model's edges count
//     +, the reference's -), and every (plane, line, point) must sum to zero.
//     With the reference's edges counted + as well, the sums vanish when the
//     two parts are the same region facing opposite ways (an inside-out copy).
// Planes and lines are identified exactly: the coordinates of both meshes are
// scaled by one power of two to integers (exact), a plane is its primitive
// integer normal (first non-zero component positive) and offset, a line its
// primitive direction and Pluecker moment, a point on a line one integer
// coordinate. No tolerance is involved: a vertex moved by one unit in the last
// place is a difference.
//
// What equal chains prove: every point where one surface has non-zero
// multiplicity lies on the other, so both volumes are equal and, for meshes
// whose triangles do not overlap each other (no self-intersection; the model's
// is checked by the solid checks), the two surfaces are the same point set:
// Hausdorff distance 0. A zero-area triangle has no plane; it is reported as
// differing, for the caller to measure.
//
// What unequal chains give: the planes holding a difference, so a caller can
// measure distances only on the triangles in those planes (every other
// triangle lies on the other surface, facing the same way or, in an
// "opposite" plane, the other way).
//
// Triangles with an out-of-range index or a repeated index are ignored. The
// comparison needs the coordinates of both meshes on one integer grid of at
// most 125 bits (practically any binary STL; double coordinates spanning less
// than about 2^70 between the largest and the finest bit); otherwise, or with
// a non-finite coordinate, `compared` is false. Up to 61 bits (a binary STL
// whose smallest non-zero coordinate is above ~1e-10 of its largest) it runs
// in 64/128/256-bit arithmetic, beyond in 128/256/512-bit.
//
// Cost: O(n log n) in the triangles of both meshes; on the 100 x 100 model
// (135 k + 180 k triangles) about 0.2 s (docs/verifier.md).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

struct ChainComparison {
    bool compared = false;     ///< false: could not put the coordinates on one grid (`note` says why)
    std::string note;          ///< why not compared
    int grid_bits = 0;         ///< bits of the integer grid used (<= 61: 64-bit arithmetic; <= 125: 256/512-bit)
    size_t planes = 0;         ///< distinct planes holding triangles of either mesh
    size_t differing_planes = 0;   ///< planes where the two parts are different regions
    size_t opposite_planes = 0;    ///< planes where they are the same region facing opposite ways
    /// Per triangle of the model / the reference: 1 when it lies in a
    /// differing plane, or has no area; 0 when it lies on the other surface
    /// (in a same or opposite plane); 0 for ignored (invalid) triangles. All
    /// 1 when not compared.
    std::vector<uint8_t> model_differs, reference_differs;
    /// Places (mm) where the boundaries differ: segment ends with a non-zero
    /// sum in a differing plane, at most `max_points`, and how many there were.
    std::vector<Vec3> difference_points;
    size_t difference_point_count = 0;

    /// Both surfaces are proven equal, facing the same way.
    bool identical() const { return compared && differing_planes == 0 && opposite_planes == 0; }
    /// Both surfaces are proven the same point set, some parts possibly facing the other way.
    bool samePointSet() const { return compared && differing_planes == 0; }
};

/// Compares the surfaces of `model` and `reference` exactly (see above).
ChainComparison compareSurfaceChains(const Mesh& model, const Mesh& reference, size_t max_points);

}  // namespace tsf
