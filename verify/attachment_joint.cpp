#include "verify/attachment_joint.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <optional>

#include "gen/field/hex_grid.h"
#include "gen/model/attachments.h"
#include "gen/model/joint_walls.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

std::string partName(const std::string& part) {
    if (part == "marks") return "the orientation tab";
    if (part == "legend") return "the braille legend's plate";
    if (part == "scale") return "the tactile scale";
    return "the " + part;
}

}  // namespace

std::vector<AttachmentJoint> attachmentJoints(const Scene& s, double push_N) {
    std::vector<AttachmentJoint> out;
    for (const Attachment& a : sceneAttachments(s, Assembly::OnePiece)) {
        if (a.joined.mesh.positions.empty()) continue;
        AttachmentJoint j;
        j.part = a.part;
        std::vector<JointWall> walls;
        for (const WallContact& w : a.walls) walls.push_back(jointWall(s, w));
        for (const RingContact& w : a.ring_walls)
            walls.push_back({s.planarPoint(w.from, 0), s.planarPoint(w.to, 0), s.zMm(w.bottom_units), s.zMm(w.top_units)});
        const JointLoad load = jointLoad(walls, meshBounds(a.joined.mesh), push_N);
        j.joint_length_mm = load.length_mm;
        j.joint_area_mm2 = load.area_mm2;
        j.push_at_mm = load.push_at_mm;
        j.lever_mm = load.lever_mm;
        j.stress_MPa = load.stress_MPa;
        out.push_back(j);
    }
    return out;
}
Check checkAttachmentJoints(const Scene& s, double push_N, double strength_MPa, size_t max_offenders) {
    Check c;
    c.id = "tactile_attachment_joints";
    c.title = "every attachment holds a hand's push at its far corner";
    c.unit = "MPa";
    c.stage = "tactile_marks";
    const std::vector<AttachmentJoint> joints = attachmentJoints(s, push_N);
    if (joints.empty()) {
        c.status = CheckStatus::Skipped;
        c.note = "no tab, legend or scale beside the pillars";
        return c;
    }
    std::string facts;
    for (const AttachmentJoint& j : joints) {
        const std::string stress = std::isfinite(j.stress_MPa) ? formatSignificant(j.stress_MPa, 3) + " MPa" : "nothing holds it";
        facts += (facts.empty() ? "" : "; ") + partName(j.part) + " joined along " + formatFixed(j.joint_length_mm, 1) +
                 " mm (" + formatFixed(j.joint_area_mm2, 1) + " mm^2), " + stress + " at " + formatFixed(j.lever_mm, 0) + " mm";
        if (j.stress_MPa <= strength_MPa) continue;
        ++c.count;
        c.worst.push_back({j.push_at_mm, std::isfinite(j.stress_MPa) ? j.stress_MPa : std::nan(""),
                           partName(j.part) + " is joined to the pillars along " + formatFixed(j.joint_length_mm, 1) +
                               " mm of wall; a " + formatSignificant(push_N, 3) + " N push on its corner at (" +
                               formatFixed(j.push_at_mm.x, 1) + ", " + formatFixed(j.push_at_mm.y, 1) + ") mm, " +
                               formatFixed(j.lever_mm, 0) + " mm away, loads the joint to " + stress + ", more than the " +
                               formatSignificant(strength_MPa, 3) + " MPa printed PLA holds: it may snap off"});
    }
    // Worst first; an attachment nothing holds before all.
    const auto key = [](const Offender& o) { return std::isnan(o.amount) ? std::numeric_limits<double>::infinity() : o.amount; };
    std::stable_sort(c.worst.begin(), c.worst.end(), [&](const Offender& a, const Offender& b) { return key(a) > key(b); });
    if (c.worst.size() > max_offenders) c.worst.resize(max_offenders);
    // A warning, as the height steps are: the model is a valid print, and
    // the joint's model is a simple one (verify/attachment_joint.h).
    c.status = c.count ? CheckStatus::Warn : CheckStatus::Pass;
    c.note = facts + " (a " + formatSignificant(push_N, 3) + " N push at the far corner; at most " +
             formatSignificant(strength_MPa, 3) + " MPa)";
    return c;
}

}  // namespace tsf
