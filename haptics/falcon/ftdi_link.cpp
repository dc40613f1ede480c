#include "haptics/falcon/ftdi_link.h"

#include <algorithm>
#include <array>
#include <cstring>

namespace tsf::haptics {

size_t stripFtdiStatus(std::span<const uint8_t> raw, std::span<uint8_t> out, uint8_t* status) noexcept {
    size_t n = 0;
    for (size_t at = 0; at < raw.size(); at += kUsbPacketBytes) {
        const size_t len = std::min(kUsbPacketBytes, raw.size() - at);
        if (len < 2) break;  // a broken packet without its status bytes
        if (status) {
            status[0] = raw[at];
            status[1] = raw[at + 1];
        }
        const size_t data = std::min(len - 2, out.size() - n);
        std::memcpy(out.data() + n, raw.data() + at + 2, data);
        n += data;
    }
    return n;
}

UsbResult FtdiLink::write(std::span<const uint8_t> data, int timeout_ms) noexcept {
    return usb_.bulkWrite(data, timeout_ms);
}

UsbResult FtdiLink::read(std::span<uint8_t, kDataBytes> out, int timeout_ms, size_t expect_bytes) noexcept {
    std::array<uint8_t, kRawBytes> raw;
    constexpr size_t kPacketData = kUsbPacketBytes - 2;
    const size_t packets = std::clamp<size_t>((expect_bytes + kPacketData - 1) / kPacketData, 1, 4);
    UsbResult r = usb_.bulkRead(std::span<uint8_t>(raw.data(), packets * kUsbPacketBytes), timeout_ms);
    r.bytes = stripFtdiStatus(std::span<const uint8_t>(raw.data(), std::min(r.bytes, raw.size())), out, status_);
    return r;
}

}  // namespace tsf::haptics
