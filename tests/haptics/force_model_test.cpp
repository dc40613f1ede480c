// The force model as a pure function: direction, magnitude, friction,
// volume, mode changes, rejection of bad input, and the clamp.
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "gen/util/error.h"
#include "haptics_fixtures.h"

using namespace tsf::haptics;
using namespace tsf::haptics::testing;

namespace {

bool finite3(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

/// Drives the model for `seconds` at 1 kHz at a fixed position so mode
/// fades settle; returns the state.
ForceState settle(const ForceModel& m, ForceState s, Vec3 p, double& t, double seconds, int lod, bool volume) {
    for (int k = 0; k < int(seconds * 1000); ++k) {
        ForceInput in;
        in.t_s = t;
        in.position_m = p;
        in.lod = lod;
        in.volume = volume;
        s = computeForce(m, s, in).state;
        t += 0.001;
    }
    return s;
}

}  // namespace

TEST(NormalForce, PointsAlongTheSurfaceNormalOnASlope) {
    ForceParams params;
    params.friction = false;
    for (Interpolation interp : {Interpolation::kBilinear, Interpolation::kBicubic}) {
        params.sampling.interpolation = interp;
        auto s = makeScene(eastRamp(9, 9), params);
        const FieldMapping& m = s->mapping;
        // Independent geometry: the relief rises relief_m over the 8 cell
        // pitches between the west and east cell centres.
        const double slope = m.relief_m / (8.0 * m.cell_m);
        const Vec3 normal = glm::normalize(Vec3(-slope, 1.0, 0.0));
        const Vec3 on_surface = gridToDevice(m, 4.0, 4.0, 0.5);
        const double dy = 0.002;
        const ForceOutput out = probe(s->model, {}, on_surface - Vec3(0, dy, 0));
        const double depth = dy / std::sqrt(1 + slope * slope);
        EXPECT_NEAR(out.penetration_m, depth, 1e-9);
        const double magnitude = params.stiffness_N_per_m * (depth - params.entry_depth_m / 2);
        EXPECT_NEAR(glm::length(out.force_N), magnitude, 1e-6);
        EXPECT_NEAR(glm::dot(glm::normalize(out.force_N), normal), 1.0, 1e-9);
        EXPECT_TRUE(out.flags & kFlagContact);
    }
}

TEST(NormalForce, GrowsWithDepthAndRampsInSmoothly) {
    ForceParams params;
    params.friction = false;
    auto s = makeScene(flatField(5, 5), params);
    const Vec3 top = gridToDevice(s->mapping, 2, 2, 0.5);
    double prev = 0.0, prev_slope = 0.0;
    const double step = 1e-5;
    for (double d = step; d < 0.004; d += step) {
        const double f = glm::length(probe(s->model, {}, top - Vec3(0, d, 0)).force_N);
        EXPECT_GT(f, prev);                         // monotone
        const double local_k = (f - prev) / step;   // N/m
        EXPECT_LE(local_k, params.stiffness_N_per_m * (1 + 1e-6));  // never stiffer than K
        EXPECT_GE(local_k, prev_slope - 1e-6);      // stiffness ramps in, no jump
        prev = f;
        prev_slope = local_k;
    }
    // First touch: a micrometre in gives a force far below a millinewton.
    EXPECT_LT(glm::length(probe(s->model, {}, top - Vec3(0, 1e-6, 0)).force_N), 1e-3);
}

TEST(NormalForce, ZeroInAirAndOnlyGravityWhenGravityIsOn) {
    ForceParams params;
    auto s = makeScene(eastRamp(6, 6), params);
    const Vec3 above = gridToDevice(s->mapping, 2.5, 2.5, 1.0) + Vec3(0, 0.002, 0);
    const ForceOutput a = probe(s->model, {}, above);
    EXPECT_EQ(a.force_N, Vec3(0.0));
    EXPECT_FALSE(a.flags & kFlagContact);
    params.gravity_N = 1.25;
    auto g = makeScene(eastRamp(6, 6), params);
    EXPECT_EQ(probe(g->model, {}, above).force_N, Vec3(0.0, -1.25, 0.0));
}

TEST(Friction, OpposesMotionAndSwitchesFromStaticToKinetic) {
    ForceParams params;  // K = 1000 N/m, delta = 1 mm, mu_s = 0.3, mu_k = 0.2
    auto s = makeScene(flatField(9, 9), params);
    const Vec3 start = gridToDevice(s->mapping, 4, 4, 0.5) - Vec3(0, 0.002, 0);
    const double fn = params.stiffness_N_per_m * (0.002 - 0.0005);  // 1.5 N
    ForceState st;
    double t = 0.0;
    const double speed = 0.02;  // m/s east
    bool slid = false;
    double slide_x = 0.0;
    Vec3 last = start;
    for (int k = 0; k < 200; ++k, t += 0.001) {
        const Vec3 p = start + Vec3(speed * t, 0, 0);
        last = p;
        const ForceOutput out = probe(s->model, st, p, t, Vec3(speed, 0, 0));
        st = out.state;
        const double ft = out.force_N.x;  // tangential component on a flat field
        EXPECT_NEAR(out.force_N.y, fn, 1e-9);
        EXPECT_LE(ft, 0.0) << "friction must oppose eastward motion";
        if (!(out.flags & kFlagSliding)) {
            EXPECT_LE(-ft, params.mu_static * fn + 1e-9);
            EXPECT_NEAR(-ft, params.stiffness_N_per_m * speed * t, 1e-9);  // the stick spring
            EXPECT_FALSE(slid) << "no return to sticking while moving fast";
        } else {
            if (!slid) slide_x = speed * t;
            slid = true;
            EXPECT_NEAR(-ft, params.mu_kinetic * fn, 1e-9);
        }
    }
    ASSERT_TRUE(slid);
    // The switch happens where the spring reaches the static limit, 0.45 mm.
    EXPECT_NEAR(slide_x, params.mu_static * fn / params.stiffness_N_per_m, speed * 0.001 + 1e-12);
    // Stop: below the stick speed it sticks again and holds the probe.
    const ForceOutput held = probe(s->model, st, last, t, Vec3(0.0));
    EXPECT_FALSE(held.flags & kFlagSliding);
    EXPECT_NEAR(-held.force_N.x, params.mu_kinetic * fn, 1e-9);
}

namespace {

/// Tangential part of the force (the friction) at p.
Vec3 tangential(const ForceModel& m, const Vec3& p, const Vec3& f) {
    const SurfacePoint sp = surfaceAt(m, p, 0.0);
    const Vec3 n = glm::normalize(Vec3(-sp.slope_x, 1, -sp.slope_z));
    return f - n * glm::dot(f, n);
}

}  // namespace

TEST(Friction, OpposesSteadySlidingInEveryDirection) {
    auto s = makeScene(eastRamp(12, 10), ForceParams{});
    ForceState st;
    double t = 0.0;
    Vec3 p = gridToDevice(s->mapping, 5.5, 4.5, 0.45);
    for (int seg = 0; seg < 16; ++seg) {
        const double a = seg * 2.4;  // directions all around
        const Vec3 v = 0.02 * Vec3(std::cos(a), 0.0, std::sin(a));
        for (int k = 0; k < 60; ++k, t += 0.001) {
            const Vec3 before = p;
            p += v * 0.001;
            p.y = surfaceAt(s->model, p, 0.0).height_y_m - 0.0015;  // stay 1.5 mm in
            const Vec3 motion = (p - before) / 0.001;                // along the slope
            const ForceOutput out = probe(s->model, st, p, t, motion);
            st = out.state;
            if (k >= 30) {  // past the stick phase of this segment
                ASSERT_TRUE(out.flags & kFlagSliding) << seg << " " << k;
                const Vec3 ft = tangential(s->model, p, out.force_N);
                const Vec3 vt = tangential(s->model, p, motion);
                // The stick point trails like a pulled string (a tractrix):
                // after a turn its direction converges to straight behind.
                const double cosine = -glm::dot(glm::normalize(ft), glm::normalize(vt));
                EXPECT_GT(cosine, k < 50 ? 0.99 : 0.9999) << seg << " " << k;
            }
        }
    }
}

TEST(Friction, NeverGivesBackMoreThanItsSpringStores) {
    // On a random walk the stick spring may push along the motion for a
    // moment (it releases what it stored), but over any stretch friction is
    // dissipative: its work never exceeds the largest energy the spring can
    // hold, (mu_s F_n)^2 / (2 K).
    ForceParams params;
    params.gravity_N = 0.0;
    auto s = makeScene(flatField(12, 10), params);
    std::mt19937 rng(11);
    std::normal_distribution<double> step(0.0, 0.0002);
    ForceState st;
    const Vec3 start = gridToDevice(s->mapping, 5, 5, 0.5) - Vec3(0, 0.002, 0);
    Vec3 p = start;
    Vec3 ft_prev(0.0);
    double work = 0.0;
    const double fn_max = params.stiffness_N_per_m * (0.002 - params.entry_depth_m / 2);
    const double bound = std::pow(params.mu_static * fn_max, 2) / (2 * params.stiffness_N_per_m);
    for (int k = 0; k < 5000; ++k) {
        const Vec3 dp(step(rng), 0.0, step(rng));
        p += dp;
        const ForceOutput out = probe(s->model, st, p, k * 0.001, dp / 0.001);
        st = out.state;
        const Vec3 ft(out.force_N.x, 0.0, out.force_N.z);
        work += 0.5 * glm::dot(ft_prev + ft, dp);  // trapezoid: exact for a spring
        ft_prev = ft;
        ASSERT_LE(work, bound + 1e-12) << k;
    }
    EXPECT_LT(work, -0.01) << "a long random walk must dissipate";
}

TEST(Volume, SlabForceIsContinuousAtItsFacesAndFinestAtTheBottom) {
    ForceParams params;
    auto s = makeScene(eastRamp(8, 8), params, 4, ScaleSpaceKind::kGaussian);
    const FieldMapping& m = s->mapping;
    const Vec3 column = gridToDevice(m, 3.5, 3.5, 0.0);
    double t = 0.0;
    ForceState st = settle(s->model, {}, Vec3(column.x, m.volume_top_y_m + 0.01, column.z), t, 0.5, 0, true);
    ASSERT_NEAR(st.volume_weight, 1.0, 1e-12);
    auto at = [&](double y) {
        ForceInput in;
        in.t_s = t;
        in.position_m = Vec3(column.x, y, column.z);
        in.volume = true;
        return computeForce(s->model, st, in);
    };
    const double eps = 1e-7;
    EXPECT_LT(glm::length(at(m.volume_top_y_m - eps).force_N), 1e-3);
    EXPECT_EQ(glm::length(at(m.volume_top_y_m + eps).force_N), 0.0);
    EXPECT_LT(glm::length(at(m.volume_bottom_y_m + eps).force_N), 1e-3);
    const ForceOutput mid = at(0.5 * (m.volume_bottom_y_m + m.volume_top_y_m));
    EXPECT_TRUE(mid.flags & kFlagInVolume);
    EXPECT_GT(mid.force_N.y, 0.0);
    EXPECT_LT(mid.force_N.x, 0.0);  // the ramp rises east: pushed downhill, west
    EXPECT_LE(glm::length(mid.force_N), params.volume_force_N + 1e-12);
    // The same height with volume mode off: nothing (it is air above the surface).
    EXPECT_EQ(glm::length(probe(s->model, {}, Vec3(column.x, 0.5 * (m.volume_bottom_y_m + m.volume_top_y_m), column.z)).force_N), 0.0);
}

TEST(ModeChange, LevelOfDetailSwitchFadesInsteadOfJumping) {
    // A bumpy field where level 0 and level 2 differ a lot under the probe.
    std::vector<float> h;
    for (int j = 0; j < 16; ++j)
        for (int i = 0; i < 16; ++i) h.push_back(((i / 2 + j / 2) % 2) ? 1.0f : 0.0f);
    ForceParams params;
    params.friction = false;
    auto s = makeScene(makeHeightGrid(16, 16, h), params, 3, ScaleSpaceKind::kMipmap);
    // Over the middle of a low block (height 0 at level 0), 2 mm into the
    // level-2 surface (a uniform 0.5 there): in the air at level 0, pressed
    // at level 2.
    const Vec3 p = gridToDevice(s->mapping, 2.5, 2.5, 0.5) - Vec3(0, 0.002, 0);
    double t = 0.0;
    ForceState st = settle(s->model, {}, p, t, 0.1, 0, false);
    ForceState jump = st;
    jump.lod = 2.0;
    const double f0 = glm::length(probe(s->model, st, p, t).force_N);
    const double f2 = glm::length(probe(s->model, jump, p, t).force_N);
    ASSERT_GT(std::abs(f0 - f2), 1.0) << "the test needs levels that differ under the probe";
    double prev = f0, worst = 0.0;
    for (int k = 0; k < 1000; ++k, t += 0.001) {
        ForceInput in;
        in.t_s = t;
        in.position_m = p;
        in.lod = 2;
        const ForceOutput out = computeForce(s->model, st, in);
        st = out.state;
        worst = std::max(worst, std::abs(glm::length(out.force_N) - prev));
        prev = glm::length(out.force_N);
    }
    EXPECT_NEAR(st.lod, 2.0, 1e-12);
    EXPECT_LT(worst, 0.05 * std::abs(f0 - f2));
}

TEST(Guidance, PullsTowardTheSurfaceInAirAndStaysBelowItsLimit) {
    ForceParams params;
    params.guidance_N = 0.4;
    auto s = makeScene(eastRamp(10, 10), params, 3, ScaleSpaceKind::kGaussian);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-0.03, 0.03);
    for (int k = 0; k < 2000; ++k) {
        const Vec3 p(u(rng), s->mapping.volume_bottom_y_m + 0.01 + 0.3 * u(rng), u(rng));
        const ForceOutput out = probe(s->model, {}, p);
        if (out.flags & kFlagContact) continue;
        EXPECT_LE(glm::length(out.force_N), params.guidance_N + 1e-12);
        EXPECT_LT(out.force_N.y, 0.0);
    }
}

