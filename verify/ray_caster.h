// RayCaster: first hit of a ray on a triangle mesh.
//
// A bounding-volume hierarchy of axis-aligned boxes (an AABB tree) over the
// triangles, traversed nearest box first, with the watertight ray/triangle
// test of Woop, Benthin and Wald ("Watertight Ray/Triangle Intersection",
// JCGT 2013): the edge functions are computed from the shared vertices in the
// same way for both triangles of an edge, so their signs are exact negations
// of each other and a ray through a shared edge or vertex meets at least one
// of the triangles there. That matters for the values read back, whose rays
// pass exactly through the diagonals of the hexagonal tops. Boxes are padded
// by a few units in the last place so the box test never rejects a ray the
// triangle test would accept.
//
// A ray lying in a triangle's plane does not hit that triangle (it meets the
// triangles around it instead). Triangles with an out-of-range index or a
// non-finite corner are left out; zero-area triangles are never hit.
//
// Units: millimetres, model frame. Direction vectors need not be unit length;
// distances are along the ray in millimetres. Queries are const and may run
// concurrently.
#pragma once

#include <cstdint>
#include <limits>
#include <memory>
#include <optional>

#include "gen/mesh.h"

namespace tsf {

struct RayHit {
    double distance_mm = 0;  ///< from the origin to the hit
    Vec3 point_mm;           ///< the hit
    uint32_t triangle = 0;   ///< mesh triangle index
};

class RayCaster {
public:
    /// Copies what it needs; `mesh` may be destroyed afterwards.
    explicit RayCaster(const Mesh& mesh);
    ~RayCaster();
    RayCaster(const RayCaster&) = delete;
    RayCaster& operator=(const RayCaster&) = delete;

    /// The nearest hit of the ray origin + s * direction, s >= 0, ignoring
    /// triangle `skip` (pass -1 to skip none) and anything farther than
    /// max_distance_mm. nullopt if nothing is hit, or the direction is zero or
    /// not finite.
    std::optional<RayHit> firstHit(const Vec3& origin, const Vec3& direction, int64_t skip = -1,
                                   double max_distance_mm = std::numeric_limits<double>::infinity()) const;

    size_t triangleCount() const;  ///< triangles in the tree
    double buildMs() const;        ///< time spent building the tree

    struct Impl;  ///< defined in ray_caster.cpp

private:
    std::unique_ptr<Impl> impl_;
};

}  // namespace tsf
