// UsbTransport: the few USB operations the Falcon driver needs, behind an
// interface so the whole driver runs against a fake device in the tests
// (tests/haptics/fake_falcon.h) and against libusb on a real one
// (libusb_transport.h, the only code that includes libusb.h).
//
// The device is an FTDI USB-serial chip: vendor control requests without a
// data stage, one bulk OUT endpoint and one bulk IN endpoint. Every IN
// packet (kUsbPacketBytes long at most) starts with two FTDI modem-status
// bytes; stripping them is ftdi_link.h's job, not the transport's.
//
// All calls are noexcept and allocation-free: the haptic tick makes them.
// Timeouts are milliseconds; a transfer that times out may still have moved
// some bytes (`bytes` says how many).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>

namespace tsf::haptics {

/// Largest bulk IN packet of a full-speed FTDI chip, status bytes included.
inline constexpr size_t kUsbPacketBytes = 64;

enum class UsbStatus {
    kOk,
    kTimeout,   ///< nothing (or not everything) arrived in time
    kNoDevice,  ///< the device is gone (unplugged, powered off)
    kError,     ///< any other transfer failure (pipe stall, overflow, I/O)
};

struct UsbResult {
    UsbStatus status = UsbStatus::kOk;
    size_t bytes = 0;  ///< bytes moved (read or written), even on a timeout
    bool ok() const { return status == UsbStatus::kOk; }
};

class UsbTransport {
public:
    virtual ~UsbTransport() = default;
    /// A vendor control request to the device (bmRequestType 0x40) without
    /// a data stage.
    virtual UsbResult control(uint8_t request, uint16_t value, uint16_t index, int timeout_ms) noexcept = 0;
    /// Writes all of data to the bulk OUT endpoint.
    virtual UsbResult bulkWrite(std::span<const uint8_t> data, int timeout_ms) noexcept = 0;
    /// Reads one transfer from the bulk IN endpoint into buffer (raw: FTDI
    /// status bytes included). Returns when a short packet ends the
    /// transfer, the buffer is full, or the timeout passes.
    virtual UsbResult bulkRead(std::span<uint8_t> buffer, int timeout_ms) noexcept = 0;
    /// Where the device sits, for messages ("bus 1 device 7").
    virtual const char* location() const noexcept { return "USB"; }
};

}  // namespace tsf::haptics