TEST(Safety, NonFiniteInputGivesZeroForceAndKeepsTheState) {
    auto s = makeScene(eastRamp(5, 5), ForceParams{});
    ForceState st;
    st.energy_J = 0.123;
    for (Vec3 bad : {Vec3(std::nan(""), 0, 0), Vec3(0, INFINITY, 0), Vec3(0, 0, -INFINITY)}) {
        const ForceOutput out = probe(s->model, st, bad, 1.0);
        EXPECT_EQ(out.force_N, Vec3(0.0));
        EXPECT_TRUE(out.flags & kFlagRejected);
        EXPECT_DOUBLE_EQ(out.state.energy_J, 0.123);
    }
    const ForceOutput nan_t = probe(s->model, st, Vec3(0.0), std::nan(""));
    EXPECT_EQ(nan_t.force_N, Vec3(0.0));
    // A NaN velocity is ignored, not propagated.
    const ForceOutput nan_v = probe(s->model, st, gridToDevice(s->mapping, 2, 2, 0.2), 1.0, Vec3(std::nan("")));
    EXPECT_TRUE(finite3(nan_v.force_N));
}

TEST(Safety, TheSameInputGivesTheSameOutput) {
    auto s = makeScene(eastRamp(7, 5), ForceParams{}, 3);
    ForceState a, b;
    std::mt19937 rng(2);
    std::uniform_real_distribution<double> u(-0.02, 0.02);
    for (int k = 0; k < 1000; ++k) {
        ForceInput in;
        in.t_s = k * 0.001;
        in.position_m = Vec3(u(rng), u(rng) * 0.5, u(rng));
        in.velocity_m_per_s = Vec3(u(rng), u(rng), u(rng)) * 10.0;
        in.lod = k / 300;
        in.volume = (k / 200) % 2;
        const ForceOutput x = computeForce(s->model, a, in);
        const ForceOutput y = computeForce(s->model, b, in);
        ASSERT_EQ(x.force_N, y.force_N);
        ASSERT_EQ(x.flags, y.flags);
        a = x.state;
        b = y.state;
    }
}

