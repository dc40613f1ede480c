// Falcon kinematics: forward/inverse round trips across the workspace, the
// Jacobian against finite differences, the solver's fallback, and force ->
// motor commands (limits keep the direction).
#include <cmath>
#include <random>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include "haptics/falcon/falcon_kinematics.h"
#include "tests/haptics/fake_falcon_mechanism.h"

using namespace tsf::haptics;

namespace {

/// Points of a regular grid over the +-30 mm workspace box, corners included.
std::vector<Vec3> workspaceGrid(int n = 7) {
    std::vector<Vec3> pts;
    for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j)
            for (int k = 0; k < n; ++k)
                pts.emplace_back(-0.03 + 0.06 * i / (n - 1), -0.03 + 0.06 * j / (n - 1), -0.03 + 0.06 * k / (n - 1));
    return pts;
}

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

TEST(FalconKinematics, EncoderScaleIsAboutThirtyEightMicrometresPerCount) {
    EXPECT_NEAR(kFalconRadPerCount * 180.0 / 3.14159265358979, 0.0364, 0.0001);
    EXPECT_NEAR(kFalconMetresPerCount, 38e-6, 1e-6);
    EXPECT_DOUBLE_EQ(falconEncoderToAngle(0), kFalconAngleAtZero_rad);
    EXPECT_NEAR(falconAngleToEncoder(falconEncoderToAngle(-1234)), -1234.0, 1e-9);
}

TEST(FalconKinematics, LegsAreSymmetricOnTheCentralAxis) {
    FalconAngles t;
    ASSERT_TRUE(falconInverseKinematics(Vec3(0.0, 0.0, 0.01), t));
    EXPECT_NEAR(t[0], t[1], 1e-12);
    EXPECT_NEAR(t[1], t[2], 1e-12);
    // Pulling the grip out (toward the user, +z) opens the thighs.
    FalconAngles out;
    ASSERT_TRUE(falconInverseKinematics(Vec3(0.0, 0.0, 0.03), out));
    EXPECT_GT(out[0], t[0]);
}

TEST(FalconKinematics, ForwardInverseRoundTripAcrossTheWorkspace) {
    int worst_iterations = 0;
    for (const Vec3& p : workspaceGrid()) {
        FalconAngles t;
        ASSERT_TRUE(falconInverseKinematics(p, t)) << p.x << " " << p.y << " " << p.z;
        // Cold start from the centre (the fallback) and warm start from 2 mm away.
        for (const Vec3& guess : {Vec3(0.0), p + Vec3(0.002, -0.001, 0.0015)}) {
            const FalconFkResult r = falconForwardKinematics(t, guess);
            ASSERT_TRUE(r.converged) << p.x << " " << p.y << " " << p.z;
            EXPECT_LT(glm::length(r.position_m - p), 1e-7);
            worst_iterations = std::max(worst_iterations, r.iterations);
        }
        // Converged to the tolerance: the angles of the solution match to a
        // hundredth of an encoder count.
        const FalconFkResult r = falconForwardKinematics(t, p);
        FalconAngles back;
        ASSERT_TRUE(falconInverseKinematics(r.position_m, back));
        for (int i = 0; i < 3; ++i) EXPECT_LT(std::abs(back[i] - t[i]), 0.01 * kFalconRadPerCount);
    }
    EXPECT_LE(worst_iterations, 10);
}

TEST(FalconKinematics, WarmStartTakesFewIterations) {
    // A 1 kHz tick moves the probe well under a millimetre.
    const Vec3 p(0.01, -0.012, 0.005);
    FalconAngles t;
    ASSERT_TRUE(falconInverseKinematics(p, t));
    const FalconFkResult r = falconForwardKinematics(t, p + Vec3(0.0005, 0.0, -0.0003));
    ASSERT_TRUE(r.converged);
    EXPECT_FALSE(r.cold_start);
    EXPECT_LE(r.iterations, 3);
}

TEST(FalconKinematics, QuantisedCountsGiveAPositionWithinTheEncoderResolution) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-0.03, 0.03);
    for (int k = 0; k < 200; ++k) {
        const Vec3 p(u(rng), u(rng), u(rng));
        FalconAngles t;
        ASSERT_TRUE(falconInverseKinematics(p, t));
        FalconAngles q;
        for (int i = 0; i < 3; ++i) q[i] = falconEncoderToAngle(int16_t(std::lround(falconAngleToEncoder(t[i]))));
        const FalconFkResult r = falconForwardKinematics(q, p);
        ASSERT_TRUE(r.converged);
        // Half a count on each thigh; the mechanism amplifies that a little.
        EXPECT_LT(glm::length(r.position_m - p), 3.0 * kFalconMetresPerCount);
    }
}

