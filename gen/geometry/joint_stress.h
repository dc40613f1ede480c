// The stress on the joint of something that stands against the pillars
// (the orientation tab, the braille legend's plate, the tactile scale) when
// a hand leans on its far corner: tsf gen uses it to place the tab where it
// holds, tsf verify --tactile to check every attachment
// (verify/attachment_joint.h, docs/tactile.md "tactile_attachment_joints").
//
// Model (a rigid body on an elastic joint, the bolt-group method of
// structural design carried to a surface):
//   - the JOINT is where the attachment stands against the pillars: each
//     covered hexagon wall over the z span both hold, a vertical rectangle;
//   - the PUSH is push_N straight down on the attachment's top at the corner
//     of its x, y box farthest from the joint's centroid O;
//   - the attachment turns as a rigid body about O against the joint,
//     which answers each point's displacement with a proportional
//     traction, the same across and along the joint: the moment
//     M = (P - O) x F turns it by K^-1 M, K = integral (|d|^2 I - d d^T) dA
//     the joint's second moment tensor about O (d = point - O), and a
//     point carries |K^-1 M x d| plus the push spread evenly, F / A (K is
//     exact for rectangles; the traction is affine over each, so its
//     largest size is at a corner of one);
//   - it holds when the largest traction is at most strength_MPa.
// Assumptions: the attachment does not bend and the pillars do not give (a
// real plate loads the part of a long joint near the push more than the
// far part, so a long joint is judged kinder than it is); the joint is as
// strong as printed PLA across its layers, the low end of the measured
// strengths (the seam between the attachment's perimeters and a pillar's
// is a bond between roads laid side by side, as weak as one between
// layers, and the bending stress crosses it); the push is a hand leaning on
// the corner (kHandPushN, verify/tactile.h). The stress is linear in the
// push: twice the push, twice the stress.
//
// Units: mm, N, MPa (N/mm^2); model frame (gen/model/scene.h).
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

/// A push at a pillar's top (N) it must stand: a hand leaning on the model,
/// several times the 0.5-2 N of exploring touch.
inline constexpr double kHandPushN = 10.0;
/// Strength of printed PLA across its layers (MPa = N/mm^2), where a pillar
/// pushed sideways breaks.
inline constexpr double kPrintedPlaInterlayerMpa = 20.0;

/// A piece of a joint: the wall from a to b (plan, mm; z ignored) over
/// z [z_lo_mm, z_hi_mm].
struct JointWall {
    Vec3 a, b;
    double z_lo_mm = 0, z_hi_mm = 0;
};

/// The largest traction (MPa) on a joint of `walls` under push_N straight
/// down at push_at_mm, as described above; infinite when the walls have no
/// area (nothing holds the push).
double jointStressMpa(const std::vector<JointWall>& walls, const Vec3& push_at_mm, double push_N);

/// A joint under a push at the far corner of what it holds.
struct JointLoad {
    double length_mm = 0;  ///< total length of the walls (in plan)
    double area_mm2 = 0;   ///< their area over the z span both hold
    Vec3 push_at_mm;       ///< the far corner, on the attachment's top
    double lever_mm = 0;   ///< from the joint's centroid to the push, in plan
    double stress_MPa = 0; ///< the largest traction on the joint (infinite when nothing joins it)
};

/// The joint of `walls` holding an attachment whose bounds are `box`,
/// pushed with push_N straight down at the corner of the box's top
/// farthest (in plan) from the joint's centroid.
JointLoad jointLoad(const std::vector<JointWall>& walls, const Bounds& box, double push_N);

}  // namespace tsf
