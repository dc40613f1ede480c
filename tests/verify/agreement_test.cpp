// Agreement with a reference mesh: the same solid passes however it is
// triangulated; a shift or a changed pillar fails, with the distance measured.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/verify/verify_test_support.h"
#include "verify/agreement.h"

namespace tsf {
namespace {

const Check& findCheck(const AgreementResult& r, const std::string& id) {
    for (const Check& c : r.checks)
        if (c.id == id) return c;
    ADD_FAILURE() << "no check " << id;
    return r.checks.front();
}

TEST(Agreement, SameSolidDifferentlyListedAndTriangulatedAgrees) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Mesh other = m.mesh;
    std::reverse(other.triangles.begin(), other.triangles.end());
    for (auto& t : other.triangles) std::rotate(t.begin(), t.begin() + 1, t.end());
    // Re-triangulate the first triangle around an extra centre vertex: the
    // surface is the same, its triangles are not.
    const auto t0 = other.triangles[0];
    const Vec3 c = vtest::centroid(other, 0);
    other.positions.push_back(c);
    const uint32_t ci = uint32_t(other.positions.size() - 1);
    other.triangles[0] = {t0[0], t0[1], ci};
    other.triangles.push_back({t0[1], t0[2], ci});
    other.triangles.push_back({t0[2], t0[0], ci});

    const AgreementResult r = compareMeshes(m.mesh, other, "retriangulated", {});
    EXPECT_EQ(findCheck(r, "reference_distance").status, CheckStatus::Pass) << findCheck(r, "reference_distance").note;
    EXPECT_EQ(findCheck(r, "reference_volume").status, CheckStatus::Pass);
    // Zero, up to the error bound CGAL guarantees.
    EXPECT_LE(r.figures.hausdorff_to_reference_mm, r.figures.hausdorff_error_bound_mm);
    EXPECT_LE(r.figures.hausdorff_from_reference_mm, r.figures.hausdorff_error_bound_mm);
    EXPECT_NEAR(r.figures.volume_difference_mm3, 0.0, 1e-9 * r.figures.volume_mm3);
}

TEST(Agreement, ShiftedCopyIsAsFarAsItWasMoved) {
    const Mesh a = vtest::box({0, 0, 0}, {10, 10, 10});
    const Mesh b = vtest::box({0.05, 0, 0}, {10.05, 10, 10});
    AgreementOptions o;
    o.distance_tolerance_mm = 0.01;
    const AgreementResult r = compareMeshes(a, b, "shifted", o);
    const double bound = r.figures.hausdorff_error_bound_mm;
    EXPECT_DOUBLE_EQ(bound, 0.001);
    EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.05, bound);
    EXPECT_NEAR(r.figures.hausdorff_from_reference_mm, 0.05, bound);
    EXPECT_EQ(findCheck(r, "reference_distance").status, CheckStatus::Fail);
    EXPECT_EQ(findCheck(r, "reference_distance").count, 2);  // both directions
    // Same volume: the volume check alone cannot tell a shifted copy.
    EXPECT_EQ(findCheck(r, "reference_volume").status, CheckStatus::Pass);
}

TEST(Agreement, ChangedPillarDiffersInDistanceAndVolumeNearIt) {
    const vtest::Model m = vtest::smallModel(Bottom::Flat);
    Scene s = m.scene;
    const size_t k = vtest::keptIndex(s, 2, 4);
    s.top[k] += 500;  // 0.5 mm
    const Mesh changed = meshScene(s);
    const AgreementResult r = compareMeshes(changed, m.mesh, "original", {});
    EXPECT_NEAR(r.figures.hausdorff_to_reference_mm, 0.5, r.figures.hausdorff_error_bound_mm);
    const Check& d = findCheck(r, "reference_distance");
    EXPECT_EQ(d.status, CheckStatus::Fail);
    ASSERT_FALSE(d.worst.empty());
    const Vec3 centre = vtest::cellCentre(s, k, 0);
    EXPECT_LT(std::hypot(d.worst[0].at_mm.x - centre.x, d.worst[0].at_mm.y - centre.y), s.pitch_mm);
    // Independent volume: the hexagon's area times 0.5 mm.
    EXPECT_NEAR(r.figures.volume_difference_mm3, hexArea(s.pitch_mm) * 0.5, 1e-3);
    EXPECT_EQ(findCheck(r, "reference_volume").status, CheckStatus::Fail);
}

TEST(Agreement, EmptyReferenceFails) {
    const AgreementResult r = compareMeshes(vtest::box({0, 0, 0}, {1, 1, 1}), Mesh{}, "nothing", {});
    EXPECT_EQ(findCheck(r, "reference_distance").status, CheckStatus::Fail);
    EXPECT_EQ(findCheck(r, "reference_volume").status, CheckStatus::Fail);
}

}  // namespace
}  // namespace tsf
