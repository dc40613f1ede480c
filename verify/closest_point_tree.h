// ClosestPointTree: the point of a triangle mesh nearest to a query point.
//
// A bounding-volume hierarchy of axis-aligned boxes over the triangles (split
// by the surface-area heuristic, so the long triangles of a fan-triangulated
// flat bottom do not inflate every box near them), searched nearest box first
// and pruned by the squared distance to each box. The distance to one
// triangle is Ericson's closest-point-on-triangle ("Real-Time Collision
// Detection", 5.1.5), in double precision: its rounding is a few units in the
// last place of the coordinates (about 1e-14 mm on a 150 mm model).
//
// Zero-area triangles are searched like any other (their closest point is on
// the segment they collapse to). Triangles with an out-of-range index or a
// non-finite corner are left out.
//
// Units: millimetres, model frame. Queries are const and may run concurrently.
#pragma once

#include <cstdint>
#include <memory>

#include "gen/mesh.h"

namespace tsf {

struct ClosestPoint {
    double distance_mm = 0;  ///< +inf when the tree is empty or the query is not finite
    Vec3 point_mm;           ///< the nearest point of the mesh
    int64_t triangle = -1;   ///< mesh triangle index holding it; -1 when none
};

class ClosestPointTree {
public:
    /// Copies what it needs; `mesh` may be destroyed afterwards.
    explicit ClosestPointTree(const Mesh& mesh);
    ~ClosestPointTree();
    ClosestPointTree(const ClosestPointTree&) = delete;
    ClosestPointTree& operator=(const ClosestPointTree&) = delete;

    /// Nearest point of the mesh to `p`. `hint` (a mesh triangle index, or -1)
    /// is tried first: near the previous query's answer, it lets the search
    /// prune most of the tree at once. The answer does not depend on the hint
    /// (ties between triangles at the same distance may pick either).
    ///
    /// `enough_mm` > 0 stops the search at the first triangle found within
    /// that distance: the answer is then some point within enough_mm, not
    /// necessarily the nearest (its distance is an upper bound of the true
    /// one, and at most enough_mm). A search for the largest distance over many
    /// points passes the largest found so far: points nearer than that cannot
    /// change it, and most are settled by the first triangle tried.
    ClosestPoint closest(const Vec3& p, int64_t hint = -1, double enough_mm = 0) const;

    size_t triangleCount() const;

    struct Impl;  ///< defined in closest_point_tree.cpp

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tsf
