// makeVerifiedModel: the one library call that makes the model tsf writes,
// meshed and proven, in parts and in halves, with no command line.
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "gen/model/build_scene.h"
#include "pipeline/verified_model.h"
#include "tests/support/fields.h"
#include "tests/support/mesh_invariants.h"

namespace tsf {
namespace {

HexField hills() {
    return test::fieldFromFunction(12, 10, [](int c, int r) { return 1.0 + double((c * 3 + r * 5) % 7); });
}

TEST(VerifiedModel, OneCallMeshesAndVerifiesAgainstTheScene) {
    SceneParams p = test::smallParams(Bottom::Flat, Cull::Hull);
    p.marks = MarkParams{};
    const Scene s = buildScene(hills(), p);
    std::vector<std::string> stages;
    const VerifiedModel m = makeVerifiedModel(s, ModelRequest{}, [&](const std::string& st) { stages.push_back(st); });
    ASSERT_TRUE(m.report);
    EXPECT_TRUE(m.report->passed());
    ASSERT_NE(m.report->find("values_read_back"), nullptr);
    EXPECT_EQ(m.report->find("values_read_back")->status, CheckStatus::Pass);
    EXPECT_FALSE(m.quick);
    EXPECT_TRUE(m.parts.empty());
    EXPECT_FALSE(m.halves);
    EXPECT_EQ(stages, (std::vector<std::string>{"meshing", "verifying"}));
    EXPECT_TRUE(test::checkInvariants(m.mesh).closedManifold());
}

TEST(VerifiedModel, PartsAreMeshedAndVerifiedAloneAndTogether) {
    SceneParams p = test::smallParams(Bottom::Flat, Cull::Hull);
    p.marks = MarkParams{};
    const Scene s = buildScene(hills(), p);
    ModelRequest rq;
    rq.parts = true;
    const VerifiedModel m = makeVerifiedModel(s, rq);
    ASSERT_FALSE(m.parts.empty());
    EXPECT_EQ(m.parts.front().name, "pillars");
    ASSERT_TRUE(m.parts_report);
    EXPECT_TRUE(m.parts_report->passed());
}

TEST(VerifiedModel, HalvesArePrintedPiecesEachVerifiedAndAsAPair) {
    SceneParams p = test::smallParams(Bottom::Mirrored, Cull::None);
    p.pitch_mm = 8.0;
    p.halves = true;
    const Scene s = buildScene(test::fieldFromFunction(9, 8, [](int c, int r) { return 1.0 + (c + r) % 4; }), p);
    ASSERT_TRUE(s.halves);
    const VerifiedModel m = makeVerifiedModel(s, ModelRequest{});
    ASSERT_TRUE(m.halves);
    ASSERT_TRUE(m.halves->upper_report && m.halves->lower_report && m.halves->pin_report && m.halves->pair);
    EXPECT_TRUE(m.halves->upper_report->passed());
    EXPECT_TRUE(m.halves->lower_report->passed());
    EXPECT_TRUE(m.halves->pair->passed());
    EXPECT_GT(m.halves->pins.triangleCount(), 0u);
    // Unverified: the same pieces, no reports.
    ModelRequest quick;
    quick.verify = false;
    const VerifiedModel u = makeVerifiedModel(s, quick);
    ASSERT_TRUE(u.halves);
    EXPECT_FALSE(u.halves->pair);
    EXPECT_FALSE(u.report);
    EXPECT_EQ(u.halves->upper.triangleCount(), m.halves->upper.triangleCount());
}

TEST(VerifiedModel, AFrontEndsEarlyRefusalEndsTheCallBeforeAnyCheck) {
    const Scene s = buildScene(hills(), test::smallParams(Bottom::Flat, Cull::Hull));
    ModelRequest rq;
    size_t seen = 0;
    rq.on_mesh = [&](const Mesh& mesh) {
        seen = mesh.triangleCount();
        throw std::invalid_argument("too large for the bed");
    };
    std::vector<std::string> stages;
    EXPECT_THROW(makeVerifiedModel(s, rq, [&](const std::string& st) { stages.push_back(st); }), std::invalid_argument);
    EXPECT_GT(seen, 0u);
    EXPECT_EQ(stages, (std::vector<std::string>{"meshing"}));
}

}  // namespace
}  // namespace tsf
