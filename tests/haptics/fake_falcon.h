// FakeFalcon: a Novint Falcon on the far side of a UsbTransport, for running
// the whole driver without hardware (test_haptics, and through the
// LD_PRELOAD libusb stand-in in fake_libusb/ for `tsf feel --device falcon`).
//
// What it plays:
//   - the FTDI chip: records every control request; tracks the baud divisor,
//     DTR and the latency timer; purges; prefixes every IN packet with two
//     modem-status bytes;
//   - the DSP's boot loader: a DTR low -> high edge at 9600 baud resets it;
//     it answers LF 'C' CR with LF 'D' ',' CR, then at upload speed echoes
//     'A' and every firmware byte; switching to normal speed starts the
//     firmware if the whole image (firmware_bytes) came through intact;
//   - the firmware: answers each 16-byte command with one 16-byte frame of
//     encoder counts from the grip's pose (inverse kinematics, rounded to
//     counts), buttons and homed flags. Before homing, counts are offset by
//     an arbitrary amount, as relative encoders are after power-up.
//   - the grip: either a scripted pose (pose(t)) or a finger - a mass held by
//     a hand spring toward pose(t) and pushed by the motors' force
//     (falconForceFromCommands) - integrated 1 ms per command packet.
// Faults are switched on in FakeFalconConfig.
#pragma once

#include <cstdint>
#include <deque>
#include <functional>
#include <memory>
#include <vector>

#include "haptics/falcon/falcon_packet.h"
#include "haptics/falcon/usb_transport.h"
#include "haptics/frames.h"

namespace tsf::haptics::testing {

struct FakeFalconConfig {
    size_t firmware_bytes = 0;       ///< image size that makes the firmware start (0 = any complete upload)
    bool firmware_running = false;   ///< firmware already loaded at power-up
    // Boot loader faults.
    bool silent_loader = false;      ///< never answers the handshake
    int handshake_after = 0;         ///< ignores this many 'C' before answering
    long corrupt_echo_byte = -1;     ///< image byte whose echo is flipped...
    int corrupt_attempts = 1;        ///< ...in this many upload attempts
    long swallow_echo_from = -1;     ///< image byte from which echoes stop coming (timeout)
    // Normal-mode faults.
    int homing_packets = 30;         ///< packets with the homing bit before all motors report homed (-1 = never)
    int garbage_every = 0;           ///< every Nth reply is preceded by garbage bytes
    int split_every = 0;             ///< every Nth reply arrives in two reads
    int drop_reply_every = 0;        ///< every Nth command gets no reply
    long unplug_after_packets = -1;  ///< every transfer fails with kNoDevice after this many commands
    long silent_after_packets = -1;  ///< the firmware hangs after this many commands: taken, never answered
    // The grip.
    std::function<Vec3(double t_s)> pose;  ///< device-frame position (or the hand's target with finger)
    std::function<uint8_t(double t_s)> buttons;
    bool finger = false;             ///< simulate a finger (mass 0.15 kg, hand 300 N/m, 4 N s/m) pushed by the motors
    double press_N = 0.0;            ///< finger: constant downward push of the hand
    double hand_y_N_per_m = 300.0;   ///< finger: the hand spring's vertical stiffness (soft = a resting hand)
};

struct ControlRecord {
    uint8_t request;
    uint16_t value;
    uint16_t index;
};

class FakeFalcon final : public UsbTransport {
public:
    explicit FakeFalcon(FakeFalconConfig config = {});

    UsbResult control(uint8_t request, uint16_t value, uint16_t index, int timeout_ms) noexcept override;
    UsbResult bulkWrite(std::span<const uint8_t> data, int timeout_ms) noexcept override;
    UsbResult bulkRead(std::span<uint8_t> buffer, int timeout_ms) noexcept override;
    const char* location() const noexcept override { return "fake bus 1 device 2"; }

    /// Cuts the cable now.
    void unplug() { unplugged_ = true; }
    /// The firmware hangs: commands are taken but never answered.
    void stopAnswering() { silent_ = true; }

    // What happened.
    const std::vector<ControlRecord>& controls() const { return controls_; }
    const std::vector<FalconCommand>& commands() const { return commands_; }
    /// Force (N, device frame) the motors applied for each command.
    const std::vector<Vec3>& forces() const { return forces_; }
    bool firmwareRunning() const { return firmware_running_; }
    int uploads() const { return upload_attempts_; }
    size_t firmwareBytesEchoed() const { return uploaded_; }
    int handshakes() const { return handshakes_; }
    bool homed() const { return homed_; }
    /// Commands with a nonzero motor value received while not homed.
    long nonzeroBeforeHomed() const { return nonzero_unhomed_; }
    /// Lowest y the grip reached after homing.
    double lowestHomedY() const { return lowest_y_; }
    double time() const { return t_s_; }
    Vec3 gripPosition() const { return p_; }
    uint16_t baudDivisor() const { return divisor_; }
    int latencyTimer() const { return latency_ms_; }
    bool dtr() const { return dtr_; }

    /// Every packet of bytes the device would send next is prepared this
    /// many reads late (0 = ready at the next read).
    int reply_delay_reads = 0;

private:
    enum class Loader { kOff, kHandshake, kAutobaud, kUpload };
    struct Pending {
        std::vector<uint8_t> bytes;
        long ready_at_read = 0;
    };
    void queue(std::vector<uint8_t> bytes);
    void onCommandBytes(std::span<const uint8_t> data);
    void onCommand(const FalconCommand& c);
    void onLoaderBytes(std::span<const uint8_t> data);
    void stepGrip(const Vec3& force_N);

    FakeFalconConfig cfg_;
    std::vector<ControlRecord> controls_;
    std::vector<FalconCommand> commands_;
    std::vector<Vec3> forces_;
    std::deque<Pending> out_;
    std::vector<uint8_t> in_;  ///< partial command bytes
    long reads_ = 0;
    uint16_t divisor_ = 0x4138;
    int latency_ms_ = 16;
    bool dtr_ = false;
    bool unplugged_ = false;
    bool silent_ = false;
    bool firmware_running_ = false;
    Loader loader_ = Loader::kOff;
    int handshakes_ = 0;
    int upload_attempts_ = 0;
    size_t uploaded_ = 0;
    bool upload_damaged_ = false;
    long homing_seen_ = 0;
    bool homed_ = false;
    long replies_ = 0;
    long nonzero_unhomed_ = 0;
    double lowest_y_ = 1e9;
    double t_s_ = 0.0;
    Vec3 p_{0.0}, v_{0.0};
};

/// A UsbOpener-compatible handle on a FakeFalcon the test keeps.
class FakeFalconHandle final : public UsbTransport {
public:
    explicit FakeFalconHandle(FakeFalcon& f) : f_(f) {}
    UsbResult control(uint8_t r, uint16_t v, uint16_t i, int t) noexcept override { return f_.control(r, v, i, t); }
    UsbResult bulkWrite(std::span<const uint8_t> d, int t) noexcept override { return f_.bulkWrite(d, t); }
    UsbResult bulkRead(std::span<uint8_t> b, int t) noexcept override { return f_.bulkRead(b, t); }
    const char* location() const noexcept override { return f_.location(); }

private:
    FakeFalcon& f_;
};

/// A firmware image the fake accepts: n bytes starting AA 08.
std::vector<uint8_t> fakeFirmwareImage(size_t n = 7400);

}  // namespace tsf::haptics::testing
