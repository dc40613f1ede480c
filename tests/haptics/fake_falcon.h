// FakeFalcon: a Novint Falcon on the far side of a UsbTransport, for running
// the whole driver without hardware (test_haptics, and through the
// LD_PRELOAD libusb stand-in in fake_libusb/ for `tsf feel --device falcon`).
//
// What it plays:
//   - the FTDI chip, on a virtual clock (no test waits for real time):
//     every control request is recorded (baud divisor, DTR, latency
//     timer, purges: wValue 2 empties what waits for the host, 1 what the
//     host wrote and the chip has not yet sent on, as libftdi 1.5 names
//     them: SIO_TCIFLUSH 2, SIO_TCOFLUSH 1). Bytes the DSP sends reach the chip at the serial line's
//     speed (10 bits a byte at 9600, 142 857 or 1 500 000 baud). The chip
//     hands the host a USB packet (two modem-status bytes, then up to 62
//     data bytes) when 62 bytes are waiting, or else when its latency timer
//     runs out since the last packet - with whatever has come, nothing at
//     all included (a 2-byte status-only packet). The two modem-status
//     bytes change from packet to packet (line bits come and go, as on a
//     real chip), so a reader that takes them for data is caught. A bulk read lasts until a
//     short packet ends it, the buffer is full or its timeout passes; a
//     full 64-byte packet does not end it. So a read right after a quiet
//     spell returns at once with no data, and one that waits for a 62-byte
//     echo in a 256-byte buffer lasts until the latency timer fires after it.
//   - the DSP's boot loader: a DTR low -> high edge at 9600 baud resets it;
//     it answers LF 'C' CR with LF 'D' ',' CR, then at upload speed echoes
//     'A' and every firmware byte as it arrives; switching to normal speed
//     starts the firmware if the whole image (firmware_bytes) came through
//     intact;
//   - the firmware: answers each 16-byte command, reply_turnaround_us after
//     it arrived, with one 16-byte frame of encoder counts from the grip's
//     pose, buttons and homed flags. Before homing, counts are offset by an
//     arbitrary amount, as relative encoders are after power-up. Homing
//     needs the homing bit in every packet (as libnifalcon sends it): a
//     packet without it un-homes the motors. Each reply is the grip's
//     pose after the command it answers (replyPositions()), so a driver
//     that reports a position one packet late is seen to.
//   - the mechanism (fake_falcon_mechanism.h, written independently of the
//     driver's kinematics): thigh angles and encoder counts from the pose,
//     the motors' force from the commands;
//   - the grip: either a scripted pose (pose(t)) or a finger - a mass held by
//     a hand spring toward pose(t) and pushed by the motors' force -
//     integrated 1 ms per command packet.
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
    double loader_turnaround_ms = 0.1; ///< the loader's delay before it answers or echoes a byte
    int slow_echo_every = 0;         ///< every Nth upload write is echoed late...
    double slow_echo_ms = 0.0;       ///< ...by this much (a DSP busy writing its memory)
    // Normal-mode faults.
    int homing_packets = 30;         ///< packets with the homing bit before all motors report homed (-1 = never)
    int garbage_every = 0;           ///< every Nth reply is preceded by garbage bytes
    int split_every = 0;             ///< every Nth reply stops after 7 bytes and comes on 1.5 ms later
    double reply_turnaround_us = 250.0; ///< the firmware's delay between a command and its reply
    int drop_reply_every = 0;        ///< every Nth command gets no reply
    long unplug_after_packets = -1;  ///< every transfer fails with kNoDevice after this many commands
    long silent_after_packets = -1;  ///< the firmware hangs after this many commands: taken, never answered
    // The grip.
    std::function<Vec3(double t_s)> pose;  ///< device-frame position (or the hand's target with finger)
    std::function<uint8_t(double t_s)> buttons;
    bool finger = false;             ///< simulate a finger (mass 0.15 kg, hand 300 N/m, 4 N s/m) pushed by the motors
    double press_N = 0.0;            ///< finger: constant downward push of the hand
    double hand_y_N_per_m = 300.0;   ///< finger: the hand spring's vertical stiffness (soft = a resting hand)
    // State kept by the device across host processes (fake_libusb restores it).
    bool homed_at_start = false;     ///< the motors are homed already (firmware_running too)
    uint16_t divisor_at_start = 0x4138; ///< the chip's baud divisor at power-up (or left by the last process)
    int latency_at_start_ms = 16;
    /// Called after each command the firmware took (e.g. to keep a report current).
    std::function<void()> on_command;
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

    /// The host lets `s` seconds pass without a transfer (bytes the DSP
    /// sends meanwhile reach the chip).
    void wait(double s) { now_us_ += s * 1e6; }
    /// Cuts the cable now.
    void unplug() { unplugged_ = true; }
    /// The firmware hangs: commands are taken but never answered.
    void stopAnswering() { silent_ = true; }

    // What happened.
    const std::vector<ControlRecord>& controls() const { return controls_; }
    const std::vector<FalconCommand>& commands() const { return commands_; }
    /// The grip's position (device frame) each reply reported, in order.
    const std::vector<Vec3>& replyPositions() const { return reply_positions_; }
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
    /// The link's virtual clock (seconds since the fake was made): what the
    /// reads and writes so far would have taken on the hardware.
    double linkTime() const { return now_us_ * 1e-6; }
    Vec3 gripPosition() const { return p_; }
    uint16_t baudDivisor() const { return divisor_; }
    int latencyTimer() const { return latency_ms_; }
    bool dtr() const { return dtr_; }

private:
    enum class Loader { kOff, kHandshake, kAutobaud, kUpload };
    /// A byte the DSP sent, and when it is in the chip's buffer (us).
    struct Arriving {
        uint8_t byte;
        double at_us;
    };
    /// The DSP sends bytes, starting `after_us` from now (or when the line
    /// is free), one byte time apart.
    void send(std::span<const uint8_t> bytes, double after_us);
    double byteTime_us() const;
    void onCommandBytes(std::span<const uint8_t> data);
    void onCommand(const FalconCommand& c);
    void onLoaderBytes(std::span<const uint8_t> data);
    void stepGrip(const Vec3& force_N);

    FakeFalconConfig cfg_;
    std::vector<ControlRecord> controls_;
    std::vector<FalconCommand> commands_;
    std::vector<Vec3> forces_;
    std::vector<Vec3> reply_positions_;
    std::deque<Arriving> rx_;  ///< bytes for the host, in the chip or still on the line
    std::vector<uint8_t> in_;  ///< partial command bytes
    double now_us_ = 0.0;
    double line_free_us_ = 0.0;    ///< when the DSP's transmit line is next free
    double last_packet_us_ = -1e9; ///< when the chip last handed the host a packet
    uint64_t packets_to_host_ = 0;  ///< USB packets handed to the host (varies the status bytes)
    long upload_writes_ = 0;
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
