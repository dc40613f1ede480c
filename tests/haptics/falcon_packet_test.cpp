// The Falcon's 16-byte packets: the recorded command vector, round trips, framing
// errors, resynchronisation in a byte stream, and a randomised (fuzz)
// property test of the decoder.
#include <algorithm>
#include <array>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "haptics/falcon/falcon_packet.h"
#include "tests/haptics/falcon_stream_property.h"

using namespace tsf::haptics;

namespace {

/// A host -> device command as the Novint driver sends it (libnifalcon's
/// util/translate_packet.py); not a frame from a device.
const FalconPacket kCaptured = {0x3c, 0x41, 0x4d, 0x4b, 0x41, 0x4d, 0x4e, 0x4b,
                                0x41, 0x49, 0x45, 0x4c, 0x41, 0x45, 0x41, 0x3e};

std::vector<uint8_t> bytes(const FalconPacket& p) { return {p.begin(), p.end()}; }

}  // namespace

TEST(FalconPacket, TheRecordedCommandDecodesToItsMotorsAndTheBlueLed) {
    FalconCommand c;
    ASSERT_TRUE(decodeFalconCommand(kCaptured, c));
    EXPECT_EQ(c.motor[0], 2752);
    EXPECT_EQ(c.motor[1], 2780);
    EXPECT_EQ(c.motor[2], 2888);
    EXPECT_EQ(c.status, kFalconLedBlue);
    EXPECT_EQ(encodeFalconCommand(c), kCaptured);  // and back, byte for byte
}

// The report has the command's layout: the same 16 bytes read as a report
// give the same three numbers (as encoder counts) and the status nibble as
// buttons. This checks the shared layout, not a device capture.
TEST(FalconPacket, TheReportSharesTheCommandsLayout) {
    FalconReport r;
    ASSERT_TRUE(decodeFalconReport(kCaptured, r));
    EXPECT_EQ(r.encoder[0], 2752);
    EXPECT_EQ(r.encoder[1], 2780);
    EXPECT_EQ(r.encoder[2], 2888);
    EXPECT_EQ(r.buttons, 0x4);  // the centre button
    EXPECT_EQ(r.homed_mask, 0);
    EXPECT_FALSE(r.homed());
    EXPECT_EQ(encodeFalconReport(r), kCaptured);  // and back, byte for byte
}

TEST(FalconPacket, CommandLayoutIsNibblesLeastSignificantFirst) {
    FalconCommand c;
    c.motor = {0x1234, -1, 0};
    c.status = kFalconHoming | kFalconLedGreen;
    const FalconPacket p = encodeFalconCommand(c);
    const FalconPacket expected = {'<', 0x41 + 4, 0x41 + 3, 0x41 + 2, 0x41 + 1,     // 0x1234
                                   0x41 + 15, 0x41 + 15, 0x41 + 15, 0x41 + 15,     // -1 = 0xFFFF
                                   0x41, 0x41, 0x41, 0x41, 0x41 + 3, 0x41, '>'};   // 0, status 3, spare
    EXPECT_EQ(p, expected);
    FalconCommand back;
    ASSERT_TRUE(decodeFalconCommand(p, back));
    EXPECT_EQ(back.motor, c.motor);
    EXPECT_EQ(back.status, c.status);
}

TEST(FalconPacket, RoundTripsExtremeValues) {
    for (int16_t v : {int16_t(-32768), int16_t(-4096), int16_t(-1), int16_t(0), int16_t(1), int16_t(4096),
                      int16_t(32767)}) {
        FalconReport r;
        r.encoder = {v, int16_t(-v / 2), int16_t(v / 3)};
        r.buttons = 0xF;
        r.homed_mask = 0x7;
        FalconReport back;
        ASSERT_TRUE(decodeFalconReport(encodeFalconReport(r), back));
        EXPECT_EQ(back.encoder, r.encoder);
        EXPECT_EQ(back.buttons, 0xF);
        EXPECT_TRUE(back.homed());
    }
}

TEST(FalconPacket, RejectsBrokenFrames) {
    FalconReport r;
    r.encoder = {7, 7, 7};
    FalconPacket p = kCaptured;
    p[0] = '[';
    EXPECT_FALSE(decodeFalconReport(p, r));
    p = kCaptured;
    p[15] = 0;
    EXPECT_FALSE(decodeFalconReport(p, r));
    p = kCaptured;
    p[5] = 0x40;  // below 'A': not a nibble
    EXPECT_FALSE(decodeFalconReport(p, r));
    p = kCaptured;
    p[12] = 0x51;  // 'A' + 16
    EXPECT_FALSE(decodeFalconReport(p, r));
    p = kCaptured;
    p[13] = 0x40;  // status below 'A'
    EXPECT_FALSE(decodeFalconReport(p, r));
    EXPECT_EQ(r.encoder[0], 7);  // untouched on failure
}

