// Loading the Falcon's firmware. The Falcon forgets it at every power-up;
// it is Novint's (under Novint's licence), so tsf does not ship it: the user
// gives its path (`tsf feel --firmware FILE`).
//
// The load, over the FTDI link (ftdi_link.h):
//   1. purge both buffers; latency timer 16 ms;
//   2. 9600 baud, 8N1, no flow control, RTS low, DTR low then high (this
//      resets the DSP into its serial boot loader);
//   3. handshake: send LF 'C' CR until the loader answers LF 'D' ',' CR
//      (some hosts see a 0x00 first; bytes before the answer are ignored);
//   4. DTR low; ~142.9 kbaud;
//   5. send 'A' (0x41; the loader's autobaud character), expect 'A' back;
//   6. stream the image in kFirmwareChunkBytes chunks; the loader echoes
//      every chunk, and each echo must equal what was sent - the only
//      integrity check the protocol has;
//   7. normal mode (setFalconNormalMode): latency timer 1 ms, 1.5 Mbaud,
//      purge.
// A failed attempt (no handshake, a bad or missing echo) cannot be resumed
// mid-stream - the boot loader has consumed what it got - so the whole load
// restarts from step 1, up to `attempts` times.
//
// Whether firmware already runs (it survives until the power goes) is
// checked by sending zero-force packets and waiting for a valid answer
// (falconFirmwareRunning).
//
// Timing. The loader runs with the chip's latency timer at 16 ms, so a read
// with nothing to return still ends after 16 ms (a status-only packet);
// waits are therefore counted in reads, each bounded by read_timeout_ms.
// What an answer should take on the hardware: a 62-byte chunk is 4.3 ms on
// the wire at 142 857 baud and its echo as long again, and the 4-byte
// handshake answer 4.2 ms at 9600 baud, so every answer is in within about
// 10 ms plus a latency period (26 ms). reads_per_reply = 25 waits at least
// 25 x 16 ms = 400 ms for one (15 times that, for a DSP busy writing its
// memory or a loaded USB bus; libnifalcon waits 1000 ms and loading is
// known to fail on hosts with short waits), and read_timeout_ms = 50 bounds
// a read above the latency period. Measured against the fake chip
// (tests/haptics/falcon_link_test.cpp): a 7400-byte image loads in 0.59 s of
// link time, each echo read sized to end with its packet (2.5 s when every
// read waited for the latency timer). A loader that never answers costs handshake_tries x 400 ms an
// attempt, and the load gives up after two such attempts (about 8 s).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "haptics/falcon/ftdi_link.h"

namespace tsf::haptics {

/// Chunk size of the upload (a full FTDI packet of data: 64 - 2 status bytes).
inline constexpr size_t kFirmwareChunkBytes = 62;

/// Reads a firmware file and checks it looks like one: between 1 KiB and
/// 64 KiB, starting with the bytes AA 08 (the key of a TI TMS320 C2000 boot
/// image, which is what Novint's firmware files are). Throws
/// tsf::InputError naming the file otherwise.
std::vector<uint8_t> readFalconFirmware(const std::string& path);

struct FirmwareLoadOptions {
    int attempts = 5;          ///< whole loads tried before giving up (a bad echo restarts the load)
    int handshake_tries = 10;  ///< 'C' sent per attempt before giving up on the loader
    int reads_per_reply = 25;  ///< reads waited for one answer (handshake, 'A', one echo)
    int read_timeout_ms = 50;  ///< each read's timeout (above the 16 ms latency timer)
};

struct FirmwareLoadReport {
    int attempts = 0;            ///< attempts made (1 = first time right)
    size_t bytes = 0;            ///< bytes uploaded and echoed in the successful attempt
    size_t chunks = 0;
    std::string retried_because; ///< the last failed attempt's reason ("" if none failed)
};

/// Loads the image (steps 1-7 above). Throws DeviceError naming what failed
/// last (handshake, which chunk's echo at which byte, a timeout, the device
/// gone) once every attempt has failed; a vanished device fails at once.
FirmwareLoadReport loadFalconFirmware(FtdiLink& link, std::span<const uint8_t> image,
                                      const FirmwareLoadOptions& options = {});

/// Step 7: the normal-mode link settings. False if a request failed.
bool setFalconNormalMode(FtdiLink& link) noexcept;

/// Sends up to `tries` zero-force packets (homing bit set, red LED),
/// reading after each, and returns true as soon as a valid frame comes
/// back. Expects the link in normal mode.
bool falconFirmwareRunning(FtdiLink& link, int tries = 20, int read_timeout_ms = 5) noexcept;

}  // namespace tsf::haptics
