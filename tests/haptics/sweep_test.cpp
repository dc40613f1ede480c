// The simulated hand is a fair test: the scripted sweep gets over steps
// instead of being held at them, and the force rarely sits at its limit.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "haptics/feel_renderer.h"
#include "haptics/haptic_loop.h"
#include "haptics/sim_device.h"
#include "haptics_fixtures.h"

using namespace tsf::haptics;
using namespace tsf::haptics::testing;

namespace {

/// No more than this share of the sweep's ticks are at the force limit.
constexpr double kMaxClampedShare = 0.01;

struct StepRun {
    double east_on_top_m = -1.0;  ///< farthest east the finger touched the high side
    double east_edge_m = 0.0;
    double clamped_share = 0.0;
    double max_force_N = 0.0;
};

/// The default sweep over a step: the west half at the floor, the east half
/// 60 % of the relief up (14 mm on a Falcon), a wall across every line.
StepRun sweepOverAStep(const FingerParams& hand) {
    std::vector<float> h;
    for (int j = 0; j < 20; ++j)
        for (int i = 0; i < 30; ++i) h.push_back(i < 15 ? 0.0f : 0.6f);
    auto scene = makeScene(makeHeightGrid(30, 20, h), {}, 1, ScaleSpaceKind::kGaussian);
    SimDevice device(makeSimScript(SimTrajectory::kSweep, scene->mapping), scene->limits, hand);
    FeelRenderer renderer(scene->model);
    FakeLoopClock clock;
    LoopOptions lo;
    lo.duration_s = 600.0;  // a hand that never gets past the wall still ends
    std::atomic<bool> stop{false};
    LoopStats stats;
    ForceLog log(700'000);
    runHapticLoop(device, renderer, clock, lo, stop, &log, stats);
    StepRun r;
    r.east_edge_m = scene->mapping.eastX();
    const double high = scene->mapping.floor_y_m + 0.5 * scene->mapping.relief_m;
    for (size_t i = 0; i < log.size(); ++i)
        if ((log[i].flags & kFlagContact) && log[i].position_m.y > high)
            r.east_on_top_m = std::max(r.east_on_top_m, log[i].position_m.x);
    r.clamped_share = double(renderer.counters().clamped_ticks) / double(renderer.counters().ticks);
    r.max_force_N = renderer.counters().max_force_N;
    return r;
}

}  // namespace

TEST(Sweep, TheHandClimbsAStepInsteadOfDraggingTheFinger) {
    const StepRun r = sweepOverAStep({});
    EXPECT_GT(r.east_on_top_m, r.east_edge_m - 0.003);  // onto the high side, across its width
    EXPECT_LE(r.clamped_share, kMaxClampedShare);
    EXPECT_LE(r.max_force_N, 4.0);  // never shoved into the wall
    // The planted defect: a hand without the reflexes (pushes on, never
    // lifts, never waits) is held at the wall and presses into it.
    FingerParams pushy;
    pushy.lift_gain = 0.0;
    pushy.max_lead_m = 1e9;
    const StepRun bad = sweepOverAStep(pushy);
    std::printf("[ step     ] reflexes: east %.1f mm of %.1f, %.2f%% clamped; pushy: east %.1f mm, %.2f%% clamped\n",
                1e3 * r.east_on_top_m, 1e3 * r.east_edge_m, 100 * r.clamped_share, 1e3 * bad.east_on_top_m,
                100 * bad.clamped_share);
    EXPECT_TRUE(bad.east_on_top_m < r.east_edge_m - 0.003 || bad.clamped_share > kMaxClampedShare)
        << bad.east_on_top_m << " " << bad.clamped_share;
}
