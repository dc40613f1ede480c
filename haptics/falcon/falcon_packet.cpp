#include "haptics/falcon/falcon_packet.h"

#include <algorithm>
#include <cstring>

namespace tsf::haptics {
namespace {

constexpr uint8_t kStart = '<';
constexpr uint8_t kEnd = '>';
constexpr uint8_t kZero = 0x41;  // 'A': the wire value of 0
constexpr size_t kStatusByte = 13;
constexpr size_t kSpareByte = 14;

void putNumber(FalconPacket& p, size_t first, int16_t value) noexcept {
    const auto v = uint16_t(value);
    for (size_t k = 0; k < 4; ++k) p[first + k] = uint8_t(kZero + ((v >> (4 * k)) & 0xF));
}

bool getNumber(std::span<const uint8_t, kFalconPacketBytes> f, size_t first, int16_t& value) noexcept {
    uint16_t v = 0;
    for (size_t k = 0; k < 4; ++k) {
        const uint8_t b = f[first + k];
        if (b < kZero || b > kZero + 0xF) return false;
        v = uint16_t(v | ((b - kZero) << (4 * k)));
    }
    value = int16_t(v);
    return true;
}

/// A frame of three numbers and a status value (already without 'A').
FalconPacket frame(const std::array<int16_t, 3>& numbers, uint8_t status) noexcept {
    FalconPacket p{};
    p[0] = kStart;
    for (size_t m = 0; m < 3; ++m) putNumber(p, 1 + 4 * m, numbers[m]);
    p[kStatusByte] = uint8_t(kZero + status);
    p[kSpareByte] = kZero;
    p[kFalconPacketBytes - 1] = kEnd;
    return p;
}

/// The numbers and status value of a frame; false when the delimiters are
/// missing, a number's byte is no nibble or the status is above max_status.
bool unframe(std::span<const uint8_t, kFalconPacketBytes> f, std::array<int16_t, 3>& numbers, uint8_t& status,
             uint8_t max_status) noexcept {
    if (f[0] != kStart || f[kFalconPacketBytes - 1] != kEnd) return false;
    for (size_t m = 0; m < 3; ++m)
        if (!getNumber(f, 1 + 4 * m, numbers[m])) return false;
    const uint8_t s = f[kStatusByte];
    if (s < kZero || s > kZero + max_status) return false;
    status = uint8_t(s - kZero);
    return true;
}

}  // namespace

FalconPacket encodeFalconCommand(const FalconCommand& c) noexcept { return frame(c.motor, c.status & 0x0F); }

bool decodeFalconReport(std::span<const uint8_t, kFalconPacketBytes> f, FalconReport& out) noexcept {
    FalconReport r;
    uint8_t status = 0;
    if (!unframe(f, r.encoder, status, uint8_t(0xFF - kZero))) return false;
    r.buttons = uint8_t(status & 0x0F);
    r.homed_mask = uint8_t((status >> 4) & 0x07);
    r.unknown_bits = uint8_t(status & 0x80);
    out = r;
    return true;
}

FalconPacket encodeFalconReport(const FalconReport& r) noexcept {
    return frame(r.encoder, uint8_t((r.buttons & 0x0F) | ((r.homed_mask & 0x07) << 4) | (r.unknown_bits & 0x80)));
}

bool decodeFalconCommand(std::span<const uint8_t, kFalconPacketBytes> f, FalconCommand& out) noexcept {
    FalconCommand c;
    if (!unframe(f, c.motor, c.status, 0x0F)) return false;
    out = c;
    return true;
}

void FalconFrameParser::push(std::span<const uint8_t> bytes) noexcept {
    // An empty read may come with a null pointer, which memcpy must never get
    // (UBSan found it, even for 0 bytes).
    if (bytes.empty()) return;
    if (bytes.size() > kCapacity) {
        discarded_ += bytes.size() - kCapacity + size_;
        size_ = 0;
        bytes = bytes.last(kCapacity);
    } else if (size_ + bytes.size() > kCapacity) {
        drop(size_ + bytes.size() - kCapacity);
    }
    std::memcpy(buf_.data() + size_, bytes.data(), bytes.size());
    size_ += bytes.size();
}

void FalconFrameParser::drop(size_t n) noexcept {
    n = std::min(n, size_);
    std::memmove(buf_.data(), buf_.data() + n, size_ - n);
    size_ -= n;
    discarded_ += n;
}

bool FalconFrameParser::next(FalconReport& out) noexcept {
    for (;;) {
        // Skip to the next start byte.
        const auto* start = std::find(buf_.data(), buf_.data() + size_, kStart);
        drop(size_t(start - buf_.data()));
        if (size_ < kFalconPacketBytes) return false;  // partial frame: wait for more
        const std::span<const uint8_t, kFalconPacketBytes> frame(buf_.data(), kFalconPacketBytes);
        if (decodeFalconReport(frame, out)) {
            std::memmove(buf_.data(), buf_.data() + kFalconPacketBytes, size_ - kFalconPacketBytes);
            size_ -= kFalconPacketBytes;
            ++frames_;
            return true;
        }
        drop(1);  // a broken candidate: resume at the next '<' inside it
    }
}

}  // namespace tsf::haptics
