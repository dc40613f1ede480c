// FalconDevice: the Novint Falcon as a HapticDevice (haptic_device.h), over
// any UsbTransport (libusb_transport.h on hardware, a fake in the tests).
//
// open() (main thread; throws DeviceError with what to do):
//   opens the transport, puts the FTDI link in normal mode and checks
//   whether firmware already runs (it survives until the power goes); if
//   not, loads the image given in FalconOptions::firmware (falcon_firmware.h)
//   or says that --firmware is needed.
// Each tick (haptic thread; noexcept, no allocation, no locks):
//   read()        if a packet is in flight, one bulk read (at most
//                 tick_read_timeout_ms); frames are parsed and resynchronised
//                 (falcon_packet.h); the newest one gives encoder counts,
//                 buttons and the homed flags; counts -> angles -> position
//                 by the warm-started Newton solve (falcon_kinematics.h).
//   writeForce()  force -> motor commands (J^T F, scaled to the command
//                 limit); one packet is sent if none is in flight (or the
//                 one in flight is presumed lost after resend_after_ticks).
//   So exactly one packet is ever in flight, and the device is talked to on
//   every tick, force or not (the link drops if packets stop).
//
// Safety:
//   - homing: every packet carries the homing bit; until all three motors
//     report homed, positions are not computed and every motor command is 0,
//     and writeForce refuses (returns false for) any nonzero force;
//   - the force is clamped to limits().max_force_N, then the motor vector is
//     scaled down as a whole to the command limit (direction kept);
//   - a pose where the solver fell back, a singular Jacobian or a non-finite
//     force sends zero motor commands;
//   - a position that stops updating is not pushed on: after
//     stale_ticks_to_zero ticks without a frame every motor command is 0
//     until a frame comes again (a tick or two of USB jitter keeps the force);
//   - holdZero() (a pause) exchanges close_packets zero packets and keeps
//     the link; read() reports how many ticks the position is old
//     (DeviceState::stale_ticks: the loop restarts its start ramp after a
//     stall);
//   - close() (and the destructor) sends zero commands before releasing the
//     device, also after a failure: to a device that stopped answering it
//     writes them without waiting for replies, so the last command the
//     Falcon holds is zero whenever it can still hear; a vanished device or
//     silent_ticks_to_fail ticks without a frame makes read() return kFailed,
//     and the loop ends with zero force.
//
// LEDs show the state: red = not homed (no force), green = homed, blue =
// touching the surface, green + blue = volume mode.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "haptics/falcon/falcon_firmware.h"
#include "haptics/falcon/falcon_kinematics.h"
#include "haptics/falcon/falcon_packet.h"
#include "haptics/falcon/ftdi_link.h"
#include "haptics/falcon/usb_transport.h"
#include "haptics/haptic_device.h"

namespace tsf::haptics {

struct FalconOptions {
    std::vector<uint8_t> firmware;  ///< image to load when none runs (readFalconFirmware); may be empty
    FirmwareLoadOptions firmware_load;
    double counts_per_Nm = kFalconCountsPerNm;
    int max_motor_command = kFalconMaxMotorCommand;
    int tick_read_timeout_ms = 1;   ///< the read inside a tick waits at most this long
    int resend_after_ticks = 10;    ///< a packet unanswered this long is presumed lost
    int silent_ticks_to_fail = 250; ///< this many ticks without a frame: the device has failed
    int stale_ticks_to_zero = 10;   ///< this many ticks without a frame: motors commanded to 0 (no push from a stale position)
    int firmware_check_tries = 20;  ///< zero packets sent to see whether firmware runs
    int close_packets = 5;          ///< zero packets exchanged by close()
};

/// What the link did over a session (read after the loop has ended).
struct FalconLinkStats {
    bool firmware_was_running = false;  ///< open() found firmware running and loaded nothing
    FirmwareLoadReport firmware;        ///< the load, when one was made
    uint64_t packets_sent = 0;
    uint64_t frames_received = 0;
    uint64_t resends = 0;               ///< packets sent again after resend_after_ticks
    uint64_t ticks_without_frame = 0;   ///< ticks whose read brought no new frame (position held)
    uint64_t max_silent_ticks = 0;      ///< longest run of such ticks
    uint64_t bytes_discarded = 0;       ///< resynchronisation losses
    uint64_t usb_errors = 0;            ///< failed transfers other than timeouts
    uint64_t solver_fallbacks = 0;      ///< positions the Newton solve could not produce
    uint64_t limited_commands = 0;      ///< motor vectors scaled down to the command limit
    uint64_t refused_forces = 0;        ///< nonzero forces asked for before homing
    uint64_t stale_zeroed = 0;          ///< commands sent as zero because the position had gone stale
    uint64_t frames_with_unknown_bits = 0;  ///< frames whose status had an undocumented bit (taken, bit ignored)
    uint64_t ticks_homed = 0;
};

/// Opens the USB transport; throws DeviceError.
using UsbOpener = std::function<std::unique_ptr<UsbTransport>()>;

class FalconDevice final : public HapticDevice {
public:
    FalconDevice(UsbOpener opener, FalconOptions options);
    ~FalconDevice() override;

    std::string name() const override { return "falcon"; }
    /// CHAI3D's Falcon figures and libnifalcon's test cube (+-30 mm about
    /// kFalconWorkspaceCentreZ_m); not measured here.
    DeviceLimits limits() const override { return {}; }
    bool needsRealtime() const override { return true; }

    void open() override;
    void close() noexcept override;
    ReadStatus read(double loop_time_s, DeviceState& out) noexcept override;
    bool writeForce(const Vec3& force_N) noexcept override;
    /// close_packets zero packets, each read back (a pause: the link stays).
    void holdZero() noexcept override;
    void showStatus(bool in_contact, bool volume_mode) noexcept override;
    std::string failureReason() const override { return failure_ ? failure_ : ""; }

    /// Homed state seen by open() or the last frame.
    bool homed() const { return homed_; }
    const FalconLinkStats& stats() const { return stats_; }
    /// The last motor command sent (for tests).
    const FalconCommand& lastCommand() const { return sent_; }

private:
    void fail(const char* why) noexcept;
    bool send(const FalconCommand& command) noexcept;
    void takeFrame(const FalconReport& report) noexcept;
    uint8_t statusBits() const noexcept;

    UsbOpener opener_;
    FalconOptions options_;
    std::unique_ptr<UsbTransport> transport_;
    std::unique_ptr<FtdiLink> link_;
    FalconFrameParser parser_;
    std::array<uint8_t, FtdiLink::kDataBytes> buf_{};
    FalconLinkStats stats_;
    FalconReport report_;
    FalconCommand sent_;
    FalconAngles angles_{0.0, 0.0, 0.0};
    Vec3 position_m_{0.0};
    bool homed_ = false;
    bool pose_ok_ = false;     ///< position_m_ and angles_ come from a converged solve of the last frame
    bool awaiting_ = false;    ///< a packet is in flight
    int since_sent_ = 0;       ///< ticks since the packet in flight was sent
    uint64_t silent_ = 0;      ///< ticks since the last frame
    bool unplugged_ = false;   ///< the link said the device is gone: nothing more can be sent
    bool contact_ = false, volume_ = false;
    bool failed_ = false;
    const char* failure_ = nullptr;  ///< why read() failed (a static string: the tick cannot allocate)
};

}  // namespace tsf::haptics
