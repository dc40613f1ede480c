// TriangleBvh: a bounding-volume hierarchy over a mesh's triangles, for the
// closest points of the agreement and halves checks; its first hits of rays
// and its pairs of overlapping boxes answer what the column grid
// (verify/column_grid.h, the checks' rays and the self-intersections' broad
// phase) answers, and the tests hold the two to each other.
//
// Build: axis-aligned boxes split by the surface-area heuristic over 16 bins
// of the box centres along their longest extent, so the long triangles of a
// flat bottom triangulated without interior vertices sit in small subtrees of
// their own instead of inflating the boxes of everything near them. Below
// depth 32 nodes are halved at the median instead: the heuristic can peel off
// one triangle at a time (600 boxes at x = 2^k), and halving bounds the depth
// by 32 + log2(triangles) <= 64, so the traversals' fixed stacks can never
// overflow. The two halves of the root are built on two threads when that
// pays (from 10 000 triangles). The build reads each triangle's box on a grid
// of 65 536 steps a side (16 bytes a triangle); the tree's own boxes come from
// the exact corners, padded by a few units in the last place and rounded
// outwards to floats (32-byte nodes), so that a box test never rejects what
// the exact triangle test would accept.
//
// Rays: nearest box first, and the watertight ray/triangle test of Woop,
// Benthin and Wald ("Watertight Ray/Triangle Intersection", JCGT 2013): the
// edge functions of a shared edge are computed the same way for both of its
// triangles, so their signs are exact negations and a ray through a shared
// edge or vertex meets at least one of the triangles there (the values read
// back cast rays exactly through the diagonals of the hexagonal tops). A ray
// lying in a triangle's plane does not hit that triangle (it meets the
// triangles around it instead); zero-area triangles are never hit. A hit on a
// face parallel to an axis plane reports that face's coordinate exactly.
//
// Closest points: Ericson's closest point on a triangle ("Real-Time Collision
// Detection", 5.1.5), in double precision (rounding of a few units in the last
// place, about 1e-14 mm on a 150 mm model). Zero-area triangles are searched
// like any other (their closest point is on the segment they collapse to).
//
// Triangles with an out-of-range index or a non-finite corner are left out.
// Units: millimetres, model frame. Direction vectors need not be unit length;
// distances are along the ray in millimetres. Queries are const and may run
// concurrently. The tree reads the mesh's positions and triangles in place
// (copies were 24 bytes a vertex and 12 a triangle, 320 MB on a 1000 x 1000
// model; reading the triangles through the mesh costs the rays about 5 %):
// the mesh must outlive the tree and not change while it lives; a temporary
// mesh is refused at compile time.
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <optional>

#include "gen/geometry/mesh.h"
#include "verify/ray_hit.h"

namespace tsf {

struct ClosestPoint {
    double distance_mm = 0;  ///< +inf when the tree is empty or the query is not finite
    Vec3 point_mm;           ///< the nearest point of the mesh
    int64_t triangle = -1;   ///< mesh triangle index holding it; -1 when none
};

class TriangleBvh {
public:
    explicit TriangleBvh(const Mesh& mesh);
    explicit TriangleBvh(Mesh&&) = delete;  ///< the tree reads the mesh in place: it must outlive the tree
    ~TriangleBvh();
    TriangleBvh(const TriangleBvh&) = delete;
    TriangleBvh& operator=(const TriangleBvh&) = delete;

    /// The nearest hit of the ray origin + s * direction, s >= 0, ignoring
    /// triangle `skip` (pass -1 to skip none) and anything farther than
    /// max_distance_mm. nullopt if nothing is hit, or the direction is zero or
    /// not finite.
    std::optional<RayHit> firstHit(const Vec3& origin, const Vec3& direction, int64_t skip = -1,
                                   double max_distance_mm = std::numeric_limits<double>::infinity()) const;

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

    /// Calls visit(worker, a, b) once for every unordered pair of distinct
    /// triangles in the tree (mesh indices a != b, in either order) whose
    /// closed bounding boxes overlap (touching counts): every pair that
    /// touches or intersects is among them. Runs on up to `workers` threads (0: one per core); `worker`
    /// is the calling thread's number in [0, workers), so a visitor can keep
    /// its results per worker without locks. An exception thrown by `visit`
    /// stops the traversal and is rethrown here once every thread is done.
    void forEachOverlappingPair(const std::function<void(unsigned worker, uint32_t a, uint32_t b)>& visit,
                                unsigned workers = 0) const;
    /// The number of threads forEachOverlappingPair uses for `workers`.
    static unsigned workerCount(unsigned workers);

    size_t triangleCount() const;  ///< triangles in the tree
    int depth() const;             ///< levels below the root (<= 64)
    double buildMs() const;        ///< time spent building the tree

    struct Impl;  ///< defined in triangle_bvh.cpp

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tsf
