// Writes small PNG files with libpng for the reader tests.
#pragma once

#include <png.h>

#include <csetjmp>
#include <stdexcept>
#include <string>
#include <vector>

namespace tsf::test {

struct PngSpec {
    int width = 1;
    int height = 1;
    int color_type = PNG_COLOR_TYPE_GRAY;
    int bit_depth = 8;
    bool interlaced = false;
    /// Samples in row-major order, channels interleaved (as many per pixel as
    /// the colour type has); for bit depths < 8, one sample per pixel (packed here).
    std::vector<unsigned> samples;
    std::vector<png_color> palette;        ///< PNG_COLOR_TYPE_PALETTE only
    std::vector<png_byte> palette_alpha;   ///< tRNS for palette images
    int grey_transparent = -1;             ///< tRNS grey level for grey images (-1 = none)
};

namespace detail {
inline void appendBytes(png_structp png, png_bytep data, size_t n) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), n);
}
inline void flushNothing(png_structp) {}
inline int channelsOf(int color_type) {
    switch (color_type) {
        case PNG_COLOR_TYPE_GRAY_ALPHA: return 2;
        case PNG_COLOR_TYPE_RGB: return 3;
        case PNG_COLOR_TYPE_RGB_ALPHA: return 4;
        default: return 1;
    }
}
// Packs one row; all locals trivially destructible (setjmp frame below).
inline std::vector<png_byte> packRow(const PngSpec& s, int row) {
    const int ch = channelsOf(s.color_type);
    std::vector<png_byte> out;
    if (s.bit_depth < 8) {
        out.assign(size_t((s.width * s.bit_depth + 7) / 8), 0);
        for (int x = 0; x < s.width; ++x) {
            const unsigned v = s.samples[size_t(row * s.width + x)];
            const int bit = x * s.bit_depth;
            out[size_t(bit / 8)] |= png_byte(v << (8 - s.bit_depth - bit % 8));
        }
        return out;
    }
    for (int k = 0; k < s.width * ch; ++k) {
        const unsigned v = s.samples[size_t(row * s.width * ch + k)];
        if (s.bit_depth == 16) out.push_back(png_byte(v >> 8));
        out.push_back(png_byte(v & 0xFF));
    }
    return out;
}
inline bool writeWithLibpng(png_structp png, png_infop info, const PngSpec& s, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_IHDR(png, info, png_uint_32(s.width), png_uint_32(s.height), s.bit_depth, s.color_type,
                 s.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    if (!s.palette.empty()) png_set_PLTE(png, info, s.palette.data(), int(s.palette.size()));
    if (!s.palette_alpha.empty())
        png_set_tRNS(png, info, s.palette_alpha.data(), int(s.palette_alpha.size()), nullptr);
    if (s.grey_transparent >= 0) {
        png_color_16 trans{};
        trans.gray = png_uint_16(s.grey_transparent);
        png_set_tRNS(png, info, nullptr, 0, &trans);
    }
    png_write_info(png, info);
    png_write_image(png, rows);
    png_write_end(png, nullptr);
    return true;
}
}  // namespace detail

/// PNG file bytes for `spec`; throws std::runtime_error if libpng refuses.
inline std::string makePng(const PngSpec& spec) {
    std::string out;
    std::vector<std::vector<png_byte>> packed;
    for (int r = 0; r < spec.height; ++r) packed.push_back(detail::packRow(spec, r));
    std::vector<png_bytep> rows;
    for (auto& row : packed) rows.push_back(row.data());
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    png_set_write_fn(png, &out, detail::appendBytes, detail::flushNothing);
    const bool ok = detail::writeWithLibpng(png, info, spec, rows.data());
    png_destroy_write_struct(&png, &info);
    if (!ok) throw std::runtime_error("libpng could not write the test PNG");
    return out;
}

}  // namespace tsf::test
