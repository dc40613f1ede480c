// The strength of an attachment's joint (verify/attachment_joint.h): one
// wall against the closed form worked out here by hand, the rules a joint
// must follow (longer holds more, a farther push loads more, twice the push
// twice the stress), and the attachments of real Scenes: a legend plate
// along a whole row of pillars holds, the tab holds, a scale stepped back
// from a spur holds, and the check reads them in tsf verify --tactile.
#include <gtest/gtest.h>

#include <cmath>

#include <nlohmann/json.hpp>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/build_scene.h"
#include "gen/model/features/legend/legend_join.h"
#include "gen/model/features/scale.h"
#include "gen/model/features/tab/tab_state.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "tests/support/mesh_invariants.h"
#include "tests/support/run.h"
#include "verify/attachment_joint.h"
#include "verify/tactile.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

// A wall along y at x = 0, from y = -L/2 to L/2, z from 0 to h.
JointWall wallAlongY(double len, double h) { return {{0, -len / 2, 0}, {0, len / 2, 0}, 0, h}; }

TEST(JointStress, OneWallAgreesWithTheClosedForm) {
    // About the wall's centre O = (0, 0, h/2), with u along the wall and w up:
    // K = diag(A (L^2 + h^2) / 12, A h^2 / 12, A L^2 / 12) (no products: the
    // rectangle is symmetric). A push F down at (X, Y) turns it by
    // theta = (-F Y / Kxx, F X / Kyy, 0); the traction at (0, u, w) is
    // theta x d = (theta_y w, -theta_x w, theta_x u), plus -F/A in z, largest
    // at a corner: sqrt((theta_x^2 + theta_y^2) h^2/4 + (|theta_x| L/2 + F/A)^2).
    const double len = 10, h = 2, f = 10, x = 30, y = 20;
    const double a = len * h;
    const double kxx = a * (len * len + h * h) / 12, kyy = a * h * h / 12;
    const double tx = -f * y / kxx, ty = f * x / kyy;
    const double expected = std::sqrt((tx * tx + ty * ty) * h * h / 4 + std::pow(std::fabs(tx) * len / 2 + f / a, 2));
    EXPECT_NEAR(jointStressMpa({wallAlongY(len, h)}, {x, y, h}, f), expected, 1e-9 * expected);
    // Pushed right above the wall's middle: the push spread evenly.
    EXPECT_NEAR(jointStressMpa({wallAlongY(len, h)}, {0, 0, h}, f), f / a, 1e-12);
}

TEST(JointStress, FollowsTheRulesOfAJoint) {
    const Vec3 corner{25, 15, 2};
    const double base = jointStressMpa({wallAlongY(10, 2)}, corner, 10);
    EXPECT_GT(base, 0);
    // Twice the push, twice the stress.
    EXPECT_NEAR(jointStressMpa({wallAlongY(10, 2)}, corner, 20), 2 * base, 1e-9 * base);
    // A longer or taller joint holds more; a farther push loads it more.
    EXPECT_LT(jointStressMpa({wallAlongY(20, 2)}, corner, 10), base);
    EXPECT_LT(jointStressMpa({wallAlongY(10, 4)}, corner, 10), base);
    EXPECT_GT(jointStressMpa({wallAlongY(10, 2)}, {50, 15, 2}, 10), base);
    // A second wall beside it (a joint of two) holds more than either.
    JointWall other = wallAlongY(10, 2);
    other.a.x = other.b.x = -3;
    EXPECT_LT(jointStressMpa({wallAlongY(10, 2), other}, corner, 10), base);
    // Nothing joins it: nothing holds it.
    EXPECT_TRUE(std::isinf(jointStressMpa({}, corner, 10)));
    EXPECT_TRUE(std::isinf(jointStressMpa({wallAlongY(10, 0)}, corner, 10)));
}

SceneParams extrasParams() {
    SceneParams p = test::smallParams();
    p.pitch_mm = 3.0;
    p.max_height_mm = 20.0;
    p.marks = MarkParams{};  // the orientation tab, as tsf gen makes it
    p.words.title = "Rain";
    p.words.units = "mm";
    p.requests.set(ScaleRequest{});
    return p;
}

