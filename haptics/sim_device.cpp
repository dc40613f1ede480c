#include "haptics/sim_device.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "gen/util/error.h"

namespace tsf::haptics {
namespace {

/// Speeds and timings of the standard scripts: slow enough to feel, like a
/// careful explorer (thesis 6.2: participants moved at a few cm/s).
constexpr double kSweepSpeed_m_per_s = 0.03;
constexpr int kTapsPerSide = 4;
/// At the end of each sweep line the hand eases its press to this fraction
/// over kSweepDwell_s, so the finger, held back by static friction, catches
/// up; it presses again kSweepEase_s into the next line.
constexpr double kSweepEasedPress = 0.2;
constexpr double kSweepDwell_s = 0.1;
constexpr double kSweepEase_s = 0.05;
constexpr double kLiftClearance_m = 0.005;
/// Every script starts with the finger held still above the surface for this
/// long: the loop ramps the force in over its first second (haptic_loop.h),
/// and a user is told to rest the grip before touching anything.
constexpr double kLeadIn_s = 1.0;

double lerp(double a, double b, double f) { return a + (b - a) * f; }

}  // namespace

SimTrajectory parseSimTrajectory(const std::string& name) {
    if (name == "sweep") return SimTrajectory::kSweep;
    if (name == "taps") return SimTrajectory::kTaps;
    if (name == "finger") return SimTrajectory::kFinger;
    throw InputError("--trajectory must be sweep, taps or finger (got '" + name + "')");
}

SimScript makeSimScript(SimTrajectory kind, const FieldMapping& m, double press_N, std::vector<SweepLine> sweep_lines) {
    SimScript s;
    const double margin = 0.05 * std::min(m.eastX() - m.west_x_m, m.south_z_m - m.northZ());
    const double x0 = m.west_x_m + margin, x1 = m.eastX() - margin;
    const double z0 = m.northZ() + margin, z1 = m.south_z_m - margin;
    // Sweeps and the finger lift just clear of the highest surface; taps and
    // the lead-in lift above the volume slab, so volume-mode taps go through
    // every level and nothing touches the finger while forces ramp in.
    const double near_y = m.volume_bottom_y_m + kLiftClearance_m;
    const double high_y = m.volume_top_y_m + kLiftClearance_m;
    double lift_y = kind == SimTrajectory::kTaps ? high_y : near_y;
    auto key = [&](double t, double x, double z, double press, double lift) {
        s.keys.push_back({t, x, z, press, lift, lift_y, 0u});
    };
    double t = kLeadIn_s;
    switch (kind) {
    case SimTrajectory::kSweep: {
        s.name = "sweep";
        const double light_N = kSweepEasedPress * press_N;
        if (sweep_lines.empty()) {
            // Edge to edge, a hair inside the border so the finger stays over the field.
            const double inset = 0.25 * kSweepLineSpacing_m;
            const double depth = m.south_z_m - m.northZ();
            const int lines = std::max(1, int(std::ceil(depth / kSweepLineSpacing_m)));
            for (int k = 0; k < lines; ++k)
                sweep_lines.push_back({m.northZ() + depth * (k + 0.5) / lines, m.west_x_m + inset, m.eastX() - inset});
        }
        std::sort(sweep_lines.begin(), sweep_lines.end(),
                  [](const SweepLine& a, const SweepLine& b) { return a.z_m < b.z_m; });  // north first
        key(t, sweep_lines.front().x_west_m, sweep_lines.front().z_m, press_N, 1.0);
        lift_y = near_y;
        t += 0.5;
        for (size_t line = 0; line < sweep_lines.size(); ++line) {
            const SweepLine& l = sweep_lines[line];
            const bool east = line % 2 == 0;
            const double from = east ? l.x_west_m : l.x_east_m, to = east ? l.x_east_m : l.x_west_m;
            if (line == 0) {
                key(t, from, l.z_m, press_N, 0.0);  // put the finger down
                t += 0.5;                           // and let it settle
            } else {
                const SimKeyframe& prev = s.keys.back();
                t += std::max(kSweepEase_s, std::hypot(from - prev.x_m, l.z_m - prev.z_m) / kSweepSpeed_m_per_s);
                key(t, from, l.z_m, light_N, 0.0);
                t += kSweepEase_s;
            }
            key(t, from, l.z_m, press_N, 0.0);
            t += std::max(0.01, std::abs(to - from) / kSweepSpeed_m_per_s);
            key(t, to, l.z_m, press_N, 0.0);
            // Static friction holds the finger until the hand spring pulls
            // harder than mu_s * press (1.5 mm behind at the defaults): at
            // each line's end the hand eases its press so the finger slides
            // the rest of the way, and moves to the next line so.
            t += kSweepDwell_s;
            key(t, to, l.z_m, light_N, 0.0);
        }
        const SimKeyframe last = s.keys.back();
        t += 0.5;
        key(t, last.x_m, last.z_m, press_N, 1.0);
        break;
    }
    case SimTrajectory::kTaps: {
        s.name = "taps";
        for (int row = 0; row < kTapsPerSide; ++row)
            for (int col = 0; col < kTapsPerSide; ++col) {
                const double x = lerp(x0, x1, (col + 0.5) / kTapsPerSide);
                const double z = lerp(z0, z1, (row + 0.5) / kTapsPerSide);
                key(t, x, z, press_N, 1.0);  // arrive lifted
                t += 0.3;
                key(t, x, z, press_N, 1.0);
                t += 0.05;
                key(t, x, z, press_N, 0.0);  // drop onto the surface
                t += 0.4;
                key(t, x, z, press_N, 0.0);
                t += 0.05;
                key(t, x, z, press_N, 1.0);  // lift off
                t += 0.3;
            }
        break;
    }
    case SimTrajectory::kFinger: {
        s.name = "finger";
        const double cx = 0.5 * (x0 + x1), cz = 0.5 * (z0 + z1);
        const double r = 0.25 * std::min(x1 - x0, z1 - z0);
        const double peak = 2.0 * press_N;
        key(t, cx, cz, 0.0, 1.0);
        lift_y = near_y;
        t += 0.5;
        key(t, cx, cz, 0.0, 0.0);
        t += 2.0;
        key(t, cx, cz, peak, 0.0);  // press harder and harder
        t += 1.0;
        key(t, cx, cz, peak, 0.0);
        t += 0.5;
        key(t, cx + r, cz, press_N, 0.0);
        constexpr int kCircleKeys = 36;
        const double lap_s = 2.0 * std::numbers::pi * r / kSweepSpeed_m_per_s;
        for (int k = 1; k <= kCircleKeys; ++k) {
            const double a = 2.0 * std::numbers::pi * k / kCircleKeys;
            t += lap_s / kCircleKeys;
            key(t, cx + r * std::cos(a), cz + r * std::sin(a), press_N, 0.0);
        }
        t += 1.0;
        key(t, cx + r, cz, 0.0, 0.0);
        t += 0.5;
        key(t, cx + r, cz, 0.0, 1.0);
        break;
    }
    }
    SimKeyframe first = s.keys.front();
    first.t_s = 0.0;
    first.lift = 1.0;
    first.lift_y_m = high_y;
    s.keys.insert(s.keys.begin(), first);
    s.start_m = Vec3(first.x_m, first.lift_y_m, first.z_m);
    return s;
}

SimDevice::SimDevice(SimScript script, DeviceLimits limits, FingerParams finger)
    : script_(std::move(script)), limits_(limits), finger_(finger) {
    assert(!script_.keys.empty());
    for ([[maybe_unused]] size_t k = 1; k < script_.keys.size(); ++k)
        assert(script_.keys[k].t_s > script_.keys[k - 1].t_s);
    p_ = script_.start_m;
}

Vec3 SimDevice::travelAt(double t) noexcept {
    const auto& keys = script_.keys;
    if (t <= keys.front().t_s || t >= keys.back().t_s) return Vec3(0.0);
    targetAt(t);  // moves key_cursor_ to the segment holding t
    const SimKeyframe& a = keys[key_cursor_];
    const SimKeyframe& b = keys[key_cursor_ + 1];
    return Vec3(b.x_m - a.x_m, 0.0, b.z_m - a.z_m) / (b.t_s - a.t_s);
}

SimKeyframe SimDevice::targetAt(double t) noexcept {
    const auto& keys = script_.keys;
    if (t <= keys.front().t_s) return keys.front();
    if (t >= keys.back().t_s) return keys.back();
    if (keys[key_cursor_].t_s > t) key_cursor_ = 0;
    while (key_cursor_ + 1 < keys.size() && keys[key_cursor_ + 1].t_s <= t) ++key_cursor_;
    const SimKeyframe& a = keys[key_cursor_];
    const SimKeyframe& b = keys[key_cursor_ + 1];
    const double f = (t - a.t_s) / (b.t_s - a.t_s);
    SimKeyframe k;
    k.t_s = t;
    k.x_m = lerp(a.x_m, b.x_m, f);
    k.z_m = lerp(a.z_m, b.z_m, f);
    k.press_N = lerp(a.press_N, b.press_N, f);
    k.lift = lerp(a.lift, b.lift, f);
    k.lift_y_m = lerp(a.lift_y_m, b.lift_y_m, f);
    k.buttons = a.buttons;
    return k;
}

void SimDevice::step(double dt) noexcept {
    const SimKeyframe k = targetAt(script_t_);
    const FingerParams& f = finger_;
    Vec3 hand(0.0);
    // The hand waits for a finger that falls behind (held at a step, say)
    // instead of dragging it: its script runs slower while the finger lags.
    const double lead = std::hypot(k.x_m - p_.x, k.z_m - p_.z);
    const double pace = k.lift < 1.0 && lead > f.max_lead_m ? f.waiting_pace : 1.0;
    const Vec3 travel = pace * travelAt(script_t_);  // the hand's own velocity (x, z)
    hand.x = f.hand_stiffness_N_per_m * (k.x_m - p_.x) + f.hand_damping_Ns_per_m * (travel.x - v_.x);
    hand.z = f.hand_stiffness_N_per_m * (k.z_m - p_.z) + f.hand_damping_Ns_per_m * (travel.z - v_.z);
    hand.y = -(1.0 - k.lift) * k.press_N + k.lift * f.hand_stiffness_N_per_m * (k.lift_y_m - p_.y) -
             f.hand_damping_Ns_per_m * v_.y;
    // Lift when the surface pushes back against the hand's travel.
    const double speed = glm::length(travel);
    const double resisting = speed > 0.0 ? -glm::dot(force_, travel) / speed : 0.0;
    hand.y += (1.0 - k.lift) * std::min(k.press_N + f.lift_excess_N,
                                        f.lift_gain * std::max(0.0, resisting - f.lift_threshold_N));
    Vec3 stop(0.0);
    const WorkspaceBox& box = limits_.workspace;
    for (int a = 0; a < 3; ++a) {
        const double below = box.min_m[a] - p_[a], above = p_[a] - box.max_m[a];
        if (below > 0.0) stop[a] = f.stop_stiffness_N_per_m * below - f.stop_damping_Ns_per_m * std::min(v_[a], 0.0);
        if (above > 0.0) stop[a] = -f.stop_stiffness_N_per_m * above - f.stop_damping_Ns_per_m * std::max(v_[a], 0.0);
    }
    const Vec3 total = force_ + hand + stop - f.device_damping_Ns_per_m * v_;
    v_ += total * (dt / f.mass_kg);
    const Vec3 dp = v_ * dt;
    work_J_ += glm::dot(force_, dp);
    max_work_J_ = std::max(max_work_J_, work_J_);
    p_ += dp;
    t_ += dt;
    script_t_ += pace * dt;
}

ReadStatus SimDevice::read(double loop_time_s, DeviceState& out) noexcept {
    // Sub-steps until the loop time (or the script's end); a remainder below
    // a nanosecond is not worth a step (and could be below the resolution of t_).
    constexpr double kTimeResolution_s = 1e-9;
    while (loop_time_s - t_ > kTimeResolution_s && script_t_ <= script_.duration_s())
        step(std::min(kSimSubstep_s, loop_time_s - t_));
    if (script_t_ > script_.duration_s()) return ReadStatus::kEnded;
    out.t_s = t_;
    out.position_m = p_;
    out.buttons = targetAt(script_t_).buttons;
    out.homed = true;
    return ReadStatus::kOk;
}

bool SimDevice::writeForce(const Vec3& force_N) noexcept {
    const double m = glm::length(force_N);
    if (!std::isfinite(m) || m > limits_.max_force_N * (1.0 + 1e-9)) {
        force_ = Vec3(0.0);  // a real driver refuses too
        return false;
    }
    force_ = force_N;
    return true;
}

}  // namespace tsf::haptics
