// runFeelSession: a feel session from a Scene through the library alone, on
// the simulated device, ending at zero force.
#include <gtest/gtest.h>

#include <atomic>

#include "gen/model/build_scene.h"
#include "haptics/sim_device.h"
#include "pipeline/feel_session.h"
#include "tests/support/fields.h"

namespace tsf {
namespace {

using namespace tsf::haptics;

TEST(FeelSession, TheLibraryRunsASessionOnTheSimulatedHandAndEndsAtZeroForce) {
    const Scene scene = buildScene(test::fieldFromFunction(12, 10, [](int c, int r) { return 1.0 + (c * 3 + r) % 5; }),
                                   test::smallParams(Bottom::Flat, Cull::Hull));
    const FeelSurface surface = buildFeelSurface(scene, 2, ScaleSpaceKind::kGaussian);
    ASSERT_FALSE(surface.grid.empty());
    EXPECT_EQ(surface.space.count(), 2);
    SimDevice device(makeSimScript(parseSimTrajectory("sweep"), surface.mapping, 1.5), surface.limits);
    FeelRequest rq;
    rq.loop.duration_s = 2.0;
    rq.log_records = 4000;
    std::atomic<bool> stop{false};
    bool told = false;
    const FeelOutcome out = runFeelSession(scene, surface, device, rq, stop, [&] { told = true; });
    EXPECT_TRUE(told);
    EXPECT_EQ(out.stats.end, LoopEnd::kDuration);
    EXPECT_TRUE(out.stats.zero_force_sent);
    EXPECT_GT(out.counters.contact_ticks, 0u) << "the simulated finger touched the relief";
    EXPECT_LE(out.counters.max_force_N, surface.limits.max_force_N + 1e-9);
    EXPECT_GT(out.log.size(), 1000u);
    EXPECT_GT(out.coverage.touched, 0);
}

}  // namespace
}  // namespace tsf
