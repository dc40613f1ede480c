#include "tests/haptics/fake_falcon_mechanism.h"

#include <cmath>

namespace tsf::haptics::testing {
namespace {

constexpr double kPi = 3.14159265358979323846;
// Stamper's lengths for the Falcon (metres): thigh a, parallelogram side b,
// platform offsets c (in the leg's plane) and f (out of it), the two joint
// offsets d and e, the leg base at (r, s) in the leg's frame.
constexpr double a = 0.060, b = 0.1025, c = 0.01443, d = 0.01125, e = 0.01125, f = -0.025;
constexpr double r = 0.040, s = -0.02309;
// Legs at 90, -30 and -150 degrees about z, each tilted 15 degrees more.
constexpr double kLegPhi[3] = {kPi / 2 + kPi / 12, -kPi / 6 + kPi / 12, -5 * kPi / 6 + kPi / 12};
// Encoder: 320 slots read on both edges of two channels, on a 14.25 mm
// shaft that drives a 110 mm arm sector; count 0 at 35 degrees.
constexpr double kCountsPerShaftTurn = 320.0 * 4.0;
constexpr double kShaftToArm = 0.01425 / 0.110;
constexpr double kAngleAtCountZero = 35.0 * kPi / 180.0;

bool legAngle(int leg, double x, double y, double z, double& theta) {
    const double cp = std::cos(kLegPhi[leg]), sp = std::sin(kLegPhi[leg]);
    // The grip in the leg's frame: rotated by -phi, then moved to the leg's base.
    const double u = cp * x + sp * y - r, v = -sp * x + cp * y - s, w = z;
    const double cos3 = (v + f) / b;
    if (!(std::abs(cos3) < 1.0)) return false;
    const double theta3 = std::acos(cos3);
    // |knee -> platform joint| in the leg's plane equals d + e + b sin(theta3):
    //   (u + c - a cos t)^2 + (w - a sin t)^2 = K^2,
    // with tan(t / 2) = T this is l2 T^2 + l1 T + l0 = 0.
    const double K = d + e + b * std::sin(theta3), U = u + c;
    const double base = U * U + w * w + a * a - K * K;
    const double l0 = base - 2 * a * U, l1 = -4 * a * w, l2 = base + 2 * a * U;
    const double disc = l1 * l1 - 4 * l0 * l2;
    if (!(disc >= 0.0) || l2 == 0.0) return false;
    // The Falcon's knees bend the way of the smaller root.
    theta = 2.0 * std::atan((-l1 - std::sqrt(disc)) / (2 * l2));
    return std::isfinite(theta);
}

/// d theta_i / d p_k at p (row i, column k); false out of reach.
bool angleRates(const Vec3& p, double D[3][3]) noexcept {
    constexpr double h = 1e-6;
    for (int k = 0; k < 3; ++k) {
        Vec3 lo = p, hi = p;
        lo[k] -= h;
        hi[k] += h;
        std::array<double, 3> t_lo, t_hi;
        if (!fakeThighAngles(lo, t_lo) || !fakeThighAngles(hi, t_hi)) return false;
        for (int i = 0; i < 3; ++i) D[i][k] = (t_hi[size_t(i)] - t_lo[size_t(i)]) / (2 * h);
    }
    return true;
}

double det3(const double m[3][3]) {
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

double computeMotorUnitsPerNm() noexcept {
    // F = D^T tau (virtual work): solve for tau with F = 12.5 N along -z.
    double D[3][3];
    if (!angleRates(Vec3(0.0), D)) return 0.0;
    double A[3][3];
    for (int r = 0; r < 3; ++r)
        for (int c = 0; c < 3; ++c) A[r][c] = D[c][r];
    const double F[3] = {0.0, 0.0, -12.5};
    const double d = det3(A);
    double mean_abs_tau = 0.0;
    for (int i = 0; i < 3; ++i) {
        double Ai[3][3];
        for (int r = 0; r < 3; ++r)
            for (int c = 0; c < 3; ++c) Ai[r][c] = c == i ? F[r] : A[r][c];
        mean_abs_tau += std::abs(det3(Ai) / d) / 3.0;
    }
    constexpr double kHdalUnits = 700.0;  // each motor, for that push
    return kHdalUnits / mean_abs_tau;
}

}  // namespace

double fakeMotorUnitsPerNm() noexcept {
    static const double units = computeMotorUnitsPerNm();
    return units;
}

bool fakeThighAngles(const Vec3& p, std::array<double, 3>& theta) noexcept {
    std::array<double, 3> t{};
    for (int leg = 0; leg < 3; ++leg)
        if (!legAngle(leg, p.x, p.y, p.z + kFakeWorkspaceCentreZ_m, t[size_t(leg)])) return false;
    theta = t;
    return true;
}

int16_t fakeEncoderCount(double theta) noexcept {
    const double shaft_turns = (theta - kAngleAtCountZero) / (2 * kPi) / kShaftToArm;
    return int16_t(std::lround(shaft_turns * kCountsPerShaftTurn));
}

Vec3 fakeMotorForce(const Vec3& p, const std::array<int16_t, 3>& motor) noexcept {
    // Virtual work: tau . dtheta = F . dp for every small motion, so
    // F_k = sum_i tau_i d theta_i / d p_k.
    constexpr double h = 1e-6;
    double tau[3];
    for (int i = 0; i < 3; ++i) tau[i] = -double(motor[size_t(i)]) / fakeMotorUnitsPerNm();
    Vec3 force(0.0);
    for (int k = 0; k < 3; ++k) {
        Vec3 lo = p, hi = p;
        lo[k] -= h;
        hi[k] += h;
        std::array<double, 3> t_lo, t_hi;
        if (!fakeThighAngles(lo, t_lo) || !fakeThighAngles(hi, t_hi)) return Vec3(0.0);
        for (int i = 0; i < 3; ++i) force[k] += tau[i] * (t_hi[size_t(i)] - t_lo[size_t(i)]) / (2 * h);
    }
    return force;
}

}  // namespace tsf::haptics::testing
