// RayHit: what the verifier's ray casters (verify/triangle_bvh.h,
// verify/column_grid.h) answer for a ray's first hit.
#pragma once

#include <cstdint>

#include "gen/geometry/mesh.h"

namespace tsf {

struct RayHit {
    double distance_mm = 0;  ///< from the origin to the hit
    Vec3 point_mm;           ///< the hit
    uint32_t triangle = 0;   ///< mesh triangle index
};

}  // namespace tsf
