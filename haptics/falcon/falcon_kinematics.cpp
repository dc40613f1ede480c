#include "haptics/falcon/falcon_kinematics.h"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace tsf::haptics {
namespace {

// Geometry (metres, radians); see the header.
constexpr double kA = 0.060, kB = 0.1025, kC = 0.01443, kD = 0.01125, kE = 0.01125, kF = -0.025;
constexpr double kR = 0.040, kS = -0.02309;
constexpr double kDeg = 3.14159265358979323846 / 180.0;
constexpr std::array<double, 3> kPhi{105.0 * kDeg, -15.0 * kDeg, -135.0 * kDeg};

/// The parallelogram's out-of-plane component (v + f) / b must stay inside
/// (-1, 1); this far from +-1 the leg is treated as out of reach (the
/// derivative of its in-plane reach grows without bound there).
constexpr double kReachMargin = 1e-6;
/// A pivot below this (in the Jacobian's units) is a singular pose.
constexpr double kSingularDet = 1e-12;
/// A solution farther than this from the workspace centre is not the
/// Falcon's assembly mode (the real workspace is about +-60 mm).
constexpr double kPlausibleRadius_m = 0.1;
/// The other elbow configuration is tens of degrees away; a converged
/// solution of the right one matches to far below a count.
constexpr double kSameBranch_rad = 10.0 * kFalconRadPerCount;

Vec3 toMechanism(const Vec3& p) { return {p.x, p.y, p.z + kFalconWorkspaceCentreZ_m}; }

/// One leg's closure g_i, its gradient in p (mechanism = device axes) and
/// its derivative in theta_i. False when the leg is out of reach.
struct Leg {
    double g = 0.0;
    Vec3 dg_dp{0.0};
    double dg_dtheta = 0.0;
};

/// The probe seen from leg i: its frame's axes (cos, sin of phi), the
/// in-plane coordinates u, w, the parallelogram's out-of-plane ratio
/// q = (v + f) / b and its in-plane reach d + e + b sqrt(1 - q^2).
struct LegView {
    double cp = 0.0, sp = 0.0, u = 0.0, w = 0.0, q = 0.0, root = 0.0, reach = 0.0;
};

/// False when the leg cannot reach p (the parallelogram would have to be
/// longer than b out of its plane).
bool viewFromLeg(int i, const Vec3& p_mech, LegView& l) noexcept {
    l.cp = std::cos(kPhi[size_t(i)]);
    l.sp = std::sin(kPhi[size_t(i)]);
    l.u = l.cp * p_mech.x + l.sp * p_mech.y - kR;
    const double v = -l.sp * p_mech.x + l.cp * p_mech.y - kS;
    l.w = p_mech.z;
    l.q = (v + kF) / kB;
    if (!(std::abs(l.q) < 1.0 - kReachMargin)) return false;
    l.root = std::sqrt(1.0 - l.q * l.q);
    l.reach = kD + kE + kB * l.root;
    return true;
}

bool evalLeg(int i, const Vec3& p_mech, double theta, Leg& out) noexcept {
    LegView l;
    if (!viewFromLeg(i, p_mech, l)) return false;
    const double U = l.u + kC - kA * std::cos(theta), W = l.w - kA * std::sin(theta);
    const double rho = std::hypot(U, W);
    if (!(rho > 0.0)) return false;
    out.g = rho - l.reach;
    const double dg_du = U / rho, dg_dv = l.q / l.root, dg_dw = W / rho;
    out.dg_dp = Vec3(dg_du * l.cp - dg_dv * l.sp, dg_du * l.sp + dg_dv * l.cp, dg_dw);
    out.dg_dtheta = kA * (U * std::sin(theta) - W * std::cos(theta)) / rho;
    return std::isfinite(out.g) && std::isfinite(out.dg_dtheta);
}

/// All three legs; G has the gradients as ROWS (glm is column-major, so
/// G[col][row]).
bool evalLegs(const Vec3& p_mech, const FalconAngles& theta, Vec3& g, glm::dmat3& G, Vec3& dg_dtheta) noexcept {
    for (int i = 0; i < 3; ++i) {
        Leg l;
        if (!evalLeg(i, p_mech, theta[size_t(i)], l)) return false;
        g[i] = l.g;
        dg_dtheta[i] = l.dg_dtheta;
        for (int k = 0; k < 3; ++k) G[k][i] = l.dg_dp[k];
    }
    return true;
}

double maxAbs(const Vec3& v) { return std::max({std::abs(v.x), std::abs(v.y), std::abs(v.z)}); }

bool finite(const Vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

bool inverseMechanism(const Vec3& p, FalconAngles& out) noexcept {
    if (!finite(p)) return false;
    FalconAngles th;
    for (int i = 0; i < 3; ++i) {
        LegView l;
        if (!viewFromLeg(i, p, l)) return false;
        // |(U0 - a cos t, w - a sin t)| = reach  <=>  R cos(t - alpha) = M.
        const double U0 = l.u + kC;
        const double R = std::hypot(U0, l.w);
        const double M = (U0 * U0 + l.w * l.w + kA * kA - l.reach * l.reach) / (2.0 * kA);
        if (!(R > 0.0) || !(std::abs(M) <= R)) return false;
        // The Falcon's configuration is the smaller of the two angles
        // (libnifalcon's "-" root of the same equation).
        th[size_t(i)] = std::atan2(l.w, U0) - std::acos(M / R);
    }
    out = th;
    return true;
}

/// A solution of g = 0 is the Falcon's pose only near the workspace and with
/// every knee bent the Falcon's way: g alone cannot tell the two elbow
/// configurations of a leg apart, so the angles must be the ones
/// falconInverseKinematics gives for the point.
bool isFalconPose(const Vec3& p_mech, const FalconAngles& theta) noexcept {
    if (glm::length(p_mech - Vec3(0.0, 0.0, kFalconWorkspaceCentreZ_m)) > kPlausibleRadius_m) return false;
    FalconAngles back;
    if (!inverseMechanism(p_mech, back)) return false;
    for (size_t i = 0; i < 3; ++i)
        if (!(std::abs(back[i] - theta[i]) < kSameBranch_rad)) return false;
    return true;
}

/// Newton from `start` (mechanism frame). True with p_out on convergence.
bool newton(const FalconAngles& theta, Vec3 p, Vec3& p_out, int& iterations) noexcept {
    Vec3 g, dth;
    glm::dmat3 G;
    if (!evalLegs(p, theta, g, G, dth)) return false;
    for (int it = 0; it < kFalconFkMaxIterations; ++it) {
        ++iterations;
        if (std::abs(glm::determinant(G)) < kSingularDet) return false;
        Vec3 step = -(glm::inverse(G) * g);
        if (!finite(step)) return false;
        const double len = glm::length(step);
        if (len > kFalconFkMaxStep_m) step *= kFalconFkMaxStep_m / len;
        // Halve the step until the residual drops (at most 4 times).
        const double r0 = maxAbs(g);
        bool accepted = false;
        for (int half = 0; half < 5 && !accepted; ++half, step *= 0.5) {
            Vec3 g1, d1;
            glm::dmat3 G1;
            const Vec3 p1 = p + step;
            if (evalLegs(p1, theta, g1, G1, d1) && (maxAbs(g1) < r0 || r0 <= kFalconFkTolerance_m)) {
                p = p1;
                g = g1;
                G = G1;
                accepted = true;
                if (glm::length(step) < kFalconFkTolerance_m && maxAbs(g) < kFalconFkTolerance_m) {
                    if (!isFalconPose(p, theta)) return false;
                    p_out = p;
                    return true;
                }
            }
        }
        if (!accepted) return false;
    }
    return false;
}

}  // namespace

double falconEncoderToAngle(int16_t counts) noexcept { return double(counts) * kFalconRadPerCount + kFalconAngleAtZero_rad; }

double falconAngleToEncoder(double angle_rad) noexcept { return (angle_rad - kFalconAngleAtZero_rad) / kFalconRadPerCount; }

bool falconInverseKinematics(const Vec3& p_m, FalconAngles& out) noexcept {
    return inverseMechanism(toMechanism(p_m), out);
}

FalconFkResult falconForwardKinematics(const FalconAngles& theta, const Vec3& guess_m) noexcept {
    FalconFkResult r;
    Vec3 p;
    const bool angles_ok = std::isfinite(theta[0]) && std::isfinite(theta[1]) && std::isfinite(theta[2]);
    if (angles_ok && finite(guess_m) && newton(theta, toMechanism(guess_m), p, r.iterations)) {
        r.converged = true;
    } else if (angles_ok && newton(theta, toMechanism(Vec3(0.0)), p, r.iterations)) {
        r.converged = true;
        r.cold_start = true;
    }
    if (r.converged) {
        r.position_m = Vec3(p.x, p.y, p.z - kFalconWorkspaceCentreZ_m);
        return r;
    }
    Vec3 keep = finite(guess_m) ? guess_m : Vec3(0.0);
    const double len = glm::length(keep);
    if (len > kPlausibleRadius_m) keep *= kPlausibleRadius_m / len;
    r.position_m = keep;
    return r;
}

bool falconJacobian(const Vec3& p_m, const FalconAngles& theta, glm::dmat3& J) noexcept {
    if (!finite(p_m)) return false;
    Vec3 g, dth;
    glm::dmat3 G;
    if (!evalLegs(toMechanism(p_m), theta, g, G, dth)) return false;
    if (std::abs(glm::determinant(G)) < kSingularDet) return false;
    // G dp + diag(dth) dtheta = 0  =>  dp/dtheta = -G^-1 diag(dth).
    const glm::dmat3 Ginv = glm::inverse(G);
    for (int i = 0; i < 3; ++i) J[i] = -Ginv[i] * dth[i];
    for (int i = 0; i < 3; ++i)
        if (!finite(J[i])) return false;
    return true;
}

FalconMotorOutput falconMotorCommands(const Vec3& p_m, const FalconAngles& theta, const Vec3& force_N,
                                      double counts_per_Nm, int max_command) noexcept {
    FalconMotorOutput out;
    glm::dmat3 J;
    if (!finite(force_N) || !falconJacobian(p_m, theta, J)) {
        out.valid = false;
        return out;
    }
    const Vec3 tau = glm::transpose(J) * force_N;  // N m per thigh
    Vec3 c = -counts_per_Nm * tau;
    const double largest = maxAbs(c);
    if (!std::isfinite(largest)) {
        out.valid = false;
        return out;
    }
    if (largest > double(max_command)) {
        c *= double(max_command) / largest;
        out.limited = true;
    }
    for (int i = 0; i < 3; ++i) out.command[size_t(i)] = int16_t(std::lround(std::clamp(c[i], -double(max_command), double(max_command))));
    return out;
}

Vec3 falconForceFromCommands(const Vec3& p_m, const FalconAngles& theta, const std::array<int16_t, 3>& command,
                             double counts_per_Nm) noexcept {
    glm::dmat3 J;
    if (!falconJacobian(p_m, theta, J)) return Vec3(0.0);
    const glm::dmat3 Jt = glm::transpose(J);
    if (std::abs(glm::determinant(Jt)) < kSingularDet * 1e-6) return Vec3(0.0);
    const Vec3 tau(-double(command[0]) / counts_per_Nm, -double(command[1]) / counts_per_Nm,
                   -double(command[2]) / counts_per_Nm);
    const Vec3 f = glm::inverse(Jt) * tau;
    return finite(f) ? f : Vec3(0.0);
}

}  // namespace tsf::haptics
