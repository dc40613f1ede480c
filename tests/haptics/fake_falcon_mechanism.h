// The fake Falcon's own mechanism: where the grip is for given thigh angles,
// what encoder counts the DSP reports, and what force the motors push with.
// Written from the published constants alone (R. E. Stamper's thesis as
// libnifalcon's FalconGeometry.h gives the Falcon's numbers) and on purpose
// NOT with the driver's functions (haptics/falcon/falcon_kinematics.h): a
// fake that computed its forces with the driver's own kinematics would let a
// wrong model (a swapped leg, a mirrored axis, a sign) pass every test.
//
// The formulation differs from the driver's too: each leg's thigh angle is
// the closed-form root of Stamper's half-angle quadratic, and the force the
// motors make is (d theta / d p)^T tau, from central differences of that
// inverse, with no Jacobian inverted.
//
// Frames: positions are in the DEVICE frame of haptics/frames.h (x right,
// y up, z toward the user, metres), the mechanism frame shifted by
// kFakeWorkspaceCentreZ_m along z (the centre of libnifalcon's test cube).
#pragma once

#include <array>
#include <cstdint>

#include "haptics/frames.h"

namespace tsf::haptics::testing {

/// Device-frame origin in Stamper's mechanism frame, metres.
inline constexpr double kFakeWorkspaceCentreZ_m = 0.125;
/// What the fake's motors take as one N m of thigh torque, derived here
/// from the raw observation alone, not from the driver's figure: Novint's
/// own driver (HDAL, as libnifalcon traced it) commanded about 700 units on
/// each motor for a 12.5 N push along -z at the workspace centre; the
/// thigh torque that push needs comes from this file's mechanism (virtual
/// work, dtheta/dp by central differences, the 3 x 3 system solved by
/// Cramer's rule). Computed once.
double fakeMotorUnitsPerNm() noexcept;

/// Thigh angles (radians) that put the grip at p (device frame); false when
/// a leg cannot reach it.
bool fakeThighAngles(const Vec3& p_device_m, std::array<double, 3>& theta) noexcept;

/// The encoder count the DSP reports for a thigh angle (320-slot wheel read
/// in quadrature on a 14.25 mm shaft driving a 110 mm arm; 35 degrees at
/// count 0), rounded as a counter is.
int16_t fakeEncoderCount(double theta_rad) noexcept;

/// The force (N, device frame) the motors push the grip at p with when
/// commanded `motor` (thigh torque -motor / fakeMotorUnitsPerNm() N m each).
/// Zero when p is out of reach.
Vec3 fakeMotorForce(const Vec3& p_device_m, const std::array<int16_t, 3>& motor) noexcept;

}  // namespace tsf::haptics::testing
