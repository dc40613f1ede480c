// FtdiLink: the FTDI USB-serial chip inside the Falcon, driven over a
// UsbTransport with the chip's vendor control requests (all bmRequestType
// 0x40, wIndex 0, no data stage):
//
//   request 0  reset/purge      wValue 2 = the chip's buffer of data for the host
//                               (what the host reads), 1 = its buffer of data
//                               from the host (not yet sent on the serial line)
//   request 1  modem control    wValue = mask << 8 | state; DTR is bit 0, RTS bit 1
//   request 2  flow control     wValue 0 = none
//   request 3  baud rate        wValue = the chip's divisor encoding
//   request 4  line properties  wValue 0x0008 = 8 data bits, no parity, 1 stop bit
//   request 9  latency timer    wValue = milliseconds (1..255)
//
// read() strips the two modem-status bytes that begin every IN packet
// (each kUsbPacketBytes long at most), so callers see only serial data.
// Every call is noexcept and allocation-free.
#pragma once

#include <cstdint>
#include <span>

#include "haptics/falcon/usb_transport.h"

namespace tsf::haptics {

/// The chip's request numbers (see the file comment).
enum class FtdiRequest : uint8_t {
    kReset = 0,
    kModemControl = 1,
    kFlowControl = 2,
    kBaudRate = 3,
    kLineProperties = 4,
    kLatencyTimer = 9,
};

/// Baud divisors the Falcon uses (the chip's 3 MHz base clock divided, with
/// its fractional encoding in the top bits).
inline constexpr uint16_t kFtdiBaud9600 = 0x4138;    ///< 312.5: the boot loader's handshake
inline constexpr uint16_t kFtdiBaud142857 = 0x0015;  ///< 21: firmware upload
inline constexpr uint16_t kFtdiBaud1500000 = 0x0002; ///< 2 (special code): normal operation
inline constexpr uint16_t kFtdiLine8N1 = 0x0008;
/// Purge (request 0) values, see FtdiLink::purgeReceive.
inline constexpr uint16_t kFtdiPurgeToHost = 2;
inline constexpr uint16_t kFtdiPurgeFromHost = 1;

/// Control requests wait this long; they are rare and answered at once.
inline constexpr int kFtdiControlTimeout_ms = 100;

class FtdiLink {
public:
    explicit FtdiLink(UsbTransport& transport) noexcept : usb_(transport) {}

    /// The purge values are the chip's, named from its side: libftdi 1.5
    /// (src/ftdi.h, SIO_TCIFLUSH 2 and SIO_TCOFLUSH 1; its comment there says
    /// the older SIO_RESET_PURGE_RX = 1 empties the FIFO of data from the
    /// CPU, the opposite of what its name suggested to earlier releases).
    /// Drops what the device sent that the host has not read (tcflush TCIFLUSH).
    UsbResult purgeReceive() noexcept { return request(FtdiRequest::kReset, kFtdiPurgeToHost); }
    /// Drops what the host wrote that the chip has not sent on (TCOFLUSH).
    UsbResult purgeTransmit() noexcept { return request(FtdiRequest::kReset, kFtdiPurgeFromHost); }
    UsbResult setDtr(bool high) noexcept { return request(FtdiRequest::kModemControl, high ? 0x0101 : 0x0100); }
    UsbResult setRts(bool high) noexcept { return request(FtdiRequest::kModemControl, high ? 0x0202 : 0x0200); }
    UsbResult setNoFlowControl() noexcept { return request(FtdiRequest::kFlowControl, 0); }
    UsbResult setBaudDivisor(uint16_t divisor) noexcept { return request(FtdiRequest::kBaudRate, divisor); }
    UsbResult setLine8N1() noexcept { return request(FtdiRequest::kLineProperties, kFtdiLine8N1); }
    UsbResult setLatencyTimer(uint8_t ms) noexcept { return request(FtdiRequest::kLatencyTimer, ms); }

    /// Writes serial data.
    UsbResult write(std::span<const uint8_t> data, int timeout_ms) noexcept;
    /// One bulk IN transfer of up to kRawBytes raw bytes; the serial data
    /// (status bytes removed) goes to out, which must hold kDataBytes.
    /// result.bytes counts data bytes.
    ///
    /// The transfer ends at the chip's first short packet (its latency timer
    /// sends one, data or none, that long after its last packet), when the
    /// buffer is full, or at the timeout. A caller that knows how many bytes
    /// it waits for passes `expect_bytes`: the buffer is then sized to the
    /// packets those need, so the transfer ends as soon as they are in
    /// (a 62-byte echo fills one full packet, which alone would not end a
    /// longer transfer before the latency timer fires).
    static constexpr size_t kRawBytes = 4 * kUsbPacketBytes;
    static constexpr size_t kDataBytes = 4 * (kUsbPacketBytes - 2);
    UsbResult read(std::span<uint8_t, kDataBytes> out, int timeout_ms, size_t expect_bytes = kDataBytes) noexcept;

    /// Modem-status bytes of the last packet read (0, 0 before any).
    uint8_t modemStatus() const noexcept { return status_[0]; }
    uint8_t lineStatus() const noexcept { return status_[1]; }
    UsbTransport& transport() noexcept { return usb_; }

private:
    UsbResult request(FtdiRequest r, uint16_t value) noexcept {
        return usb_.control(uint8_t(r), value, 0, kFtdiControlTimeout_ms);
    }

    UsbTransport& usb_;
    uint8_t status_[2] = {0, 0};
};

/// Strips the status bytes from raw IN data of `raw_bytes` bytes (packets of
/// kUsbPacketBytes, each starting with 2 status bytes; a short last packet
/// is allowed) into out; returns the data byte count. out must hold at
/// least raw_bytes bytes. status (2 bytes, may be null) receives the last
/// packet's status bytes.
size_t stripFtdiStatus(std::span<const uint8_t> raw, std::span<uint8_t> out, uint8_t* status) noexcept;

}  // namespace tsf::haptics