TEST(FalconKinematics, FallbackNeverReturnsGarbage) {
    const Vec3 last(0.004, 0.002, -0.01);
    // Angles no pose of the mechanism has (far beyond its range).
    for (const FalconAngles& bad : {FalconAngles{3.0, 3.0, 3.0}, FalconAngles{-2.5, 1.5, 0.2},
                                    FalconAngles{NAN, 0.5, 0.5}, FalconAngles{INFINITY, 0.0, 0.0}}) {
        const FalconFkResult r = falconForwardKinematics(bad, last);
        EXPECT_FALSE(r.converged);
        EXPECT_EQ(r.position_m, last);
    }
    // A garbage guess: the centre start still finds the pose.
    FalconAngles t;
    ASSERT_TRUE(falconInverseKinematics(Vec3(0.02, 0.02, 0.02), t));
    for (const Vec3& guess : {Vec3(NAN), Vec3(5.0, -3.0, 9.0)}) {
        const FalconFkResult r = falconForwardKinematics(t, guess);
        EXPECT_TRUE(r.converged);
        EXPECT_TRUE(r.cold_start);
        EXPECT_LT(glm::length(r.position_m - Vec3(0.02, 0.02, 0.02)), 1e-7);
    }
    // No solution and a wild guess: a finite position near the workspace.
    const FalconFkResult r = falconForwardKinematics({3.0, 3.0, 3.0}, Vec3(50.0, 0.0, 0.0));
    EXPECT_FALSE(r.converged);
    EXPECT_TRUE(finite(r.position_m));
    EXPECT_LE(glm::length(r.position_m), 0.1 + 1e-12);
}

TEST(FalconKinematics, OutOfReachHasNoInverse) {
    FalconAngles t{9.0, 9.0, 9.0};
    EXPECT_FALSE(falconInverseKinematics(Vec3(0.0, 0.0, 0.5), t));
    EXPECT_FALSE(falconInverseKinematics(Vec3(NAN, 0.0, 0.0), t));
    EXPECT_EQ(t[0], 9.0);
}

TEST(FalconKinematics, JacobianMatchesFiniteDifferencesOfTheForwardSolve) {
    constexpr double h = 1e-6;  // rad
    for (const Vec3& p : workspaceGrid(4)) {
        FalconAngles t;
        ASSERT_TRUE(falconInverseKinematics(p, t));
        glm::dmat3 J;
        ASSERT_TRUE(falconJacobian(p, t, J));
        for (int i = 0; i < 3; ++i) {
            FalconAngles up = t, down = t;
            up[size_t(i)] += h;
            down[size_t(i)] -= h;
            const Vec3 col =
                (falconForwardKinematics(up, p).position_m - falconForwardKinematics(down, p).position_m) / (2 * h);
            EXPECT_LT(glm::length(J[i] - col), 1e-5 * (1.0 + glm::length(col))) << "column " << i;
        }
    }
}

TEST(FalconKinematics, MotorCommandsFollowTheHdalCalibration) {
    FalconAngles t;
    ASSERT_TRUE(falconInverseKinematics(Vec3(0.0), t));
    // Novint's driver: -12.5 N along z at the centre -> about 700 units each.
    const FalconMotorOutput m = falconMotorCommands(Vec3(0.0), t, Vec3(0.0, 0.0, -12.5));
    ASSERT_TRUE(m.valid);
    EXPECT_FALSE(m.limited);
    for (int16_t c : m.command) EXPECT_NEAR(c, 700, 5);
}

TEST(FalconKinematics, ForcesRoundTripThroughTheMotors) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (const Vec3& p : workspaceGrid(4)) {
        FalconAngles t;
        ASSERT_TRUE(falconInverseKinematics(p, t));
        const Vec3 f = 6.0 * glm::normalize(Vec3(u(rng), u(rng), u(rng)));
        const FalconMotorOutput m = falconMotorCommands(p, t, f);
        ASSERT_TRUE(m.valid);
        ASSERT_FALSE(m.limited);
        // Rounding to whole motor units costs a few hundredths of a newton.
        EXPECT_LT(glm::length(falconForceFromCommands(p, t, m.command) - f), 0.05);
    }
}

TEST(FalconKinematics, CommandLimitScalesTheWholeVectorAndKeepsTheDirection) {
    for (const Vec3& p : workspaceGrid(3)) {
        FalconAngles t;
        ASSERT_TRUE(falconInverseKinematics(p, t));
        const Vec3 f(30.0, -50.0, 20.0);  // far beyond what the motors may give
        const FalconMotorOutput m = falconMotorCommands(p, t, f, kFalconCountsPerNm, 1000);
        ASSERT_TRUE(m.valid);
        EXPECT_TRUE(m.limited);
        int largest = 0;
        for (int16_t c : m.command) largest = std::max(largest, std::abs(int(c)));
        EXPECT_EQ(largest, 1000);
        const Vec3 felt = falconForceFromCommands(p, t, m.command);
        EXPECT_GT(glm::dot(glm::normalize(felt), glm::normalize(f)), 0.9999);
        EXPECT_LT(glm::length(felt), glm::length(f));
    }
}

TEST(FalconKinematics, NonFiniteForceGivesNoCommand) {
    FalconAngles t;
    ASSERT_TRUE(falconInverseKinematics(Vec3(0.0), t));
    const FalconMotorOutput m = falconMotorCommands(Vec3(0.0), t, Vec3(NAN, 0.0, 1.0));
    EXPECT_FALSE(m.valid);
    EXPECT_EQ(m.command, (std::array<int16_t, 3>{0, 0, 0}));
}

TEST(FalconKinematics, TheMotorScaleAgreesWithTheFakesOwnDerivation) {
    // The fake derives its motors' units per N m from Novint's trace (700
    // units for 12.5 N along -z at the centre) through its own mechanism;
    // the driver's constant came from the same trace through the driver's
    // Jacobian. Two derivations, one answer (2218.5 against 2220).
    EXPECT_NEAR(tsf::haptics::testing::fakeMotorUnitsPerNm(), tsf::haptics::kFalconCountsPerNm,
                0.005 * tsf::haptics::kFalconCountsPerNm);
}
