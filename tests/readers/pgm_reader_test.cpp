#include "gen/readers/pgm_reader.h"

#include <gtest/gtest.h>

#include <string>

#include "tests/support/files.h"
#include "tests/support/input_error.h"

namespace tsf {
namespace {

std::string bytesOf(std::initializer_list<int> values) {
    std::string out;
    for (int v : values) out += char(static_cast<unsigned char>(v));
    return out;
}

TEST(PgmReader, PlainP2WithCommentsKeepsRawGreyLevels) {
    const Raster r = parsePgm("P2\n# made by hand\n3 2 # width height\n255\n0 128 255\n1 2\n# mid-data comment\n3\n", "a.pgm");
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.kind, "pgm");
    EXPECT_EQ(r.at(0, 0), 0.0);
    EXPECT_EQ(r.at(1, 0), 128.0);  // not normalised to 0..1
    EXPECT_EQ(r.at(2, 0), 255.0);
    EXPECT_EQ(r.at(0, 1), 1.0);
    EXPECT_EQ(r.at(2, 1), 3.0);
}

TEST(PgmReader, BinaryP5EightBit) {
    const std::string file = "P5 2 2 200\n" + bytesOf({0, 7, 199, 200});
    const Raster r = parsePgm(file, "b.pgm");
    ASSERT_EQ(r.cols, 2);
    EXPECT_EQ(r.at(0, 0), 0.0);
    EXPECT_EQ(r.at(1, 0), 7.0);
    EXPECT_EQ(r.at(0, 1), 199.0);
    EXPECT_EQ(r.at(1, 1), 200.0);
}

TEST(PgmReader, BinaryP5SixteenBitIsBigEndian) {
    // 0x0102 = 258, 0xFFFF = 65535, 0x0100 = 256, 0x00FF = 255
    const std::string file = "P5\n# 16-bit\n4 1\n65535\n" + bytesOf({0x01, 0x02, 0xFF, 0xFF, 0x01, 0x00, 0x00, 0xFF});
    const Raster r = parsePgm(file, "w.pgm");
    ASSERT_EQ(r.cols, 4);
    EXPECT_EQ(r.at(0, 0), 258.0);
    EXPECT_EQ(r.at(1, 0), 65535.0);
    EXPECT_EQ(r.at(2, 0), 256.0);
    EXPECT_EQ(r.at(3, 0), 255.0);
    // maxval 256 already needs two bytes per sample.
    const Raster r256 = parsePgm("P5 1 1 256\n" + bytesOf({0x01, 0x00}), "w.pgm");
    EXPECT_EQ(r256.at(0, 0), 256.0);
}

TEST(PgmReader, PlainP2SixteenBit) {
    const Raster r = parsePgm("P2 2 1 65535 65535 40000", "p.pgm");
    EXPECT_EQ(r.at(0, 0), 65535.0);
    EXPECT_EQ(r.at(1, 0), 40000.0);
}

TEST(PgmReader, TruncatedP5NamesByteOffsets) {
    // Header "P5 4 4 255\n" is 11 bytes; 16 samples needed, 10 present.
    const std::string file = "P5 4 4 255\n" + std::string(10, 'x');
    EXPECT_INPUT_ERROR_AT(parsePgm(file, "t.pgm"), 0, 0,
                          "needs 16 bytes of samples from byte offset 11, but the file ends at byte offset 21");
    // 16-bit: an odd number of bytes is also short.
    EXPECT_INPUT_ERROR_AT(parsePgm("P5 2 1 1000\n" + bytesOf({0, 1, 2}), "t.pgm"), 0, 0, "needs 4 bytes");
    // Nothing after the header at all.
    EXPECT_INPUT_ERROR_AT(parsePgm("P5 2 2 255", "t.pgm"), 0, 0, "truncated");
}

TEST(PgmReader, TruncatedP2NamesLineAndCounts) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n3 2\n9\n1 2 3\n4 5\n", "t.pgm"), 5, 0, "expected 6 grey levels (3 x 2), found 5");
}

TEST(PgmReader, BadMaxval) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n1 1\n0\n0\n", "m.pgm"), 3, 1, "maxval 0");
    EXPECT_INPUT_ERROR_AT(parsePgm("P5 1 1   70000\n\x01\x01\x01", "m.pgm"), 1, 10, "maxval 70000");
    EXPECT_INPUT_ERROR_AT(parsePgm("P2 1 1 -5 0", "m.pgm"), 1, 8, "maxval");
}

TEST(PgmReader, SampleAboveMaxval) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n2 1\n10\n3 11\n", "s.pgm"), 4, 3, "grey level 11 is above maxval 10");
    // P5: byte offset of the sample; header "P5 2 2 100\n" is 11 bytes, sample 3 is at 11 + 2.
    EXPECT_INPUT_ERROR_AT(parsePgm("P5 2 2 100\n" + bytesOf({1, 2, 101, 3}), "s.pgm"), 0, 0,
                          "sample 101 at byte offset 13 (pixel (col 0, row 1)) is above maxval 100");
}

TEST(PgmReader, BadHeaderFields) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n3 x\n255\n", "h.pgm"), 2, 3, "height");
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n3\n", "h.pgm"), 2, 0, "ends before the PGM height");
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n0 3 255\n", "h.pgm"), 2, 0, "at least 1 x 1");
    EXPECT_INPUT_ERROR_AT(parsePgm("P5 20001 10 255\n", "h.pgm"), 1, 0, "largest side");
    EXPECT_INPUT_ERROR_AT(parsePgm("P2x 1 1 1 0", "h.pgm"), 1, 3, "whitespace after the magic");
    EXPECT_INPUT_ERROR_AT(parsePgm("P2\n1 1\n3\n2.5\n", "h.pgm"), 4, 1, "found \"2.5\"");
}

TEST(PgmReader, OtherNetpbmKindsAreNamed) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P6 1 1 255\nabc", "c.ppm"), 1, 1, "colour PPM");
    EXPECT_INPUT_ERROR_AT(parsePgm("P1 1 1 0", "c.pbm"), 1, 1, "PBM bitmap");
    EXPECT_INPUT_ERROR_AT(parsePgm("GIF89a", "c.pgm"), 1, 1, "not a PGM file");
    EXPECT_INPUT_ERROR_AT(parsePgm("", "c.pgm"), 1, 1, "not a PGM file");
}

TEST(PgmReader, ExtraP2ValuesAreAnError) {
    EXPECT_INPUT_ERROR_AT(parsePgm("P2 2 1 9\n1 2\n3\n", "x.pgm"), 3, 1, "more grey levels than width x height = 2");
}

TEST(PgmReader, BytesAfterAP5ImageAreIgnored) {
    const Raster r = parsePgm("P5 1 1 255\n" + bytesOf({42}) + "P5 1 1 255\n\x01", "m.pgm");
    EXPECT_EQ(r.at(0, 0), 42.0);
}

TEST(PgmReader, ReadsFromFile) {
    const std::string path = test::writeScratch("read.pgm", "P5 3 1 255\n" + bytesOf({10, 20, 30}));
    const Raster r = readPgm(path);
    EXPECT_EQ(r.source, path);
    EXPECT_EQ(r.at(2, 0), 30.0);
}

}  // namespace
}  // namespace tsf
