// The wall an attachment stands against, as a piece of its joint: what the
// tab's placement (gen/model/features/tab/orientation_tab.cpp) and the
// verifier's joint check (verify/attachment_joint.h) both measure.
#pragma once

#include "gen/geometry/joint_stress.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// The pillar wall of `w` (its hexagon edge, plan, mm) over the z span both
/// the pillar (at the edge's two corners) and the attachment's band hold.
JointWall jointWall(const Scene& scene, const WallContact& w);

}  // namespace tsf
