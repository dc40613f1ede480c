// Novint Falcon kinematics: encoder counts -> thigh angles -> probe position,
// and a force at the probe -> motor commands. Pure functions, noexcept, no
// allocation (the haptic tick calls them).
//
// Model: the Falcon is a three-legged parallel (delta-like) mechanism. After
// R. E. Stamper's thesis (Univ. of Maryland, 1997) as libnifalcon applies it,
// with libnifalcon's published geometry (metres):
//   a = 0.060 thigh, b = 0.1025 parallelogram side, c = 0.01443,
//   d = e = 0.01125 joint offsets, f = -0.025, (r, s) = (0.040, -0.02309)
//   leg base offset, legs at phi = 105, -15, -135 degrees about z.
// Leg i sees the probe p (mechanism frame) in its own frame
//   u = cos(phi) p.x + sin(phi) p.y - r,  v = -sin(phi) p.x + cos(phi) p.y - s,  w = p.z
// and closes when (our formulation, one equation per leg)
//   g_i(p, theta_i) = |(u + c - a cos theta_i, w - a sin theta_i)| - (d + e + b sqrt(1 - ((v + f) / b)^2)) = 0
// i.e. the in-plane distance from the knee to the platform joint equals the
// in-plane reach of the parallelogram. theta_i is the thigh (motor) angle.
//
// Frames: the functions below take and return DEVICE-frame positions
// (frames.h: x right, y up, z toward the user, origin at the workspace
// centre). The mechanism frame is the device frame shifted by
// kFalconWorkspaceCentre_m, the centre of libnifalcon's test cube
// (x, y +-30 mm, z 95..155 mm).
//
// Encoders: 320 slots in quadrature (1280 counts per motor turn) on a
// 14.25 mm capstan driving a 110 mm arm sector: theta = counts * 2 pi /
// (1280 * 110 / 14.25) + 35 deg, about 0.0364 deg (38 um at the thigh's
// 60 mm) per count. Valid only once the device is homed.
//
// Forward kinematics is a Newton solve of g(p) = 0, warm-started from the
// previous position, converged to kFalconFkTolerance_m (a hundredth of the
// distance one encoder count moves the probe); it never returns garbage:
// see falconForwardKinematics.
//
// Forces: tau = J^T F with J = dp/dtheta (N m at each thigh), then motor
// units = -kFalconCountsPerNm * tau, the whole vector scaled down so the
// largest stays within the command limit (the force direction is kept).
// Nothing here was checked against a real Falcon; see docs/haptics.md.
#pragma once

#include <array>
#include <cstdint>

#include <glm/mat3x3.hpp>

#include "haptics/frames.h"

namespace tsf::haptics {

/// Thigh angles of legs 0, 1, 2 in radians.
using FalconAngles = std::array<double, 3>;

/// Device-frame origin in the mechanism frame (libnifalcon's), metres.
inline constexpr double kFalconWorkspaceCentreZ_m = 0.125;

/// Radians per encoder count and the angle at count 0.
inline constexpr double kFalconRadPerCount = 2.0 * 3.14159265358979323846 * 14.25 / (1280.0 * 110.0);
inline constexpr double kFalconAngleAtZero_rad = 35.0 * 3.14159265358979323846 / 180.0;

/// Probe travel per encoder count at the thigh's tip (a * rad per count),
/// about 38 um: the position resolution the solver's tolerance is tied to.
inline constexpr double kFalconMetresPerCount = 0.060 * kFalconRadPerCount;
/// Newton stops when a step and every leg's residual are below this: a
/// hundredth of a count, far below what the encoders can resolve.
inline constexpr double kFalconFkTolerance_m = 0.01 * kFalconMetresPerCount;

/// Motor units per N m of thigh torque. Derived from Novint's own driver
/// (HDAL) as traced by libnifalcon: -12.5 N along z at the workspace centre
/// gave about 700 units, and tau_z there is 0.0252 N m per N, so
/// 700 / (12.5 * 0.0252) = 2220. Novint's sideways traces command 1.7-1.9
/// times more than this gives (tests/haptics/falcon_force_trace_test.cpp,
/// docs/haptics.md); libnifalcon's own code uses 10000 (its comment calls
/// the scale "rather random"). The figure that never exceeds Novint's
/// driver is kept until it is measured on a device.
inline constexpr double kFalconCountsPerNm = 2220.0;
/// Largest motor command magnitude sent: where Novint's own driver stops
/// (libnifalcon's HDAL traces saturate at 4095; its header's 4096 is one
/// more than any trace shows).
inline constexpr int kFalconMaxMotorCommand = 4095;

double falconEncoderToAngle(int16_t counts) noexcept;
/// Inverse of falconEncoderToAngle, unrounded (fakes round it).
double falconAngleToEncoder(double angle_rad) noexcept;

/// Thigh angles that put the probe at p (device frame). False (out
/// untouched) when p is out of the legs' reach or not finite.
bool falconInverseKinematics(const Vec3& p_m, FalconAngles& out) noexcept;

struct FalconFkResult {
    Vec3 position_m{0.0};   ///< device frame; always finite
    int iterations = 0;     ///< Newton iterations used (both starts together)
    bool converged = false; ///< false: position_m is the fallback (see below)
    bool cold_start = false;///< the warm start failed and the centre start was used
};

/// Probe position for thigh angles. Newton on g(p) = 0 from `guess`
/// (the previous position), each step at most kFalconFkMaxStep_m long and
/// halved until it reduces the residual; converged when the step and every
/// |g_i| are below kFalconFkTolerance_m. If that fails (no convergence in
/// kFalconFkMaxIterations, a singular Jacobian, a result far outside the
/// workspace - the mechanism's other assembly mode), the solve is repeated
/// from the workspace centre; if that fails too, converged is false and
/// position_m is `guess` (clamped to 0.1 m of the centre, NaN -> centre),
/// so a caller never sees garbage.
FalconFkResult falconForwardKinematics(const FalconAngles& theta, const Vec3& guess_m) noexcept;

inline constexpr int kFalconFkMaxIterations = 20;
inline constexpr double kFalconFkMaxStep_m = 0.01;

/// J = dp/dtheta at a consistent (p, theta) pair: column i is the probe
/// velocity (m/rad) when thigh i turns. False when the legs are singular
/// there or the input is not finite.
bool falconJacobian(const Vec3& p_m, const FalconAngles& theta, glm::dmat3& J) noexcept;

struct FalconMotorOutput {
    std::array<int16_t, 3> command{0, 0, 0};
    bool limited = false;  ///< the vector was scaled down to the command limit
    bool valid = true;     ///< false: singular pose or non-finite input; command is zero
};

/// Motor commands for a force (N, device frame) at a consistent (p, theta):
/// -counts_per_Nm * J^T F, scaled as a whole so no |command| exceeds
/// max_command (direction kept).
FalconMotorOutput falconMotorCommands(const Vec3& p_m, const FalconAngles& theta, const Vec3& force_N,
                                      double counts_per_Nm = kFalconCountsPerNm,
                                      int max_command = kFalconMaxMotorCommand) noexcept;

/// The force (N, device frame) that motor commands produce at (p, theta):
/// the inverse of falconMotorCommands before limiting. For simulations of
/// the device; zero when singular.
Vec3 falconForceFromCommands(const Vec3& p_m, const FalconAngles& theta, const std::array<int16_t, 3>& command,
                             double counts_per_Nm = kFalconCountsPerNm) noexcept;

}  // namespace tsf::haptics
