// HapticDevice: the small interface every force-feedback device implements -
// the simulated finger (sim_device.h), a recorded session (replay_device.h),
// and the Novint Falcon over libusb (falcon/falcon_device.h).
//
// Frame and units: positions in metres and forces in newtons in the device
// frame of frames.h (x right, y up, z toward the user, origin at the
// workspace centre). A driver converts from its own encoder/motor units and
// subtracts its mechanical workspace origin.
//
// Threading: open() and close() run on the main thread; read() and
// writeForce() run on the haptic thread only, once per tick, and are
// noexcept, allocation-free and never block for long (a real driver does one
// USB round trip). close() must leave the device applying zero force.
//
// Safety contract for drivers: writeForce() receives forces already clamped
// to limits().max_force_N; a driver clamps again in its own units anyway
// (scaling the whole vector, keeping its direction) and must refuse forces
// before the device is homed.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>

#include "haptics/frames.h"

namespace tsf::haptics {

/// Button bits of DeviceState::buttons (the Falcon's four grip buttons).
inline constexpr uint32_t kButtonPlus = 0x1;     ///< right button: coarser level of detail
inline constexpr uint32_t kButtonForward = 0x2;  ///< top button: unused
inline constexpr uint32_t kButtonCentre = 0x4;   ///< centre button: volume mode on/off
inline constexpr uint32_t kButtonMinus = 0x8;    ///< left button: finer level of detail

/// What a device can safely do. CHAI3D's Falcon figures are the defaults.
struct DeviceLimits {
    double max_force_N = 8.0;                ///< largest force magnitude the device may be asked for
    double max_stiffness_N_per_m = 3000.0;   ///< largest stable rendered stiffness at rated_rate_Hz
    double max_damping_Ns_per_m = 20.0;      ///< largest stable virtual damping
    double rated_rate_Hz = 1000.0;           ///< servo rate the two figures above were rated at
    WorkspaceBox workspace{{-0.03, -0.03, -0.03}, {0.03, 0.03, 0.03}};  ///< reachable box, metres
};

/// One reading of the device.
struct DeviceState {
    double t_s = 0.0;       ///< time of the reading on the loop's clock
    Vec3 position_m{0.0};   ///< end-effector position, device frame
    uint32_t buttons = 0;   ///< kButton* bits, 1 = pressed
    bool homed = true;      ///< false until a device with relative encoders has found its origin
    /// Ticks since the device last reported a new position (0: this reading
    /// is new). A device that always has one leaves it 0.
    uint32_t stale_ticks = 0;
};

enum class ReadStatus {
    kOk,      ///< out holds a fresh reading
    kEnded,   ///< a recording or script has no more samples (normal end)
    kFailed,  ///< the device stopped answering
};

/// A device could not be opened or used; message() is for a person.
class DeviceError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

class HapticDevice {
public:
    virtual ~HapticDevice() = default;

    /// Short name for reports ("sim:sweep", "replay:FILE", "falcon").
    virtual std::string name() const = 0;
    virtual DeviceLimits limits() const = 0;
    /// True for hardware that must be served in real time; false for
    /// simulations that may run faster than real time.
    virtual bool needsRealtime() const = 0;

    /// Connects and prepares the device. Throws DeviceError.
    virtual void open() = 0;
    /// Leaves the device applying zero force and releases it. Idempotent.
    virtual void close() noexcept = 0;

    /// Reads the state at loop time loop_time_s (simulations advance to that
    /// time; hardware may ignore it and stamp its own time on out.t_s).
    virtual ReadStatus read(double loop_time_s, DeviceState& out) noexcept = 0;
    /// Commands a force, held until the next call. False when the device did
    /// not accept it.
    virtual bool writeForce(const Vec3& force_N) noexcept = 0;
    /// Makes the device hold zero force now, as far as it can confirm it,
    /// and stay open (before the process is stopped: a pause). Default: a
    /// zero writeForce.
    virtual void holdZero() noexcept { writeForce(Vec3(0.0)); }
    /// What the rendering is doing, for a device that can show it (the
    /// Falcon's LEDs); called by the loop after each tick's force. Default:
    /// nothing.
    virtual void showStatus(bool in_contact, bool volume_mode) noexcept {}
    /// Why read() returned kFailed, for a person ("" when unknown).
    virtual std::string failureReason() const { return {}; }
};

}  // namespace tsf::haptics