TEST(FalconPacket, AnUndocumentedStatusBitIsKeptAndIgnoredNotAReasonToDropTheFrame) {
    FalconPacket p = kCaptured;
    p[13] = uint8_t(0x41 + 0x80 + 0x30 + 0x2);  // bit 7, motors 0 and 1 homed, a button (the byte holds 'A' + 0xBE at most)
    FalconReport r;
    ASSERT_TRUE(decodeFalconReport(p, r));
    EXPECT_EQ(r.unknown_bits, 0x80);
    EXPECT_EQ(r.homed_mask, 0x3);
    EXPECT_EQ(encodeFalconReport(r), p);  // the unknown bit survives a round trip
    EXPECT_EQ(r.buttons, 0x2);
    EXPECT_EQ(r.encoder[0], 2752);
}

TEST(FalconFrameParser, FindsFramesSplitAcrossReads) {
    FalconFrameParser parser;
    const auto b = bytes(kCaptured);
    FalconReport r;
    parser.push(std::span(b).first(5));
    EXPECT_FALSE(parser.next(r));
    parser.push(std::span<const uint8_t>());  // an empty read (null data): nothing, and no UB
    parser.push(std::span(b).subspan(5, 10));
    EXPECT_FALSE(parser.next(r));
    parser.push(std::span(b).subspan(15));
    ASSERT_TRUE(parser.next(r));
    EXPECT_EQ(r.encoder[2], 2888);
    EXPECT_FALSE(parser.next(r));
    EXPECT_EQ(parser.bytesDiscarded(), 0u);
}

TEST(FalconFrameParser, ResynchronisesAfterGarbageAndBrokenFrames) {
    FalconReport a;
    a.encoder = {100, -200, 300};
    a.homed_mask = 7;
    const FalconPacket pa = encodeFalconReport(a);
    std::vector<uint8_t> stream = {'>', 'x', '<', 0x41, 0x42};  // garbage and a stray start
    stream.insert(stream.end(), kCaptured.begin(), kCaptured.begin() + 9);  // a frame cut short...
    stream.insert(stream.end(), pa.begin(), pa.end());                      // ...then a whole one
    stream.insert(stream.end(), {'<', '<'});
    stream.insert(stream.end(), kCaptured.begin(), kCaptured.end());
    FalconFrameParser parser;
    parser.push(stream);
    FalconReport r;
    ASSERT_TRUE(parser.next(r));
    EXPECT_EQ(r.encoder, a.encoder);
    ASSERT_TRUE(parser.next(r));
    EXPECT_EQ(r.encoder[0], 2752);
    EXPECT_FALSE(parser.next(r));
    EXPECT_EQ(parser.framesDecoded(), 2u);
    EXPECT_EQ(parser.bytesDiscarded(), stream.size() - 32);
}

TEST(FalconFrameParser, OverflowKeepsTheNewestBytes) {
    FalconFrameParser parser;
    std::vector<uint8_t> junk(FalconFrameParser::kCapacity * 3, '<');
    parser.push(junk);
    parser.push(bytes(kCaptured));
    FalconReport r;
    ASSERT_TRUE(parser.next(r));
    EXPECT_EQ(r.encoder[1], 2780);
    EXPECT_LE(parser.buffered(), FalconFrameParser::kCapacity);
}

// Fuzz: random streams and mutated frames, pushed in random pieces. The
// property (falcon_stream_property.h) is what the libFuzzer entry point in
// fuzz/ checks too: no crash, only frames that re-encode to bytes present in
// the input come out, every intact frame surrounded by garbage is found.
TEST(FalconFrameParser, FuzzRandomStreams) {
    std::mt19937 rng(1234);
    std::uniform_int_distribution<int> byte(0, 255);
    const std::array<uint8_t, 6> alphabet = {'<', '>', 0x41, 0x4F, 0x50, 0xC0};
    size_t frames = 0;
    for (int round = 0; round < 20000; ++round) {
        std::vector<uint8_t> data(size_t(rng() % 120));
        const int kind = round % 3;
        for (auto& b : data) b = kind == 0 ? uint8_t(byte(rng)) : alphabet[rng() % alphabet.size()];
        if (kind == 2 && data.size() > 20) {  // plant a valid frame and mutate near it
            FalconReport r;
            r.encoder = {int16_t(rng()), int16_t(rng()), int16_t(rng())};
            r.buttons = uint8_t(rng() & 0xF);
            r.homed_mask = uint8_t(rng() & 0x7);
            const FalconPacket p = encodeFalconReport(r);
            std::copy(p.begin(), p.end(), data.begin() + long(rng() % (data.size() - 16)));
        }
        frames += tsf::haptics::testing::checkFalconStream(data.data(), data.size(), unsigned(rng()));
    }
    EXPECT_GT(frames, 1000u);  // the planted frames were found
}
