// Closed-loop passivity: a simulated finger (mass, hand spring-damper) presses
// and slides on rendered fields through the real loop, renderer and force
// model; the work the rendered force does on the finger must never go above
// zero by more than a sliver - the surface gives no energy to the hand.
#include <cmath>
#include <cstdio>

#include <gtest/gtest.h>

#include "haptics/feel_renderer.h"
#include "haptics/haptic_loop.h"
#include "haptics/sim_device.h"
#include "haptics_fixtures.h"

using namespace tsf::haptics;
using namespace tsf::haptics::testing;

namespace {

/// Energy bound for "gains nothing": a 0.1 mJ sliver lifts a 150 g finger by
/// 0.07 mm - below anything a hand can feel - and covers the one tick of lag
/// the observer needs to see energy before it can dissipate it.
constexpr double kEnergySliver_J = 1e-4;

HeightGrid cliffs(int n) {
    std::vector<float> h;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) h.push_back(((i / 3 + j / 3) % 2) ? 1.0f : 0.0f);
    return makeHeightGrid(n, n, h);
}

HeightGrid waves(int n) {
    std::vector<float> h;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) h.push_back(float(0.5 + 0.5 * std::sin(0.9 * i) * std::cos(0.7 * j)));
    return makeHeightGrid(n, n, h);
}

struct SessionEnergy {
    double max_work_J = 0.0;
    double final_work_J = 0.0;
    uint64_t damping_ticks = 0;
    uint64_t contact_ticks = 0;
};

SessionEnergy runSession(const HeightGrid& grid, ForceParams params, SimTrajectory trajectory, double rate_Hz = 1000.0,
               bool volume = false) {
    auto scene = makeScene(grid, params, 4, ScaleSpaceKind::kGaussian, rate_Hz);
    SimDevice device(makeSimScript(trajectory, scene->mapping, 2.0), scene->limits);
    RendererOptions ro;
    ro.start_volume = volume;
    FeelRenderer renderer(scene->model, ro);
    FakeLoopClock clock;
    LoopOptions lo;
    lo.rate_Hz = rate_Hz;
    std::atomic<bool> stop{false};
    LoopStats stats;
    runHapticLoop(device, renderer, clock, lo, stop, nullptr, stats);
    EXPECT_EQ(stats.end, LoopEnd::kDeviceEnded);
    return {device.maxDeviceWork_J(), device.deviceWork_J(), renderer.counters().damping_ticks,
            renderer.counters().contact_ticks};
}

ForceParams stiff(Interpolation interp) {
    ForceParams p;
    p.stiffness_N_per_m = 3000.0;  // the device's limit: the hardest case
    p.max_force_N = 8.0;
    p.sampling.interpolation = interp;
    return p;
}

}  // namespace

TEST(Energy, FingerPressingAndSlidingGainsNoEnergyFromTheSurface) {
    struct Case {
        const char* name;
        HeightGrid grid;
        Interpolation interp;
        SimTrajectory trajectory;
    };
    const Case cases[] = {
        {"waves/bicubic/finger", waves(24), Interpolation::kBicubic, SimTrajectory::kFinger},
        {"cliffs/bilinear/finger", cliffs(24), Interpolation::kBilinear, SimTrajectory::kFinger},
        {"cliffs/bilinear/taps", cliffs(24), Interpolation::kBilinear, SimTrajectory::kTaps},
        {"waves/bicubic/sweep", waves(24), Interpolation::kBicubic, SimTrajectory::kSweep},
    };
    for (const Case& c : cases) {
        const SessionEnergy r = runSession(c.grid, stiff(c.interp), c.trajectory);
        std::printf("%-26s max work %+.3e J, final %+.3e J, contact %llu ticks, damped %llu ticks\n", c.name,
                    r.max_work_J, r.final_work_J, (unsigned long long)r.contact_ticks,
                    (unsigned long long)r.damping_ticks);
        EXPECT_GT(r.contact_ticks, 1000u) << c.name << ": the finger must actually touch";
        EXPECT_LE(r.max_work_J, kEnergySliver_J) << c.name;
    }
}

TEST(Energy, VolumeModeGainsNoEnergy) {
    const SessionEnergy r = runSession(waves(24), stiff(Interpolation::kBicubic), SimTrajectory::kTaps, 1000.0, true);
    std::printf("volume/taps max work %+.3e J, damped %llu ticks\n", r.max_work_J, (unsigned long long)r.damping_ticks);
    EXPECT_LE(r.max_work_J, kEnergySliver_J);
}

TEST(Energy, WithoutTheObserverTheSampledSurfaceDoesFeedEnergy) {
    // The planted defect: the same sessions with the passivity observer off
    // must show the energy the guard removes, or the test above proves nothing.
    ForceParams p = stiff(Interpolation::kBilinear);
    p.passivity_observer = false;
    p.friction = false;
    const SessionEnergy r = runSession(cliffs(24), p, SimTrajectory::kTaps, 1000.0);
    std::printf("observer off: max work %+.3e J\n", r.max_work_J);
    EXPECT_GT(r.max_work_J, kEnergySliver_J);
}
