// makeVerifiedModel: the one library call that makes the model tsf writes,
// meshed and proven, in parts and in halves, with no command line.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <stdexcept>
#include <thread>
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

// The hills with the default orientation marks (smallParams leaves them
// out): a model as tsf gen makes it.
Scene hillsWithMarks() {
    SceneParams p = test::smallParams(Bottom::Flat, Cull::Hull);
    p.marks = MarkParams{};
    return buildScene(hills(), p);
}

TEST(VerifiedModel, OneCallMeshesAndVerifiesAgainstTheScene) {
    const Scene s = hillsWithMarks();
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
    const Scene s = hillsWithMarks();
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

// The one solid is handed to write_ahead while it is verified: the very
// mesh the checks read and the call returns (as the file holds it: float32).
TEST(VerifiedModel, TheSolidIsWrittenAheadAsItIsChecked) {
    const Scene s = hillsWithMarks();
    ModelRequest rq;
    rq.stored_as_float32 = true;
    Mesh written;
    int calls = 0;
    rq.write_ahead = [&](const Mesh& mesh) {
        ++calls;
        written = mesh;
    };
    const VerifiedModel m = makeVerifiedModel(s, rq);
    ASSERT_TRUE(m.report && m.report->passed());
    EXPECT_TRUE(m.written_ahead);
    EXPECT_EQ(calls, 1);
    EXPECT_EQ(written.triangles, m.mesh.triangles);
    ASSERT_EQ(written.positions.size(), m.mesh.positions.size());
    for (size_t v = 0; v < written.positions.size(); ++v) {
        const Vec3& q = written.positions[v];
        EXPECT_EQ(q.x, double(float(q.x)));  // already rounded: the bytes the checks saw
        EXPECT_EQ(q.x, m.mesh.positions[v].x);
        EXPECT_EQ(q.y, m.mesh.positions[v].y);
        EXPECT_EQ(q.z, m.mesh.positions[v].z);
    }
}

// A failed check wins over the write: the caller learns of the failure (and
// discards what was written), and only once the writer has let go of the mesh.
TEST(VerifiedModel, AFailedCheckIsThrownOnceTheWriteAheadHasEnded) {
    const Scene s = buildScene(hills(), test::smallParams(Bottom::Flat, Cull::Hull));
    ModelRequest rq;
    rq.verify_options.nozzle_mm = 40.0;  // every wall thinner than the nozzle
    rq.verify_options.fail_on_warnings = true;
    std::atomic<bool> ended{false};
    rq.write_ahead = [&](const Mesh&) {
        std::this_thread::sleep_for(std::chrono::milliseconds(200));
        ended = true;
        throw std::runtime_error("disk full");
    };
    EXPECT_THROW(makeVerifiedModel(s, rq), ModelVerificationFailed);
    EXPECT_TRUE(ended);
}

// A write that fails is reported once the model has passed its checks.
TEST(VerifiedModel, AWriteAheadThatFailsIsRethrownAfterTheChecksPass) {
    const Scene s = buildScene(hills(), test::smallParams(Bottom::Flat, Cull::Hull));
    ModelRequest rq;
    rq.write_ahead = [](const Mesh&) { throw std::runtime_error("No space left on device"); };
    try {
        makeVerifiedModel(s, rq);
        ADD_FAILURE() << "the write's failure was lost";
    } catch (const std::runtime_error& e) {
        EXPECT_STREQ(e.what(), "No space left on device");
    }
}

// Parts, halves and an unverified model are written by the front end after
// the call: write_ahead is not called.
TEST(VerifiedModel, PartsHalvesAndUnverifiedModelsAreNotWrittenAhead) {
    int calls = 0;
    ModelRequest rq;
    rq.write_ahead = [&](const Mesh&) { ++calls; };
    const Scene flat = hillsWithMarks();
    ModelRequest parts = rq;
    parts.parts = true;
    EXPECT_FALSE(makeVerifiedModel(flat, parts).written_ahead);
    ModelRequest unverified = rq;
    unverified.verify = false;
    EXPECT_FALSE(makeVerifiedModel(flat, unverified).written_ahead);
    SceneParams hp = test::smallParams(Bottom::Mirrored, Cull::None);
    hp.pitch_mm = 8.0;
    hp.halves = true;
    const Scene halves = buildScene(test::fieldFromFunction(9, 8, [](int c, int r) { return 1.0 + (c + r) % 4; }), hp);
    EXPECT_FALSE(makeVerifiedModel(halves, rq).written_ahead);
    EXPECT_EQ(calls, 0);
}

}  // namespace
}  // namespace tsf