const AttachmentJoint* jointOf(const std::vector<AttachmentJoint>& joints, const std::string& part) {
    for (const AttachmentJoint& j : joints)
        if (j.part == part) return &j;
    return nullptr;
}

TEST(AttachmentJoints, TheExtrasOfARegularGridHoldAHandsPush) {
    const Scene s = buildScene(test::fieldFromFunction(40, 30, [](int c, int r) { return 1.0 + (c * 7 + r * 3) % 11; }),
                               extrasParams());
    ASSERT_TRUE(sceneLegend(s) && sceneScale(s) && sceneTab(s));
    const std::vector<AttachmentJoint> joints = attachmentJoints(s, kHandPushN);
    ASSERT_EQ(joints.size(), 3u);
    for (const AttachmentJoint& j : joints) {
        EXPECT_LE(j.stress_MPa, kPrintedPlaInterlayerMpa) << j.part;
        EXPECT_GT(j.joint_area_mm2, 0) << j.part;
    }
    // The plate stands against the tops of the whole northern row: its joint
    // (the zigzag of hexagon walls) is longer than the plate is wide.
    const AttachmentJoint* plate = jointOf(joints, "legend");
    ASSERT_NE(plate, nullptr);
    EXPECT_GE(plate->joint_length_mm, sceneLegend(s)->plate_east_mm);
    const Check c = checkAttachmentJoints(s, kHandPushN, kPrintedPlaInterlayerMpa, 10);
    EXPECT_EQ(c.status, CheckStatus::Pass) << c.note;
    EXPECT_EQ(c.count, 0);
    // A push ten times a hand's breaks what a hand's does not.
    const Check hard = checkAttachmentJoints(s, 100 * kHandPushN, kPrintedPlaInterlayerMpa, 10);
    EXPECT_EQ(hard.status, CheckStatus::Warn) << hard.note;
    EXPECT_EQ(hard.count, 3);
    ASSERT_FALSE(hard.worst.empty());
    EXPECT_NE(hard.worst[0].detail.find("may snap off"), std::string::npos) << hard.worst[0].detail;
}

TEST(AttachmentJoints, NoAttachmentsNoCheck) {
    SceneParams p = test::smallParams();
    const Scene s = buildScene(test::fieldFromFunction(6, 6, [](int c, int r) { return 1.0 + c + r; }), p);
    EXPECT_TRUE(attachmentJoints(s, kHandPushN).empty());
    EXPECT_EQ(checkAttachmentJoints(s, kHandPushN, kPrintedPlaInterlayerMpa, 10).status, CheckStatus::Skipped);
}

// A scale on the east side of an outline with a one-row spur: the foot
// steps back to the run of rows west of it (gen/model/features/scale.h) and
// its joint holds; alone against the spur it would stand on one wall.
TEST(AttachmentJoints, TheScaleBesideASpurHolds) {
    const HexField f = test::fieldFromFunction(30, 30, [](int c, int r) {
        if (c == 29) return r == 14 || r == 15 ? 6.0 : test::kNaN;
        return 1.0 + (c + r) % 9;
    });
    SceneParams p = extrasParams();
    p.words = ModelWords{};
    const Scene s = buildScene(f, p);
    ASSERT_TRUE(sceneScale(s));
    EXPECT_GE(sceneScale(s)->contacts.size(), 3u);
    const AttachmentJoint* scale = jointOf(attachmentJoints(s, kHandPushN), "scale");
    ASSERT_NE(scale, nullptr);
    EXPECT_LE(scale->stress_MPa, kPrintedPlaInterlayerMpa);
    // The same scale joined to one of its walls only would not hold.
    const Vec3 a = s.point(hexCorner(s.grid, s.col[size_t(sceneScale(s)->contacts[0])], s.row[size_t(sceneScale(s)->contacts[0])], 0), 0);
    const Vec3 b = s.point(hexCorner(s.grid, s.col[size_t(sceneScale(s)->contacts[0])], s.row[size_t(sceneScale(s)->contacts[0])], 1), 0);
    EXPECT_GT(jointStressMpa({{a, b, 0, s.zMm(s.floor_units)}}, scale->push_at_mm, kHandPushN), kPrintedPlaInterlayerMpa);
}

