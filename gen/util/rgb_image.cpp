#include "gen/util/rgb_image.h"

#include <png.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ostream>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"

namespace tsf {
namespace {

// 3 x 5 glyphs; each row is 3 bits, the high bit the left column.
struct Glyph {
    char ch;
    uint8_t rows[5];
};
constexpr Glyph kGlyphs[] = {
    {'0', {7, 5, 5, 5, 7}}, {'1', {2, 6, 2, 2, 7}}, {'2', {7, 1, 7, 4, 7}}, {'3', {7, 1, 7, 1, 7}},
    {'4', {5, 5, 7, 1, 1}}, {'5', {7, 4, 7, 1, 7}}, {'6', {7, 4, 7, 5, 7}}, {'7', {7, 1, 1, 1, 1}},
    {'8', {7, 5, 7, 5, 7}}, {'9', {7, 5, 7, 1, 7}}, {'A', {2, 5, 7, 5, 5}}, {'B', {6, 5, 6, 5, 6}},
    {'C', {3, 4, 4, 4, 3}}, {'D', {6, 5, 5, 5, 6}}, {'E', {7, 4, 6, 4, 7}}, {'F', {7, 4, 6, 4, 4}},
    {'G', {3, 4, 5, 5, 3}}, {'H', {5, 5, 7, 5, 5}}, {'I', {7, 2, 2, 2, 7}}, {'J', {1, 1, 1, 5, 2}},
    {'K', {5, 5, 6, 5, 5}}, {'L', {4, 4, 4, 4, 7}}, {'M', {5, 7, 7, 5, 5}}, {'N', {5, 7, 7, 7, 5}},
    {'O', {2, 5, 5, 5, 2}}, {'P', {6, 5, 6, 4, 4}}, {'Q', {2, 5, 5, 6, 3}}, {'R', {6, 5, 6, 5, 5}},
    {'S', {3, 4, 2, 1, 6}}, {'T', {7, 2, 2, 2, 2}}, {'U', {5, 5, 5, 5, 7}}, {'V', {5, 5, 5, 5, 2}},
    {'W', {5, 5, 7, 7, 5}}, {'X', {5, 5, 2, 5, 5}}, {'Y', {5, 5, 2, 2, 2}}, {'Z', {7, 1, 2, 4, 7}},
    {'.', {0, 0, 0, 0, 2}}, {',', {0, 0, 0, 2, 4}}, {':', {0, 2, 0, 2, 0}}, {';', {0, 2, 0, 2, 4}},
    {'-', {0, 0, 7, 0, 0}}, {'+', {0, 2, 7, 2, 0}}, {'/', {1, 1, 2, 4, 4}}, {'(', {1, 2, 2, 2, 1}},
    {')', {4, 2, 2, 2, 4}}, {'=', {0, 7, 0, 7, 0}}, {'%', {5, 1, 2, 4, 5}}, {'\'', {2, 2, 0, 0, 0}},
    {'<', {1, 2, 4, 2, 1}}, {'>', {4, 2, 1, 2, 4}}, {'_', {0, 0, 0, 0, 7}},
};

const uint8_t* glyph(char ch) {
    if (ch >= 'a' && ch <= 'z') ch = char(ch - 'a' + 'A');
    for (const Glyph& g : kGlyphs)
        if (g.ch == ch) return g.rows;
    return nullptr;
}

}  // namespace

RgbImage::RgbImage(int width, int height, uint32_t background) : w(width), h(height) {
    rgb.resize(size_t(w) * size_t(h) * 3);
    for (size_t k = 0; k < size_t(w) * size_t(h); ++k) {
        rgb[3 * k] = uint8_t(background >> 16);
        rgb[3 * k + 1] = uint8_t(background >> 8);
        rgb[3 * k + 2] = uint8_t(background);
    }
}

void RgbImage::set(int x, int y, uint32_t c) {
    if (x < 0 || y < 0 || x >= w || y >= h) return;
    uint8_t* p = &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3];
    p[0] = uint8_t(c >> 16);
    p[1] = uint8_t(c >> 8);
    p[2] = uint8_t(c);
}

uint32_t RgbImage::get(int x, int y) const {
    if (x < 0 || y < 0 || x >= w || y >= h) return 0;
    const uint8_t* p = &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3];
    return (uint32_t(p[0]) << 16) | (uint32_t(p[1]) << 8) | p[2];
}

void RgbImage::dot(int x, int y, int r, uint32_t c) {
    for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
            if (dx * dx + dy * dy <= r * r) set(x + dx, y + dy, c);
}

void RgbImage::fill(int x0, int y0, int x1, int y1, uint32_t c) {
    for (int y = std::max(0, y0); y < std::min(h, y1); ++y)
        for (int x = std::max(0, x0); x < std::min(w, x1); ++x) set(x, y, c);
}

void RgbImage::line(double x0, double y0, double x1, double y1, int thickness, uint32_t c) {
    const int steps = std::max(1, int(std::ceil(std::max(std::abs(x1 - x0), std::abs(y1 - y0)))));
    const int r = thickness / 2;
    for (int s = 0; s <= steps; ++s) {
        const double t = double(s) / steps;
        const int x = int(std::lround(x0 + (x1 - x0) * t)), y = int(std::lround(y0 + (y1 - y0) * t));
        fill(x - r, y - r, x - r + thickness, y - r + thickness, c);
    }
}

void drawText(RgbImage& img, int x, int y, std::string_view text, int scale, uint32_t c) {
    for (char ch : text) {
        if (const uint8_t* g = glyph(ch))
            for (int row = 0; row < 5; ++row)
                for (int col = 0; col < 3; ++col)
                    if (g[row] & (4 >> col)) img.fill(x + col * scale, y + row * scale, x + (col + 1) * scale, y + (row + 1) * scale, c);
        x += 4 * scale;
    }
}

int textWidth(std::string_view text, int scale) { return text.empty() ? 0 : int(text.size()) * 4 * scale - scale; }

namespace {

// libpng's write callback: the encoded bytes go into a string.
void appendPngBytes(png_structp png, png_bytep data, png_size_t size) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<const char*>(data), size);
}

}  // namespace

void writePng(const std::string& path, const RgbImage& img) {
    // Encoded in memory (a preview is a few hundred KB), then written like
    // every other output, so a full disk or a file-size limit reports the
    // OS's reason and leaves an earlier file as it was.
    std::string bytes;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        throw OutputError(path, "libpng could not start writing");
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        throw OutputError(path, "libpng could not encode the picture");
    }
    png_set_write_fn(png, &bytes, appendPngBytes, nullptr);
    png_set_IHDR(png, info, png_uint_32(img.w), png_uint_32(img.h), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < img.h; ++y) png_write_row(png, const_cast<png_bytep>(&img.rgb[size_t(y) * size_t(img.w) * 3]));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    writeFileAtomically(path, [&](std::ostream& out) { out.write(bytes.data(), std::streamsize(bytes.size())); });
}

}  // namespace tsf
