// The strength of every attachment's joint: a hand that leans on the far
// corner of the orientation tab, the braille legend's plate or the tactile
// scale must not snap it off the pillars (tsf verify --tactile,
// docs/tactile.md "tactile_attachment_joints").
//
// The model of the joint and the push: gen/geometry/joint_stress.h.
//
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "gen/geometry/joint_stress.h"
#include "gen/geometry/mesh.h"
#include "verify/report.h"

namespace tsf {

struct Scene;

/// One attachment's joint under the push.
struct AttachmentJoint {
    std::string part;           ///< "marks" (the orientation tab), "legend", "scale"
    double joint_length_mm = 0; ///< total length of the pillar walls it stands against (in plan)
    double joint_area_mm2 = 0;  ///< the area of those walls over the z span both hold
    Vec3 push_at_mm;            ///< the far corner, on the attachment's top
    double lever_mm = 0;        ///< from the joint's centroid to the push, in plan
    double stress_MPa = 0;      ///< the largest traction on the joint (infinite when nothing joins it)
};

/// Every attachment of `scene` joined in one piece, in sceneAttachments'
/// order, under a push of push_N at its far corner.
std::vector<AttachmentJoint> attachmentJoints(const Scene& scene, double push_N);

/// The check tactile_attachment_joints: warns of each attachment whose
/// joint carries more than strength_MPa under push_N at its far corner (a
/// warning: the model is a valid print, and this is a simple model of the
/// joint). Skipped without attachments.
Check checkAttachmentJoints(const Scene& scene, double push_N, double strength_MPa, size_t max_offenders);

}  // namespace tsf
