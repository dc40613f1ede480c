// The FTDI link and the firmware load, against the fake Falcon: the control
// requests in order, status bytes stripped, the handshake, the echoed
// upload (success, a bad echo retried, echoes that never come, a silent
// loader, an unplugged device), and detecting firmware that already runs.
#include <algorithm>
#include <filesystem>
#include <fstream>

#include <gtest/gtest.h>

#include "gen/util/error.h"
#include "haptics/falcon/falcon_firmware.h"
#include "haptics/falcon/ftdi_link.h"
#include "haptics/falcon/falcon_packet.h"
#include "haptics/haptic_device.h"
#include "tests/haptics/fake_falcon.h"

using namespace tsf::haptics;
using tsf::haptics::testing::FakeFalcon;
using tsf::haptics::testing::FakeFalconConfig;
using tsf::haptics::testing::fakeFirmwareImage;
namespace fs = std::filesystem;

namespace {

std::string errorOf(FakeFalcon& fake, const std::vector<uint8_t>& image) {
    FtdiLink link(fake);
    try {
        loadFalconFirmware(link, image, {});
    } catch (const DeviceError& e) {
        return e.what();
    }
    ADD_FAILURE() << "expected a DeviceError";
    return {};
}

bool has(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

}  // namespace

TEST(FtdiLink, StripsTheStatusBytesOfEveryPacket) {
    std::vector<uint8_t> raw;
    for (int packet = 0; packet < 2; ++packet) {  // a full packet, then a short one
        raw.push_back(0x31);
        raw.push_back(0x60);
        for (int i = 0; i < (packet == 0 ? 62 : 5); ++i) raw.push_back(uint8_t(packet * 100 + i));
    }
    std::vector<uint8_t> out(raw.size());
    uint8_t status[2] = {0, 0};
    ASSERT_EQ(stripFtdiStatus(raw, out, status), 67u);
    EXPECT_EQ(out[0], 0);
    EXPECT_EQ(out[61], 61);
    EXPECT_EQ(out[62], 100);  // the second packet's status bytes are gone
    EXPECT_EQ(out[66], 104);
    EXPECT_EQ(status[0], 0x31);
    EXPECT_EQ(status[1], 0x60);
    EXPECT_EQ(stripFtdiStatus(std::span<const uint8_t>(raw.data(), 1), out, nullptr), 0u);  // a broken packet
}

TEST(FalconFirmware, LoadsWithTheDocumentedRequestSequence) {
    const auto image = fakeFirmwareImage(7400);
    FakeFalconConfig cfg;
    cfg.firmware_bytes = image.size();
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    const FirmwareLoadReport rep = loadFalconFirmware(link, image, {});
    EXPECT_EQ(rep.attempts, 1);
    EXPECT_EQ(rep.bytes, image.size());
    EXPECT_EQ(rep.chunks, (image.size() + 61) / 62);
    EXPECT_TRUE(rep.retried_because.empty());
    EXPECT_TRUE(fake.firmwareRunning());
    EXPECT_EQ(fake.firmwareBytesEchoed(), image.size());
    // Each chunk's read ends when its echo fills a packet (4.5 ms at
    // 142 857 baud), not at the next latency timer 16 ms later: 120 chunks
    // in about 0.55 s of link time (docs/haptics.md).
    EXPECT_GT(fake.linkTime(), 120 * 0.0044);
    EXPECT_LT(fake.linkTime(), 0.7);
    // Normal mode afterwards: 1 ms latency timer, 1.5 Mbaud, DTR low.
    EXPECT_EQ(fake.latencyTimer(), 1);
    EXPECT_EQ(fake.baudDivisor(), kFtdiBaud1500000);
    EXPECT_FALSE(fake.dtr());
    // The boot sequence, request by request.
    const std::vector<std::pair<uint8_t, uint16_t>> expected = {
        {0, 2},      {0, 1},      {9, 16},     {3, 0x4138}, {4, 0x0008}, {2, 0},  // purge, latency, 9600 8N1
        {1, 0x0200}, {1, 0x0100}, {1, 0x0101},                                    // RTS low, DTR low -> high
        {1, 0x0100}, {3, 0x0015},                                                 // DTR low, upload speed
        {9, 1},      {3, 0x0002}, {0, 2},      {0, 1}};                            // normal mode
    std::vector<std::pair<uint8_t, uint16_t>> seen;
    for (const auto& c : fake.controls()) {
        seen.emplace_back(c.request, c.value);
        EXPECT_EQ(c.index, 0);
    }
    // setFalconNormalMode also sets 8N1 and no flow control; compare the
    // requests named above in order.
    size_t at = 0;
    for (const auto& s : seen)
        if (at < expected.size() && s == expected[at]) ++at;
    EXPECT_EQ(at, expected.size());
}

TEST(FalconFirmware, WaitsForALateBootLoader) {
    const auto image = fakeFirmwareImage(2000);
    FakeFalconConfig cfg;
    cfg.handshake_after = 7;
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    EXPECT_EQ(loadFalconFirmware(link, image, {}).attempts, 1);
    EXPECT_EQ(fake.handshakes(), 8);
}

TEST(FalconFirmware, ABadEchoRestartsTheLoad) {
    const auto image = fakeFirmwareImage(7400);
    FakeFalconConfig cfg;
    cfg.firmware_bytes = image.size();
    cfg.corrupt_echo_byte = 500;  // chunk 9 (bytes 496..557), its 5th byte
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    const FirmwareLoadReport rep = loadFalconFirmware(link, image, {});
    EXPECT_EQ(rep.attempts, 2);
    EXPECT_EQ(fake.uploads(), 2);
    EXPECT_TRUE(has(rep.retried_because, "bad echo of firmware chunk 9 of 120 at byte 4")) << rep.retried_because;
    EXPECT_TRUE(fake.firmwareRunning());
}

TEST(FalconFirmware, GivesUpAfterTheAttemptsWithTheReason) {
    const auto image = fakeFirmwareImage(3000);
    FakeFalconConfig cfg;
    cfg.corrupt_echo_byte = 10;
    cfg.corrupt_attempts = 99;
    FakeFalcon fake(cfg);
    const std::string e = errorOf(fake, image);
    EXPECT_TRUE(has(e, "after 5 attempts")) << e;
    EXPECT_TRUE(has(e, "bad echo of firmware chunk 1")) << e;
    EXPECT_TRUE(has(e, "plug them back in")) << e;
    EXPECT_FALSE(fake.firmwareRunning());
}

TEST(FalconFirmware, EchoTimeoutFails) {
    const auto image = fakeFirmwareImage(3000);
    FakeFalconConfig cfg;
    cfg.swallow_echo_from = 1000;
    FakeFalcon fake(cfg);
    const std::string e = errorOf(fake, image);
    EXPECT_TRUE(has(e, "no complete echo of firmware chunk 17")) << e;
    // Each attempt waited its 25 reads of at least 16 ms for the echo.
    EXPECT_GT(fake.linkTime(), 5 * 25 * 0.016);
}

TEST(FalconFirmware, SlowEchoesAreWaitedFor) {
    // A DSP that now and then takes a third of a second to echo a chunk (a
    // busy memory write, a loaded bus): the load still succeeds at once.
    const auto image = fakeFirmwareImage(7400);
    FakeFalconConfig cfg;
    cfg.firmware_bytes = image.size();
    cfg.slow_echo_every = 10;
    cfg.slow_echo_ms = 300.0;
    cfg.loader_turnaround_ms = 2.0;
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    const FirmwareLoadReport rep = loadFalconFirmware(link, image, {});
    EXPECT_EQ(rep.attempts, 1) << rep.retried_because;
    EXPECT_TRUE(fake.firmwareRunning());
    EXPECT_GT(fake.linkTime(), 12 * 0.3);  // the twelve slow echoes were waited for
}

TEST(FalconFirmware, AnEchoLaterThanTheWaitRestartsTheLoad) {
    const auto image = fakeFirmwareImage(3000);
    FakeFalconConfig cfg;
    cfg.slow_echo_every = 30;
    cfg.slow_echo_ms = 2000.0;  // five times the 400 ms wait
    FakeFalcon fake(cfg);
    const std::string e = errorOf(fake, image);
    EXPECT_TRUE(has(e, "no complete echo of firmware chunk 30")) << e;
}

TEST(FalconFirmware, SilentBootLoaderFails) {
    FakeFalconConfig cfg;
    cfg.silent_loader = true;
    FakeFalcon fake(cfg);
    const std::string e = errorOf(fake, fakeFirmwareImage(2000));
    EXPECT_TRUE(has(e, "did not answer the handshake")) << e;
    EXPECT_TRUE(has(e, "after 2 attempts")) << e;  // a second reset that changes nothing: no loader there
    EXPECT_EQ(fake.handshakes(), 2 * 10);
    // 20 handshakes, each waited 25 reads that the latency timer ends after 16 ms.
    EXPECT_NEAR(fake.linkTime(), 20 * 25 * 0.016, 0.1);
}

// The fake chip hands out packets as an FTDI chip does (the driver's timing
// rests on it): status-only packets, batching by the latency timer, and a
// full packet that does not end a longer transfer.
TEST(FakeFtdiChip, BatchesByTheLatencyTimer) {
    FakeFalconConfig cfg;
    cfg.firmware_running = true;
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    ASSERT_TRUE(setFalconNormalMode(link));  // latency timer 1 ms
    std::array<uint8_t, 256> raw;
    // After a quiet spell a read returns at once: a status-only packet.
    const double t0 = fake.linkTime();
    UsbResult r = fake.bulkRead(raw, 100);
    EXPECT_EQ(r.bytes, 2u);
    EXPECT_EQ(raw[0], 0x31);
    EXPECT_DOUBLE_EQ(fake.linkTime(), t0);
    // With nothing to send, the next one comes when the timer runs out.
    r = fake.bulkRead(raw, 100);
    EXPECT_EQ(r.bytes, 2u);
    EXPECT_NEAR(fake.linkTime() - t0, 0.001, 1e-9);
    const double t1 = fake.linkTime();
    // Four replies (64 bytes): a full packet as soon as 62 are in, which
    // does not end a 256-byte transfer; the last 2 come when the timer
    // runs out after it.
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(link.write(encodeFalconCommand(FalconCommand{}), 2).ok());
    r = fake.bulkRead(raw, 100);
    EXPECT_EQ(r.bytes, 64u + 4u);
    EXPECT_GT(fake.linkTime() - t1, 0.001);
    // The same four in a 64-byte transfer: it ends with the full packet,
    // before the latency timer.
    for (int k = 0; k < 4; ++k) ASSERT_TRUE(link.write(encodeFalconCommand(FalconCommand{}), 2).ok());
    const double t2 = fake.linkTime();
    r = fake.bulkRead(std::span<uint8_t>(raw.data(), 64), 100);
    EXPECT_EQ(r.bytes, 64u);
    EXPECT_LT(fake.linkTime() - t2, 0.001);
    // With the loader's 16 ms timer, a 10 ms read times out empty.
    fake.bulkRead(raw, 100);  // the 2 bytes left
    ASSERT_TRUE(link.setLatencyTimer(16).ok());
    const double t3 = fake.linkTime();
    r = fake.bulkRead(raw, 10);
    EXPECT_EQ(r.status, UsbStatus::kTimeout);
    EXPECT_EQ(r.bytes, 0u);
    EXPECT_NEAR(fake.linkTime() - t3, 0.010, 1e-9);
}

TEST(FtdiLink, PurgesAsLibftdiNamesThem) {
    // libftdi 1.5 (src/ftdi.h): SIO_TCIFLUSH = 2 drops what the chip holds
    // for the host, SIO_TCOFLUSH = 1 what the host wrote. A reply waiting
    // in the chip survives purgeTransmit and is gone after purgeReceive.
    FakeFalconConfig cfg;
    cfg.firmware_running = true;
    FakeFalcon fake(cfg);
    FtdiLink link(fake);
    ASSERT_TRUE(setFalconNormalMode(link));
    std::array<uint8_t, FtdiLink::kDataBytes> data{};
    ASSERT_TRUE(link.write(encodeFalconCommand(FalconCommand{{0, 0, 0}, kFalconHoming}), 2).ok());
    fake.wait(0.002);
    ASSERT_TRUE(link.purgeTransmit().ok());
    EXPECT_EQ(link.read(data, 5).bytes, kFalconPacketBytes);
    ASSERT_TRUE(link.write(encodeFalconCommand(FalconCommand{{0, 0, 0}, kFalconHoming}), 2).ok());
    fake.wait(0.002);
    ASSERT_TRUE(link.purgeReceive().ok());
    EXPECT_EQ(link.read(data, 5).bytes, 0u);
    EXPECT_EQ(fake.controls().back().value, 2);
}

TEST(FalconFirmware, UnpluggedDeviceFailsAtOnce) {
    FakeFalcon fake;
    fake.unplug();
    const std::string e = errorOf(fake, fakeFirmwareImage(2000));
    EXPECT_TRUE(has(e, "after 1 attempt:")) << e;
}

TEST(FalconFirmware, DetectsFirmwareThatAlreadyRuns) {
    FakeFalconConfig cfg;
    cfg.firmware_running = true;
    FakeFalcon running(cfg);
    FtdiLink link(running);
    ASSERT_TRUE(setFalconNormalMode(link));
    EXPECT_TRUE(falconFirmwareRunning(link));
    FakeFalcon bare;  // just powered up: only the boot loader
    FtdiLink bare_link(bare);
    ASSERT_TRUE(setFalconNormalMode(bare_link));
    EXPECT_FALSE(falconFirmwareRunning(bare_link, 5, 1));
}

TEST(FalconFirmware, FileChecksNameTheFile) {
    const fs::path dir = fs::path(TSF_TEST_SCRATCH) / "firmware";
    fs::create_directories(dir);
    auto write = [&](const std::string& name, const std::vector<uint8_t>& bytes) {
        std::ofstream(dir / name, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()),
                                                          std::streamsize(bytes.size()));
        return (dir / name).string();
    };
    EXPECT_EQ(readFalconFirmware(write("good.bin", fakeFirmwareImage(7400))).size(), 7400u);
    auto message = [](const std::string& path) {
        try {
            readFalconFirmware(path);
        } catch (const tsf::InputError& e) {
            return std::string(e.what());
        }
        return std::string("no error");
    };
    EXPECT_TRUE(has(message((dir / "missing.bin").string()), "not found"));
    EXPECT_TRUE(has(message(write("small.bin", fakeFirmwareImage(100))), "1 KiB to 64 KiB"));
    std::vector<uint8_t> png(4000, 0);
    png[0] = 0x89;
    png[1] = 'P';
    const std::string m = message(write("picture.png", png));
    EXPECT_TRUE(has(m, "picture.png")) << m;
    EXPECT_TRUE(has(m, "AA 08")) << m;
}
