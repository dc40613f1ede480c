// The verifier must be able to fail. Start from a real tsf model (buildScene +
// meshScene of a small field), plant one defect at a time, and check that it
// is reported by the right check, at the right place; the clean model passes.
#include <gtest/gtest.h>

#include <algorithm>

#include "tests/verify/verify_test_support.h"
#include "verify/verify_model.h"

namespace tsf {
namespace {

using vtest::check;
using vtest::failedIds;
using vtest::nearestOffender;

using Ids = std::vector<std::string>;

// Index of a top triangle of kept cell k: all three corners at the cell's top
// z and the centroid inside the cell's hexagon.
size_t topTriangleOf(const vtest::Model& m, size_t k) {
    const Vec3 c = vtest::cellCentre(m.scene, k, m.scene.top[k]);
    const double r = m.scene.pitch_mm / 2;  // inradius
    for (size_t t = 0; t < m.mesh.triangles.size(); ++t) {
        const Vec3 g = vtest::centroid(m.mesh, t);
        bool flat = true;
        for (uint32_t v : m.mesh.triangles[t]) flat = flat && m.mesh.positions[v].z == c.z;
        if (flat && std::hypot(g.x - c.x, g.y - c.y) < r) return t;
    }
    ADD_FAILURE() << "no top triangle found for cell " << k;
    return 0;
}

class PlantedDefects : public ::testing::TestWithParam<Bottom> {
protected:
    void SetUp() override {
        model_ = vtest::smallModel(GetParam());
        cell_ = vtest::keptIndex(model_.scene, 3, 3);
        tri_ = topTriangleOf(model_, cell_);
    }
    VerifyReport verify(const Mesh& mesh, bool exact = false) const {
        VerifyOptions o;
        o.exact = exact;
        return verifyModel(mesh, &model_.scene, o);
    }
    vtest::Model model_;
    size_t cell_ = 0;  // kept index of cell (3, 3)
    size_t tri_ = 0;   // one of its top triangles
};

TEST_P(PlantedDefects, CleanModelPassesEveryCheck) {
    const VerifyReport r = verify(model_.mesh);
    EXPECT_TRUE(r.passed()) << formatReport(r);
    // A mirrored model printed in one piece hangs its underside in the air:
    // the overhang warning says it needs supports (verify/overhang.h), and
    // nothing else warns.
    const bool mirrored = model_.scene.params.bottom == Bottom::Mirrored;
    EXPECT_EQ(check(r, "overhang").status, mirrored ? CheckStatus::Warn : CheckStatus::Pass) << formatReport(r);
    EXPECT_EQ(r.countStatus(CheckStatus::Warn), mirrored ? 1u : 0u) << formatReport(r);
    for (const char* id : {"closed", "manifold_edges", "manifold_vertices", "consistent_orientation", "single_piece",
                           "degenerate_faces", "self_intersections", "outward_orientation", "values_read_back",
                           "outside_cells_empty"})
        EXPECT_EQ(check(r, id).status, CheckStatus::Pass) << id;
    // Volume equals the sum of the prisms, computed from the Scene alone: the
    // area of each hexagon from its snapped corners (shoelace) times its height.
    const Scene& s = model_.scene;
    double prisms = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        double twice_area = 0;
        for (int c = 0; c < kHexCorners; ++c) {
            const Vec3 p = s.point(hexCorner(s.grid, s.col[k], s.row[k], c), 0);
            const Vec3 q = s.point(hexCorner(s.grid, s.col[k], s.row[k], (c + 1) % kHexCorners), 0);
            twice_area += p.x * q.y - q.x * p.y;
        }
        prisms += 0.5 * twice_area * s.zMm(s.top[k] - s.bottom[k]);
    }
    EXPECT_NEAR(r.mesh.volume_mm3, prisms, 1e-9 * prisms);
}

TEST_P(PlantedDefects, RemovedTriangleIsAHoleWhereItWas) {
    Mesh m = model_.mesh;
    const Vec3 where = vtest::centroid(m, tri_);
    m.triangles.erase(m.triangles.begin() + std::ptrdiff_t(tri_));
    const VerifyReport r = verify(m);
    EXPECT_EQ(failedIds(r), Ids{"closed"}) << formatReport(r);
    const Check& c = check(r, "closed");
    EXPECT_EQ(c.count, 3);
    ASSERT_EQ(c.worst.size(), 1u);  // one hole
    EXPECT_LT(vtest::distance(c.worst[0].at_mm, where), 1e-9);  // the rim's mean midpoint is the centroid
    EXPECT_EQ(check(r, "outward_orientation").status, CheckStatus::Skipped);
}

TEST_P(PlantedDefects, FlippedTriangleIsNamedAndLocated) {
    Mesh m = model_.mesh;
    std::swap(m.triangles[tri_][1], m.triangles[tri_][2]);
    const VerifyReport r = verify(m);
    EXPECT_EQ(failedIds(r), Ids{"consistent_orientation"}) << formatReport(r);
    const Check& c = check(r, "consistent_orientation");
    EXPECT_EQ(c.count, 3);
    ASSERT_FALSE(c.worst.empty());
    EXPECT_EQ(c.worst[0].amount, 3.0);  // all three of its edges disagree
    EXPECT_LT(vtest::distance(c.worst[0].at_mm, vtest::centroid(m, tri_)), 1e-9);
    EXPECT_NE(c.worst[0].detail.find("triangle " + std::to_string(tri_)), std::string::npos) << c.worst[0].detail;
}

TEST_P(PlantedDefects, DuplicatedTriangleIsNonManifoldAndSelfIntersecting) {
    Mesh m = model_.mesh;
    m.triangles.push_back(m.triangles[tri_]);
    const VerifyReport r = verify(m);
    const Ids failed = failedIds(r);
    EXPECT_TRUE(std::count(failed.begin(), failed.end(), "manifold_edges")) << formatReport(r);
    const Check& c = check(r, "manifold_edges");
    EXPECT_EQ(c.count, 3);
    EXPECT_LT(nearestOffender(c, vtest::centroid(m, tri_)), model_.scene.pitch_mm);
    // The twin lies on the original: CGAL sees them overlap (on a re-oriented copy).
    const Check& si = check(r, "self_intersections");
    EXPECT_EQ(si.status, CheckStatus::Fail) << formatReport(r);
    EXPECT_LT(nearestOffender(si, vtest::centroid(m, tri_)), model_.scene.pitch_mm);
}

TEST_P(PlantedDefects, NudgedVertexSelfIntersectsNearIt) {
    for (bool exact : {false, true}) {
        Mesh m = model_.mesh;
        // Push one top corner of the cell through the underside of the model.
        const uint32_t v = m.triangles[tri_][0];
        const Vec3 old = m.positions[v];
        m.positions[v].z = model_.scene.zMm(*std::min_element(model_.scene.bottom.begin(), model_.scene.bottom.end())) - 1.0;
        const VerifyReport r = verify(m, exact);
        EXPECT_EQ(r.exact, exact);
        const Check& si = check(r, "self_intersections");
        EXPECT_EQ(si.status, CheckStatus::Fail) << formatReport(r);
        EXPECT_GT(si.count, 0);
        // Every listed intersection is within a cell of the moved vertex (in plan).
        for (const Offender& o : si.worst)
            EXPECT_LT(std::hypot(o.at_mm.x - old.x, o.at_mm.y - old.y), 1.5 * model_.scene.pitch_mm) << o.detail;
        // Topology is untouched.
        for (const char* id : {"closed", "manifold_edges", "manifold_vertices", "consistent_orientation", "single_piece"})
            EXPECT_EQ(check(r, id).status, CheckStatus::Pass) << id;
    }
}

TEST_P(PlantedDefects, DisjointSecondShellIsASecondPiece) {
    const Mesh m = vtest::append(model_.mesh, vtest::box({200, 200, 0}, {210, 206, 4}));
    const VerifyReport r = verify(m);
    EXPECT_EQ(failedIds(r), Ids{"single_piece"}) << formatReport(r);
    const Check& c = check(r, "single_piece");
    EXPECT_EQ(c.count, 1);
    ASSERT_EQ(c.worst.size(), 1u);
    EXPECT_EQ(c.worst[0].amount, 12.0);
    EXPECT_LT(vtest::distance(c.worst[0].at_mm, {205, 203, 2}), 1e-12);
    EXPECT_EQ(r.mesh.component_count, 2u);
}

TEST_P(PlantedDefects, ChangedPillarHeightIsReadBackAtThatCell) {
    Scene wrong = model_.scene;
    const int64_t step = 250;  // 0.25 mm at the 1 um snap
    wrong.top[cell_] += step;
    if (GetParam() == Bottom::Mirrored) wrong.bottom[cell_] += step;  // keep the slab thickness
    const Mesh m = meshScene(wrong);
    const VerifyReport r = verify(m);
    EXPECT_EQ(failedIds(r), Ids{"values_read_back"}) << formatReport(r);
    ASSERT_TRUE(r.readback);
    const size_t surfaces = GetParam() == Bottom::Mirrored ? 2 : 1;
    EXPECT_EQ(r.readback->over_tolerance, surfaces);
    const CellReadback& w = r.readback->worst[0];
    EXPECT_EQ(w.col, 3);
    EXPECT_EQ(w.row, 3);
    EXPECT_NEAR(w.error_mm, 0.25, 1e-9);
    const Vec3 centre = vtest::cellCentre(model_.scene, cell_, 0);
    EXPECT_LT(std::hypot(check(r, "values_read_back").worst[0].at_mm.x - centre.x,
                         check(r, "values_read_back").worst[0].at_mm.y - centre.y), 1e-9);
    // In data units: 0.25 mm of 10 mm for the field's range (linear transfer).
    const ValueMapping& map = model_.scene.mapping;
    EXPECT_NEAR(w.value_error, 0.25 / 10.0 * (map.value_max - map.baseline), 2e-3 * (map.value_max - map.baseline));
}

TEST_P(PlantedDefects, InsideOutModelIsNotOutward) {
    Mesh m = model_.mesh;
    for (auto& t : m.triangles) std::swap(t[1], t[2]);
    const VerifyReport r = verify(m);
    EXPECT_EQ(failedIds(r), Ids{"outward_orientation"}) << formatReport(r);
    EXPECT_LT(check(r, "outward_orientation").worst.at(0).amount, 0.0);
}

TEST_P(PlantedDefects, ZeroAreaTriangleIsDegenerate) {
    Mesh m = model_.mesh;
    // An extra triangle on three collinear points: two corners of a top
    // triangle and the midpoint between them.
    const auto tri = m.triangles[tri_];
    const Vec3 &a = m.positions[tri[0]], &b = m.positions[tri[1]];
    m.positions.push_back({(a.x + b.x) / 2, (a.y + b.y) / 2, (a.z + b.z) / 2});
    m.triangles.push_back({tri[0], tri[1], uint32_t(m.positions.size() - 1)});
    const VerifyReport r = verify(m);
    const Check& c = check(r, "degenerate_faces");
    EXPECT_EQ(c.status, CheckStatus::Fail) << formatReport(r);
    EXPECT_EQ(c.count, 1);
    EXPECT_NE(c.worst.at(0).detail.find("collinear"), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(FlatAndMirrored, PlantedDefects, ::testing::Values(Bottom::Flat, Bottom::Mirrored),
                         [](const auto& info) { return std::string(toString(info.param)); });

}  // namespace
}  // namespace tsf
