#include "haptics/falcon/falcon_firmware.h"

#include <algorithm>
#include <array>
#include <cstdio>
#include <cstring>

#include "gen/util/error.h"
#include "gen/util/file_bytes.h"
#include "haptics/falcon/falcon_packet.h"
#include "haptics/haptic_device.h"

namespace tsf::haptics {
namespace {

constexpr size_t kMinFirmwareBytes = 1024;
constexpr size_t kMaxFirmwareBytes = 64 * 1024;
constexpr int kWriteTimeout_ms = 100;
constexpr uint8_t kHandshakeSend[] = {0x0A, 'C', 0x0D};
constexpr uint8_t kHandshakeAnswer[] = {0x0A, 'D', ',', 0x0D};
constexpr uint8_t kAutobaud = 'A';

/// A failed step of one attempt; `fatal` stops all attempts (device gone).
/// `no_loader`: the boot loader never answered the handshake.
struct Failure {
    std::string what;
    bool fatal = false;
    bool no_loader = false;
};

/// Attempts whose handshake got no answer at all before the load gives up:
/// a second DTR reset that changes nothing means the DSP is not there (its
/// power supply is off) or not in its boot loader.
constexpr int kSilentLoaderAttempts = 2;

std::string hex(uint8_t b) {
    char s[8];
    std::snprintf(s, sizeof s, "0x%02X", b);
    return s;
}

bool gone(const UsbResult& r) { return r.status == UsbStatus::kNoDevice; }

/// Reads until `want` data bytes are in `got` or the reads run out.
/// False with failure set when the device vanished.
bool readUpTo(FtdiLink& link, size_t want, std::vector<uint8_t>& got, const FirmwareLoadOptions& o, Failure& f) {
    std::array<uint8_t, FtdiLink::kDataBytes> buf;
    for (int k = 0; k < o.reads_per_reply && got.size() < want; ++k) {
        const UsbResult r = link.read(buf, o.read_timeout_ms, want - got.size());
        if (gone(r)) {
            f = {"the Falcon disappeared from USB while loading its firmware", true};
            return false;
        }
        got.insert(got.end(), buf.begin(), buf.begin() + long(r.bytes));
    }
    return true;
}

bool check(const UsbResult& r, const char* step, Failure& f) {
    if (r.ok()) return true;
    f = {std::string(step) + " failed (" + (gone(r) ? "device gone" : "USB error") + ")", gone(r)};
    return false;
}

bool handshake(FtdiLink& link, const FirmwareLoadOptions& o, Failure& f) {
    if (!check(link.purgeReceive(), "purging the receive buffer", f) ||
        !check(link.purgeTransmit(), "purging the transmit buffer", f) ||
        !check(link.setLatencyTimer(16), "setting the latency timer", f) ||
        !check(link.setBaudDivisor(kFtdiBaud9600), "setting 9600 baud", f) ||
        !check(link.setLine8N1(), "setting 8N1", f) || !check(link.setNoFlowControl(), "disabling flow control", f) ||
        !check(link.setRts(false), "clearing RTS", f) || !check(link.setDtr(false), "clearing DTR", f) ||
        !check(link.setDtr(true), "raising DTR", f))
        return false;
    for (int t = 0; t < o.handshake_tries; ++t) {
        if (!check(link.write(kHandshakeSend, kWriteTimeout_ms), "sending the handshake", f)) return false;
        std::vector<uint8_t> got;
        if (!readUpTo(link, sizeof kHandshakeAnswer, got, o, f)) return false;
        if (std::search(got.begin(), got.end(), std::begin(kHandshakeAnswer), std::end(kHandshakeAnswer)) != got.end())
            return true;
    }
    f = {"the Falcon's boot loader did not answer the handshake (" + std::to_string(o.handshake_tries) +
             " tries); is the firmware already running, or is the power supply off?",
         false, true};
    return false;
}

bool startUpload(FtdiLink& link, const FirmwareLoadOptions& o, Failure& f) {
    if (!check(link.setDtr(false), "clearing DTR", f) ||
        !check(link.setBaudDivisor(kFtdiBaud142857), "setting the upload speed", f))
        return false;
    const uint8_t a[] = {kAutobaud};
    if (!check(link.write(a, kWriteTimeout_ms), "sending the autobaud byte", f)) return false;
    std::vector<uint8_t> got;
    if (!readUpTo(link, 1, got, o, f)) return false;
    if (got.size() == 1 && got[0] == kAutobaud) return true;
    f = {got.empty() ? "no answer to the autobaud byte 'A'"
                     : "the autobaud byte 'A' came back as " + hex(got[0])};
    return false;
}

bool upload(FtdiLink& link, std::span<const uint8_t> image, const FirmwareLoadOptions& o, FirmwareLoadReport& rep,
            Failure& f) {
    const size_t chunks = (image.size() + kFirmwareChunkBytes - 1) / kFirmwareChunkBytes;
    for (size_t c = 0; c < chunks; ++c) {
        const std::span<const uint8_t> chunk =
            image.subspan(c * kFirmwareChunkBytes, std::min(kFirmwareChunkBytes, image.size() - c * kFirmwareChunkBytes));
        const std::string where = "chunk " + std::to_string(c + 1) + " of " + std::to_string(chunks);
        if (!check(link.write(chunk, kWriteTimeout_ms), ("writing firmware " + where).c_str(), f)) return false;
        std::vector<uint8_t> echo;
        if (!readUpTo(link, chunk.size(), echo, o, f)) return false;
        const size_t n = std::min(echo.size(), chunk.size());
        const auto diff = std::mismatch(chunk.begin(), chunk.begin() + long(n), echo.begin());
        if (diff.first != chunk.begin() + long(n)) {
            const size_t at = size_t(diff.first - chunk.begin());
            f = {"bad echo of firmware " + where + " at byte " + std::to_string(at) + " (sent " + hex(*diff.first) +
                 ", got " + hex(*diff.second) + ")"};
            return false;
        }
        if (echo.size() < chunk.size()) {
            f = {"no complete echo of firmware " + where + " (" + std::to_string(echo.size()) + " of " +
                 std::to_string(chunk.size()) + " bytes came back)"};
            return false;
        }
        rep.bytes += chunk.size();
        ++rep.chunks;
    }
    return true;
}

}  // namespace

std::vector<uint8_t> readFalconFirmware(const std::string& path) {
    const std::string bytes = readFileBytes(path, 1 << 20);
    if (bytes.size() < kMinFirmwareBytes || bytes.size() > kMaxFirmwareBytes)
        throw InputError(path, 0, 0,
                         "is " + std::to_string(bytes.size()) +
                             " bytes; Falcon firmware files (such as nvent_firmware.bin from Novint's SDK) are "
                             "1 KiB to 64 KiB");
    if (uint8_t(bytes[0]) != 0xAA || uint8_t(bytes[1]) != 0x08)
        throw InputError(path, 0, 0,
                         "does not look like Falcon firmware: it should start with the bytes AA 08 (a TMS320 boot "
                         "image, as nvent_firmware.bin from Novint's SDK does), but starts with " +
                             hex(uint8_t(bytes[0])) + " " + hex(uint8_t(bytes[1])));
    return {bytes.begin(), bytes.end()};
}

bool setFalconNormalMode(FtdiLink& link) noexcept {
    return link.setLatencyTimer(1).ok() && link.setBaudDivisor(kFtdiBaud1500000).ok() && link.purgeReceive().ok() &&
           link.purgeTransmit().ok();
}

bool falconFirmwareRunning(FtdiLink& link, int tries, int read_timeout_ms) noexcept {
    FalconCommand zero;
    zero.status = kFalconHoming | kFalconLedRed;
    const FalconPacket packet = encodeFalconCommand(zero);
    FalconFrameParser parser;
    std::array<uint8_t, FtdiLink::kDataBytes> buf;
    for (int t = 0; t < tries; ++t) {
        const UsbResult w = link.write(packet, kWriteTimeout_ms);
        if (w.status == UsbStatus::kNoDevice) return false;
        for (int k = 0; k < 2; ++k) {
            const UsbResult r = link.read(buf, read_timeout_ms);
            if (r.status == UsbStatus::kNoDevice) return false;
            parser.push(std::span<const uint8_t>(buf.data(), r.bytes));
            FalconReport report;
            if (parser.next(report)) return true;
        }
    }
    return false;
}

FirmwareLoadReport loadFalconFirmware(FtdiLink& link, std::span<const uint8_t> image, const FirmwareLoadOptions& o) {
    FirmwareLoadReport rep;
    Failure f;
    int silent_loader = 0;
    for (int attempt = 1; attempt <= std::max(1, o.attempts); ++attempt) {
        rep.attempts = attempt;
        rep.bytes = rep.chunks = 0;
        if (!f.what.empty()) rep.retried_because = f.what;
        f = {};
        if (handshake(link, o, f) && startUpload(link, o, f) && upload(link, image, o, rep, f)) {
            if (!setFalconNormalMode(link))
                throw DeviceError("the firmware was uploaded but switching the Falcon's link to normal mode failed");
            return rep;
        }
        if (f.fatal || (f.no_loader && ++silent_loader >= kSilentLoaderAttempts)) break;
    }
    throw DeviceError("loading the Falcon's firmware failed after " + std::to_string(rep.attempts) +
                      (rep.attempts == 1 ? " attempt: " : " attempts: ") + f.what +
                      ". Unplug the Falcon's power and USB, plug them back in (USB directly into the computer, "
                      "not through a hub) and try again.");
}

}  // namespace tsf::haptics
