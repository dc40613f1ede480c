#include "gen/readers/png_reader.h"

#include <gtest/gtest.h>

#include <cmath>
#include <zlib.h>

#include "tests/support/files.h"
#include "tests/support/input_error.h"
#include "png_test_writer.h"

namespace tsf {
namespace {

using test::makePng;
using test::PngSpec;

TEST(PngReader, EightBitGreyKeepsRawLevels) {
    PngSpec s;
    s.width = 3;
    s.height = 2;
    s.samples = {0, 1, 255, 17, 128, 254};
    const std::string path = test::writeScratch("grey8.png", makePng(s));
    const Raster r = readPng(path);
    ASSERT_EQ(r.cols, 3);
    ASSERT_EQ(r.rows, 2);
    EXPECT_EQ(r.kind, "png");
    EXPECT_EQ(r.source, path);
    EXPECT_EQ(r.at(0, 0), 0.0);
    EXPECT_EQ(r.at(1, 0), 1.0);
    EXPECT_EQ(r.at(2, 0), 255.0);
    EXPECT_EQ(r.at(0, 1), 17.0);  // row 0 of the raster is the top row of the image
    EXPECT_EQ(r.at(1, 1), 128.0);
    EXPECT_EQ(r.at(2, 1), 254.0);
}

TEST(PngReader, SixteenBitGrey) {
    PngSpec s;
    s.width = 4;
    s.bit_depth = 16;
    s.samples = {0, 258, 40000, 65535};
    const Raster r = parsePng(makePng(s), "g16.png");
    EXPECT_EQ(r.at(0, 0), 0.0);
    EXPECT_EQ(r.at(1, 0), 258.0);
    EXPECT_EQ(r.at(2, 0), 40000.0);
    EXPECT_EQ(r.at(3, 0), 65535.0);
}

TEST(PngReader, LowBitDepthIsNotRescaled) {
    PngSpec s;
    s.width = 5;
    s.bit_depth = 2;
    s.samples = {0, 1, 2, 3, 1};
    const Raster r = parsePng(makePng(s), "g2.png");
    ASSERT_EQ(r.cols, 5);
    EXPECT_EQ(r.at(0, 0), 0.0);
    EXPECT_EQ(r.at(2, 0), 2.0);
    EXPECT_EQ(r.at(3, 0), 3.0);
    EXPECT_EQ(r.at(4, 0), 1.0);
}

TEST(PngReader, AlphaZeroIsNoData) {
    PngSpec s;
    s.width = 3;
    s.color_type = PNG_COLOR_TYPE_GRAY_ALPHA;
    s.samples = {10, 255, 20, 0, 30, 1};  // (grey, alpha) pairs
    const Raster r = parsePng(makePng(s), "ga.png");
    EXPECT_EQ(r.at(0, 0), 10.0);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    EXPECT_EQ(r.at(2, 0), 30.0);  // partially transparent keeps its value
    // 16-bit grey + alpha.
    s.bit_depth = 16;
    s.samples = {1000, 65535, 2000, 0, 3000, 1};
    const Raster r16 = parsePng(makePng(s), "ga16.png");
    EXPECT_EQ(r16.at(0, 0), 1000.0);
    EXPECT_TRUE(std::isnan(r16.at(1, 0)));
    EXPECT_EQ(r16.at(2, 0), 3000.0);
}

TEST(PngReader, GreyTrnsLevelIsNoData) {
    PngSpec s;
    s.width = 3;
    s.bit_depth = 4;
    s.samples = {5, 9, 15};
    s.grey_transparent = 9;
    const Raster r = parsePng(makePng(s), "trns.png");
    EXPECT_EQ(r.at(0, 0), 5.0);
    EXPECT_TRUE(std::isnan(r.at(1, 0)));
    EXPECT_EQ(r.at(2, 0), 15.0);
}

TEST(PngReader, GreyRgbAndPaletteAreAccepted) {
    PngSpec rgb;
    rgb.width = 2;
    rgb.color_type = PNG_COLOR_TYPE_RGB;
    rgb.samples = {7, 7, 7, 200, 200, 200};
    const Raster r = parsePng(makePng(rgb), "rgb.png");
    EXPECT_EQ(r.at(0, 0), 7.0);
    EXPECT_EQ(r.at(1, 0), 200.0);

    PngSpec rgba;
    rgba.width = 2;
    rgba.color_type = PNG_COLOR_TYPE_RGB_ALPHA;
    rgba.samples = {9, 9, 9, 255, 1, 2, 3, 0};  // the colour pixel is transparent: no data, no error
    const Raster ra = parsePng(makePng(rgba), "rgba.png");
    EXPECT_EQ(ra.at(0, 0), 9.0);
    EXPECT_TRUE(std::isnan(ra.at(1, 0)));

    PngSpec pal;
    pal.width = 3;
    pal.color_type = PNG_COLOR_TYPE_PALETTE;
    pal.palette = {{50, 50, 50}, {0, 0, 0}, {99, 99, 99}};
    pal.palette_alpha = {255, 0};  // entry 1 transparent
    pal.samples = {2, 0, 1};       // indices
    const Raster rp = parsePng(makePng(pal), "pal.png");
    EXPECT_EQ(rp.at(0, 0), 99.0);  // the palette colour's level, not the index
    EXPECT_EQ(rp.at(1, 0), 50.0);
    EXPECT_TRUE(std::isnan(rp.at(2, 0)));
}

TEST(PngReader, ColourPixelIsAnErrorNamingIt) {
    PngSpec s;
    s.width = 2;
    s.height = 2;
    s.color_type = PNG_COLOR_TYPE_RGB;
    s.samples = {5, 5, 5, 6, 6, 6, 7, 7, 7, 10, 20, 30};
    EXPECT_INPUT_ERROR_AT(parsePng(makePng(s), "c.png"), 0, 0, "pixel (col 1, row 1) is RGB (10, 20, 30)");
}

TEST(PngReader, InterlacedImage) {
    PngSpec s;
    s.width = 9;
    s.height = 7;
    s.interlaced = true;
    for (int k = 0; k < 63; ++k) s.samples.push_back(unsigned(k * 4));
    const Raster r = parsePng(makePng(s), "adam7.png");
    for (int y = 0; y < 7; ++y)
        for (int x = 0; x < 9; ++x) EXPECT_EQ(r.at(x, y), double((y * 9 + x) * 4)) << x << "," << y;
}

TEST(PngReader, CorruptAndTruncatedFiles) {
    PngSpec s;
    s.width = 16;
    s.height = 16;
    for (int k = 0; k < 256; ++k) s.samples.push_back(unsigned(k));
    const std::string good = makePng(s);
    EXPECT_INPUT_ERROR_AT(parsePng(good.substr(0, good.size() / 2), "half.png"), 0, 0, "invalid PNG");
    EXPECT_INPUT_ERROR_AT(parsePng(good.substr(0, 20), "head.png"), 0, 0, "invalid PNG");
    std::string bad_crc = good;
    bad_crc[20] = char(bad_crc[20] ^ 0x40);  // inside IHDR: its CRC no longer matches
    EXPECT_INPUT_ERROR_AT(parsePng(bad_crc, "crc.png"), 0, 0, "invalid PNG");
    EXPECT_INPUT_ERROR_AT(parsePng("GIF89a....", "x.png"), 0, 0, "not a PNG file");
    EXPECT_INPUT_ERROR_AT(parsePng("", "x.png"), 0, 0, "not a PNG file");
}

TEST(PngReader, OversizedImageIsRejectedBeforeDecoding) {
    // 20001 x 1: a valid header with a side over the limit.
    PngSpec s;
    s.width = 20001;
    s.height = 1;
    s.bit_depth = 1;
    s.samples.assign(20001, 0);
    EXPECT_INPUT_ERROR_AT(parsePng(makePng(s), "wide.png"), 0, 0, "largest side");
}

// One PNG chunk: length, type, data, CRC (zlib's crc32 is PNG's).
std::string pngChunk(const std::string& type, const std::string& data) {
    const auto be32 = [](uint32_t v) {
        return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)};
    };
    const std::string body = type + data;
    return be32(uint32_t(data.size())) + body +
           be32(uint32_t(crc32(0, reinterpret_cast<const Bytef*>(body.data()), uInt(body.size()))));
}

TEST(PngReader, AHeaderClaimingMoreThanTheFileCanHoldIsRefusedBeforeAllocating) {
    // 20000 x 5000 RGBA16 (800 MB of pixels) claimed by a file of about 60
    // bytes; deflate cannot expand a few bytes that far.
    std::string ihdr = {char(0), char(0), char(0x4e), char(0x20), char(0), char(0), char(0x13), char(0x88),
                        char(16), char(6), char(0), char(0), char(0)};
    std::string idat(16, '\0');
    uLongf len = uLongf(idat.size());
    const std::string zeros(8, '\0');
    ASSERT_EQ(compress(reinterpret_cast<Bytef*>(idat.data()), &len, reinterpret_cast<const Bytef*>(zeros.data()),
                       uLong(zeros.size())),
              Z_OK);
    idat.resize(len);
    const std::string file = std::string("\x89PNG\r\n\x1a\n", 8) + pngChunk("IHDR", ihdr) + pngChunk("IDAT", idat) +
                             pngChunk("IEND", "");
    EXPECT_INPUT_ERROR_AT(parsePng(file, "claim.png"), 0, 0, "truncated or corrupt: the header claims 20000 x 5000");
}

}  // namespace
}  // namespace tsf
