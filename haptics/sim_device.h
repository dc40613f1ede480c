// SimDevice: a simulated force-feedback device with a finger on it, for
// trying fields without hardware and for the closed-loop tests.
//
// Model (device frame, SI): the end-effector and finger are one point mass
// m driven by
//   - the force the loop commands (held constant between writeForce calls,
//     a zero-order hold like a real device),
//   - a scripted hand: a lateral spring-damper (hand_stiffness,
//     hand_damping) pulling x, z toward the script's target, its damping
//     acting on the finger's velocity relative to the target's (a finger
//     keeping pace with the hand is not braked); vertically a press force
//     pushing down, blended (script "lift" weight) with a spring-damper
//     holding the finger at the script's lift height,
//   - an explorer's reflexes while pressing: the hand lifts when the surface
//     resists its travel instead of pushing into a slope (lift_gain N up per
//     N of resistance beyond lift_threshold_N, at most press + lift_excess_N),
//     and it waits for a finger that falls behind: while the finger lags the
//     target by more than max_lead_m, the script runs at waiting_pace, so a
//     finger held at a step is neither dragged nor flung (the script then
//     takes longer than its keyframes say),
//   - the device's own viscous friction (device_damping),
//   - stiff mechanical end stops at the workspace box.
// It is integrated with semi-implicit Euler in sub-steps of at most
// kSimSubstep_s. The device also integrates the work the commanded force
// does on the mass - the energy the rendering put into the hand - which is
// what the passivity tests check.
//
// Scripts are keyframes with linear interpolation (buttons hold the last
// keyframe's value); makeSimScript builds the standard ones over a field's
// footprint: a raster sweep, probing taps, and a finger pressing in place
// then sliding in a circle. The sweep is a boustrophedon raster over the
// whole footprint: given lines (tsf feel gives one per row of printed cells,
// along its centre, so every cell is crossed through its centre) or lines
// kSweepLineSpacing_m apart from edge to edge.
#pragma once

#include <string>
#include <vector>

#include "haptics/field_mapping.h"
#include "haptics/haptic_device.h"

namespace tsf::haptics {

/// Longest integration sub-step of the simulation.
inline constexpr double kSimSubstep_s = 1e-4;

struct SimKeyframe {
    double t_s = 0.0;
    double x_m = 0.0, z_m = 0.0;  ///< hand target, device frame
    double press_N = 0.0;         ///< downward push while not lifting
    double lift = 0.0;            ///< 0 = pressing, 1 = hand holds the finger at lift_y_m
    double lift_y_m = 0.0;
    uint32_t buttons = 0;
};

struct SimScript {
    std::string name;
    std::vector<SimKeyframe> keys;  ///< strictly increasing t_s, at least one
    Vec3 start_m{0.0};              ///< initial finger position
    double duration_s() const { return keys.empty() ? 0.0 : keys.back().t_s; }
};

enum class SimTrajectory { kSweep, kTaps, kFinger };

/// One line of the sweep: at device z, between x_west_m and x_east_m.
struct SweepLine {
    double z_m = 0.0;
    double x_west_m = 0.0, x_east_m = 0.0;
};

/// Sweep line spacing when no lines are given.
inline constexpr double kSweepLineSpacing_m = 0.0015;

/// Parses "sweep", "taps", "finger". Throws tsf::InputError otherwise.
SimTrajectory parseSimTrajectory(const std::string& name);

/// Standard scripts over the footprint of `mapping`. press_N is the hand's
/// downward push while touching. sweep_lines: the sweep's lines, in any
/// order (swept from north to south, alternating direction); empty =
/// kSweepLineSpacing_m apart across the footprint, edge to edge.
SimScript makeSimScript(SimTrajectory kind, const FieldMapping& mapping, double press_N = 1.5,
                        std::vector<SweepLine> sweep_lines = {});

struct FingerParams {
    double mass_kg = 0.15;
    double hand_stiffness_N_per_m = 300.0;
    double hand_damping_Ns_per_m = 12.0;
    double device_damping_Ns_per_m = 0.5;
    double stop_stiffness_N_per_m = 20000.0;  ///< mechanical end stops
    double stop_damping_Ns_per_m = 20.0;
    double lift_gain = 4.0;                   ///< upward N per N of resistance to the hand's travel (0 = off)
    double lift_threshold_N = 0.5;            ///< resistance below this (friction) does not lift the hand
    double lift_excess_N = 0.5;               ///< the lift exceeds the press by at most this (no launching)
    double max_lead_m = 0.003;                ///< the hand slows down when the finger lags it by more...
    double waiting_pace = 0.1;                ///< ...to this fraction of the script's pace
};

class SimDevice final : public HapticDevice {
public:
    SimDevice(SimScript script, DeviceLimits limits = {}, FingerParams finger = {});

    std::string name() const override { return "sim:" + script_.name; }
    DeviceLimits limits() const override { return limits_; }
    bool needsRealtime() const override { return false; }
    void open() override {}
    void close() noexcept override { force_ = Vec3(0.0); }
    ReadStatus read(double loop_time_s, DeviceState& out) noexcept override;
    bool writeForce(const Vec3& force_N) noexcept override;

    /// Work done by the commanded force on the finger so far, joules, and the
    /// largest value it reached (> 0 means the rendering fed energy in).
    double deviceWork_J() const { return work_J_; }
    double maxDeviceWork_J() const { return max_work_J_; }
    Vec3 velocity() const { return v_; }
    Vec3 position() const { return p_; }
    double time() const { return t_; }

private:
    void step(double dt) noexcept;
    SimKeyframe targetAt(double t) noexcept;
    /// Velocity (x, z) of the hand's target at t.
    Vec3 travelAt(double t) noexcept;

    SimScript script_;
    DeviceLimits limits_;
    FingerParams finger_;
    double t_ = 0.0;
    double script_t_ = 0.0;  ///< the script's own time: slower than t_ while the hand waits
    Vec3 p_{0.0}, v_{0.0}, force_{0.0};
    double work_J_ = 0.0, max_work_J_ = 0.0;
    size_t key_cursor_ = 0;
};

}  // namespace tsf::haptics
