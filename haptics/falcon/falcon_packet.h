// The Novint Falcon's normal-mode packets: 16 bytes each way over the FTDI
// serial link, once the firmware runs (falcon_firmware.h loads it).
//
// Framing: '<' (0x3C), 14 payload bytes, '>' (0x3E). There is no checksum;
// a frame is valid when both delimiters sit 15 bytes apart and every payload
// byte decodes. Payload bytes are 0x41 ('A') + a small number:
//   bytes 1-12   three signed 16-bit numbers, 4 bytes each, one nibble per
//                byte, least significant nibble first
//   byte 13      host -> device: status bits (kFalconHoming, kFalconLed*)
//                device -> host: bits 0-3 grip buttons, bits 4-6 the homed
//                flags of motors 0, 1, 2
//   byte 14      0 (0x41 on the wire)
// Host -> device the three numbers are motor commands; device -> host they
// are encoder counts (falcon_kinematics.h turns them into a position).
//
// Known vector (published with libnifalcon's util/translate_packet.py): a
// host -> device COMMAND, as the Novint driver sends it:
//   3c 41 4d 4b 41 4d 4e 4b 41 49 45 4c 41 45 41 3e
//   -> motor commands 2752, 2780, 2888; status 0x4 (the blue LED).
// The device -> host report has the same layout (encoder counts, buttons,
// homed flags), but no frame recorded from a device has been checked here:
// the report layout rests on libnifalcon's decoder, not on a capture.
//
// Everything here is a pure function or a fixed-size parser: no allocation,
// no exceptions, callable from the haptic tick.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace tsf::haptics {

inline constexpr size_t kFalconPacketBytes = 16;
using FalconPacket = std::array<uint8_t, kFalconPacketBytes>;

/// Host -> device status bits of byte 13.
inline constexpr uint8_t kFalconHoming = 0x01;    ///< homing mode: the firmware finds each motor's index
inline constexpr uint8_t kFalconLedGreen = 0x02;
inline constexpr uint8_t kFalconLedBlue = 0x04;
inline constexpr uint8_t kFalconLedRed = 0x08;

/// All three homed flags of FalconReport::homed_mask.
inline constexpr uint8_t kFalconAllHomed = 0x7;

/// What the host sends: one command per motor (signed motor units, see
/// falcon_kinematics.h) and the status bits above.
struct FalconCommand {
    std::array<int16_t, 3> motor{0, 0, 0};
    uint8_t status = 0;  ///< kFalconHoming | kFalconLed* bits
};

/// What the device answers.
struct FalconReport {
    std::array<int16_t, 3> encoder{0, 0, 0};  ///< encoder counts of motors 0, 1, 2
    uint8_t buttons = 0;                      ///< kButton* bits of haptic_device.h (same layout)
    uint8_t homed_mask = 0;                   ///< bit k set: motor k is homed
    uint8_t unknown_bits = 0;                 ///< status bits no documentation names (bit 7): kept, counted, ignored
    bool homed() const { return (homed_mask & kFalconAllHomed) == kFalconAllHomed; }
};

/// Encodes a command into a 16-byte frame. Status bits above 0x0F are
/// dropped (they do not fit the firmware's byte).
FalconPacket encodeFalconCommand(const FalconCommand& command) noexcept;

/// Decodes one device frame. False (out untouched) when the delimiters are
/// missing, a number's byte is not 'A' + nibble or the status byte is below
/// 'A'. The framing (delimiters 15 bytes apart, twelve nibble bytes) is what
/// tells a frame from noise; a status bit no documentation names (bit 7) is
/// kept in unknown_bits and otherwise ignored, so one undocumented firmware
/// bit cannot drop every frame and end a session. Byte 14 is not checked
/// either (nothing documents that the firmware keeps it at 'A').
bool decodeFalconReport(std::span<const uint8_t, kFalconPacketBytes> frame, FalconReport& out) noexcept;

/// Encodes a report the way the device would (for tests and fakes).
FalconPacket encodeFalconReport(const FalconReport& report) noexcept;

/// Decodes a host frame (for tests and fakes); same rules as
/// decodeFalconReport, status byte 'A' + 0..0x0F.
bool decodeFalconCommand(std::span<const uint8_t, kFalconPacketBytes> frame, FalconCommand& out) noexcept;

/// Finds frames in a byte stream that may start mid-frame, hold garbage, or
/// split a frame across reads. Bytes are appended with push(); complete
/// valid frames come out of next() in order. Resynchronisation: a '<' starts
/// a candidate; a candidate whose 16th byte is not '>' or whose payload does
/// not decode is dropped from its '<' and the search restarts at the next
/// '<' inside it, so a real frame hidden behind garbage is still found. At
/// most kCapacity bytes are buffered (the oldest are dropped). Fixed size,
/// no allocation.
class FalconFrameParser {
public:
    static constexpr size_t kCapacity = 256;

    /// Appends bytes (if more than kCapacity arrive at once, the newest
    /// kCapacity are kept).
    void push(std::span<const uint8_t> bytes) noexcept;
    /// The next valid frame, decoded; false when no complete frame is left
    /// (a partial tail stays buffered for the next push).
    bool next(FalconReport& out) noexcept;
    void clear() noexcept { size_ = 0; }

    uint64_t framesDecoded() const { return frames_; }
    /// Bytes thrown away while resynchronising (garbage, broken frames,
    /// buffer overflow).
    uint64_t bytesDiscarded() const { return discarded_; }
    size_t buffered() const { return size_; }

private:
    void drop(size_t n) noexcept;

    std::array<uint8_t, kCapacity> buf_{};
    size_t size_ = 0;
    uint64_t frames_ = 0;
    uint64_t discarded_ = 0;
};

}  // namespace tsf::haptics
