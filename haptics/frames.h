// Frames, units and the small vector type used by everything in haptics/.
//
// Units are SI throughout haptics/: metres, newtons, seconds, N/m, N*s/m.
//
// Device frame (the frame of every position read from and force written to a
// HapticDevice; the convention of libnifalcon):
//   x  to the user's right
//   y  up
//   z  toward the user (out of the device)
//   origin: the centre of the device's workspace (a driver subtracts its
//   mechanical workspace origin before reporting positions).
//
// Field frame (the raster, see gen/field/raster.h and haptics/height_grid.h):
//   u  east  = increasing raster column   -> device +x
//   v  north = decreasing raster row      -> device -z (away from the user)
//   w  up    = increasing field value     -> device +y
// So a field lies on the desk like a map in front of the user: north edge
// far away, south edge near the user, high values up. The mapping from field
// to device is fixed for a session (haptics/field_mapping.h).
#pragma once

#include <glm/vec3.hpp>

namespace tsf::haptics {

/// A point or vector in the device frame, metres or newtons.
using Vec3 = glm::dvec3;

/// Axis-aligned box in the device frame, metres. Valid when min_m < max_m on
/// every axis.
struct WorkspaceBox {
    Vec3 min_m{0.0};
    Vec3 max_m{0.0};
};

}  // namespace tsf::haptics