// A projected map's outline: the northern corners cut away on the
// diagonal, and cells without data (pits) in the first rows. The plate no
// longer stops at the first row with a pit, joined by a corner: it reaches
// south until it stands against pillars along most of its width, stands
// around the pits (they stay pits), and the model stays one closed solid.
TEST(AttachmentJoints, ThePlateOfAnIrregularOutlineHoldsAlongMostOfItsWidth) {
    const HexField f = test::fieldFromFunction(40, 30, [](int c, int r) {
        if (c < 12 - r || c > 27 + r) return test::kNaN;      // the cut corners
        if (r <= 3 && c % 7 == 3) return test::kNaN;          // pits in the first rows
        return 1.0 + (c * 5 + r * 3) % 9;
    });
    SceneParams p = extrasParams();
    p.requests.reset<ScaleRequest>();
    const Scene s = buildScene(f, p);
    ASSERT_TRUE(sceneLegend(s) != nullptr);
    ASSERT_GT(s.cells_nodata_kept, 0);
    const AttachmentJoint* plate = jointOf(attachmentJoints(s, kHandPushN), "legend");
    ASSERT_NE(plate, nullptr);
    EXPECT_LE(plate->stress_MPa, kPrintedPlaInterlayerMpa);
    EXPECT_GE(plate->joint_length_mm, 0.6 * sceneLegend(s)->plate_east_mm);
    // Every cell, each pit included, reads back at its height: the plate
    // stands around the pits, never over them.
    const Mesh m = meshScene(s);
    const VerifyReport report = verifyModel(m, &s, VerifyOptions{});
    const Check* cells = report.find("values_read_back");
    ASSERT_NE(cells, nullptr);
    EXPECT_EQ(cells->status, CheckStatus::Pass) << cells->note;
    const test::Invariants inv = test::checkInvariants(m);
    EXPECT_TRUE(inv.closedManifold()) << inv.describe();
    EXPECT_EQ(inv.components, 1u);
    EXPECT_EQ(inv.duplicate_positions, 0u);
}

TEST(AttachmentJointsCli, VerifyTactileReportsEveryJoint) {
    const auto dir = test::scratchDir();
    std::string csv;
    for (int r = 0; r < 30; ++r) {
        for (int c = 0; c < 40; ++c) csv += (c ? "," : "") + std::to_string(1 + (c * 7 + r * 3) % 11);
        csv += "\n";
    }
    test::writeText(dir / "grid.csv", csv);
    const std::string model = (dir / "grid.stl").string();
    const auto g = test::runTsf("gen " + (dir / "grid.csv").string() + " --title Rain --units mm --scale -o " + model, dir);
    ASSERT_EQ(g.exit_code, test::kExitOk) << g.output;
    const auto v = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile --json", dir);
    const nlohmann::json j = nlohmann::json::parse(v.out, nullptr, false);
    ASSERT_FALSE(j.is_discarded()) << v.output;
    bool found = false;
    for (const auto& c : j["checks"])
        if (c["id"] == "tactile_attachment_joints") {
            found = true;
            EXPECT_EQ(c["status"], "pass") << c.dump();
            const std::string note = c["note"].get<std::string>();
            for (const char* what : {"the orientation tab", "the braille legend's plate", "the tactile scale"})
                EXPECT_NE(note.find(what), std::string::npos) << what << ": " << note;
        }
    EXPECT_TRUE(found) << v.out;
    const auto text = test::runTsf("verify " + model + " --scene " + model + ".scene.json --tactile", dir);
    EXPECT_NE(text.output.find("every attachment holds a hand's push at its far corner"), std::string::npos) << text.output;
}

}  // namespace
}  // namespace tsf