TEST(Safety, ClampHoldsOverAMillionRandomStates) {
    std::mt19937_64 rng(20240601);
    std::uniform_real_distribution<double> u(0.0, 1.0);
    // Fields that stress the model: cliffs, 1 x 1, flat, noise.
    std::vector<float> cliff, noise;
    for (int j = 0; j < 12; ++j)
        for (int i = 0; i < 12; ++i) {
            cliff.push_back(((i + j) % 2) ? 1.0f : 0.0f);
            noise.push_back(float(u(rng)));
        }
    std::vector<HeightGrid> fields = {makeHeightGrid(12, 12, cliff), makeHeightGrid(1, 1, {0.3f}), flatField(7, 3, 0.0f),
                                      makeHeightGrid(12, 12, noise), makeHeightGrid(2, 1, {0.0f, 1.0f})};
    std::vector<std::unique_ptr<Scene>> scenes;
    for (size_t f = 0; f < fields.size(); ++f) {
        ForceParams p;
        p.max_force_N = f % 2 ? 8.0 : 3.0;
        p.stiffness_N_per_m = 2900.0;
        p.gravity_N = f == 3 ? 2.0 : 0.0;
        p.guidance_N = f == 4 ? 0.5 : 0.0;
        p.edge = f % 2 ? EdgeMode::kWall : EdgeMode::kClamp;
        p.sampling.interpolation = f % 2 ? Interpolation::kBilinear : Interpolation::kBicubic;
        p.sampling.central_differences = f == 2;
        p.volume_force_N = 3.0;
        scenes.push_back(makeScene(fields[f], p, 4, f % 2 ? ScaleSpaceKind::kGaussian : ScaleSpaceKind::kMipmap));
    }
    auto r = [&](double lo, double hi) { return lo + (hi - lo) * u(rng); };
    uint64_t clamped = 0;
    for (int k = 0; k < 1000000; ++k) {
        const Scene& sc = *scenes[size_t(k) % scenes.size()];
        ForceState st;
        st.started = u(rng) < 0.9;
        st.t_s = r(0, 10);
        st.position_m = Vec3(r(-0.1, 0.1), r(-0.1, 0.1), r(-0.1, 0.1));
        st.lod = r(-2, 12);
        st.volume_weight = r(-0.5, 1.5);
        st.in_contact = u(rng) < 0.5;
        st.sliding = u(rng) < 0.5;
        st.stick_point_m = Vec3(r(-0.1, 0.1), r(-0.1, 0.1), r(-0.1, 0.1));
        st.energy_J = r(-1, 1);
        st.observed_force_N = Vec3(r(-100, 100), r(-100, 100), r(-100, 100));
        ForceInput in;
        in.t_s = st.t_s + r(-0.01, 0.1);
        in.position_m = u(rng) < 0.5 ? st.position_m + Vec3(r(-1e-3, 1e-3), r(-1e-3, 1e-3), r(-1e-3, 1e-3))
                                     : Vec3(r(-0.1, 0.1), r(-0.1, 0.1), r(-0.1, 0.1));
        in.velocity_m_per_s = Vec3(r(-3, 3), r(-3, 3), r(-3, 3)) * (u(rng) < 0.1 ? 1e-6 : 1.0);
        in.output_gain = r(-0.5, 1.5);
        in.lod = int(r(-3, 12));
        in.volume = u(rng) < 0.5;
        const ForceOutput out = computeForce(sc.model, st, in);
        const double mag = glm::length(out.force_N);
        ASSERT_TRUE(finite3(out.force_N)) << "draw " << k;
        // Exactly: the header promises <= max_force_N, not "about" (a scaled
        // vector used to come out up to 2 ulp long).
        ASSERT_LE(mag, sc.model.params.max_force_N) << "draw " << k;
        ASSERT_TRUE(std::isfinite(out.state.energy_J) && finite3(out.state.stick_point_m));
        if (out.flags & kFlagClamped) ++clamped;
    }
    EXPECT_GT(clamped, 1000u) << "the draws must actually reach the limit";
}

TEST(Setup, RejectsUnsafeOrInconsistentParameters) {
    const HeightGrid g = flatField(3, 3);
    ForceParams p;
    p.stiffness_N_per_m = 3500.0;  // above the Falcon's 3000 N/m
    EXPECT_THROW(makeScene(g, p), tsf::InputError);
    p = ForceParams{};
    p.stiffness_N_per_m = 2000.0;  // fine at 1 kHz, too stiff at 500 Hz
    EXPECT_NO_THROW(makeScene(g, p));
    EXPECT_THROW(makeScene(g, p, 1, ScaleSpaceKind::kMipmap, 500.0), tsf::InputError);
    p = ForceParams{};
    p.mu_kinetic = 0.5;
    p.mu_static = 0.3;
    EXPECT_THROW(makeScene(g, p), tsf::InputError);
    p = ForceParams{};
    p.max_force_N = 9.0;  // device limit 8 N
    EXPECT_THROW(makeScene(g, p), tsf::InputError);
    p = ForceParams{};
    p.max_force_N = std::nan("");
    EXPECT_THROW(makeScene(g, p), tsf::InputError);
    p = ForceParams{};
    p.gravity_N = -1.0;
    EXPECT_THROW(makeScene(g, p), tsf::InputError);
}
