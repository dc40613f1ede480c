// runFeelSession: a feel session from a Scene through the library alone, on
// the simulated device, ending at zero force.
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <utility>

#include "gen/field/hex_grid.h"
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

namespace tsf {
namespace {

using namespace tsf::haptics;

/// Slope (rise over run) between the centres of cells (0, row) and
/// (cols - 1, row), on the device (device y over device x) and as printed
/// (mm over mm, from the lattice and the ramp's heights alone).
struct Slopes {
    double felt = 0, printed = 0;
};

Slopes rampSlopes(const Scene& scene, const FeelSurface& s, int cols, int row, double rise_mm) {
    // The relief samples at the two cells' centres (the relief is exact there).
    auto sample = [&](int c) {
        const LatticePoint centre = hexCentre(scene.grid, c, row);
        return std::pair<int32_t, int32_t>(
            int32_t(std::floor(latticeX(centre, scene.pitch_mm) / s.relief.sample_mm)) + s.relief.origin_i,
            int32_t(std::floor(latticeY(centre, scene.pitch_mm, 1.0) / s.relief.sample_mm)) + s.relief.origin_j);
    };
    const auto [ia, ja] = sample(0);
    const auto [ib, jb] = sample(cols - 1);
    const haptics::Vec3 a = gridToDevice(s.mapping, ia, ja, s.grid.at(ia, ja));
    const haptics::Vec3 b = gridToDevice(s.mapping, ib, jb, s.grid.at(ib, jb));
    return {(b.y - a.y) / (b.x - a.x), rise_mm / (double(ib - ia) * s.relief.sample_mm)};
}

TEST(FeelSession, AsPrintedProportionsMakeSlopesFeelAsPrinted) {
    // A ramp: 13 columns rising 1 mm each (12 mm over 12 column spacings of
    // a 5 mm pitch), flat across.
    const int cols = 13;
    SceneParams p = test::smallParams(Bottom::Flat, Cull::None);
    p.max_height_mm = 12.0;
    const Scene scene = buildScene(test::fieldFromFunction(cols, 6, [](int c, int) { return double(c); }), p);
    const FeelSurface printed =
        buildFeelSurface(scene, 1, ScaleSpaceKind::kGaussian, {}, nullptr, Proportions::kAsPrinted);
    const Slopes as = rampSlopes(scene, printed, cols, 3, 12.0);
    ASSERT_GT(as.printed, 0.1);
    EXPECT_NEAR(as.felt, as.printed, 0.01 * as.printed);
    EXPECT_NEAR(printed.scale.xy, printed.scale.z, 1e-9);
    EXPECT_DOUBLE_EQ(printed.scale.slopeExaggeration(), 1.0);
    // Fitted apart, the same ramp feels steeper by the exaggeration the
    // summary reports.
    const FeelSurface fitted = buildFeelSurface(scene, 1, ScaleSpaceKind::kGaussian);
    const Slopes fit = rampSlopes(scene, fitted, cols, 3, 12.0);
    EXPECT_GT(fitted.scale.slopeExaggeration(), 1.5);
    EXPECT_NEAR(fit.felt / fit.printed, fitted.scale.slopeExaggeration(), 0.01 * fitted.scale.slopeExaggeration());
    // The as-printed surface still lies inside the workspace.
    const DeviceLimits limits;
    EXPECT_GE(printed.mapping.west_x_m, limits.workspace.min_m.x);
    EXPECT_LE(printed.mapping.eastX(), limits.workspace.max_m.x);
    EXPECT_LE(printed.mapping.volume_top_y_m, limits.workspace.max_m.y + 1e-12);
}

}  // namespace
}  // namespace tsf
