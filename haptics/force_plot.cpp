#include "haptics/force_plot.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "gen/error.h"
#include "gen/util/atomic_file.h"
#include "haptics/force_model.h"
#include "haptics/height_sampling.h"

namespace tsf::haptics {
namespace {

struct Image {
    int w = 0, h = 0;
    std::vector<uint8_t> rgb;
    void set(int x, int y, uint32_t c) {
        if (x < 0 || y < 0 || x >= w || y >= h) return;
        uint8_t* p = &rgb[(size_t(y) * size_t(w) + size_t(x)) * 3];
        p[0] = uint8_t(c >> 16);
        p[1] = uint8_t(c >> 8);
        p[2] = uint8_t(c);
    }
    void dot(int x, int y, int r, uint32_t c) {
        for (int dy = -r; dy <= r; ++dy)
            for (int dx = -r; dx <= r; ++dx)
                if (dx * dx + dy * dy <= r * r) set(x + dx, y + dy, c);
    }
};

/// 3 x 5 glyphs for the labels: digits, '.', 'N', ' '. Each row is 3 bits.
const uint8_t* glyph(char ch) {
    static const uint8_t kDigits[10][5] = {{7, 5, 5, 5, 7}, {2, 6, 2, 2, 7}, {7, 1, 7, 4, 7}, {7, 1, 7, 1, 7},
                                           {5, 5, 7, 1, 1}, {7, 4, 7, 1, 7}, {7, 4, 7, 5, 7}, {7, 1, 1, 1, 1},
                                           {7, 5, 7, 5, 7}, {7, 5, 7, 1, 7}};
    static const uint8_t kDot[5] = {0, 0, 0, 0, 2};
    static const uint8_t kN[5] = {5, 7, 7, 7, 5};
    static const uint8_t kSpace[5] = {0, 0, 0, 0, 0};
    if (ch >= '0' && ch <= '9') return kDigits[ch - '0'];
    if (ch == '.') return kDot;
    if (ch == 'N') return kN;
    return kSpace;
}

void text(Image& img, int x, int y, const char* s, int scale, uint32_t c) {
    for (; *s; ++s, x += 4 * scale) {
        const uint8_t* g = glyph(*s);
        for (int row = 0; row < 5; ++row)
            for (int col = 0; col < 3; ++col)
                if (g[row] & (4 >> col))
                    for (int sy = 0; sy < scale; ++sy)
                        for (int sx = 0; sx < scale; ++sx) img.set(x + col * scale + sx, y + row * scale + sy, c);
    }
}

void writePng(const std::string& path, const Image& img) {
    FILE* f = std::fopen(path.c_str(), "wb");
    if (!f) throw OutputError(path, std::string("cannot write: ") + std::strerror(errno));
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png ? png_create_info_struct(png) : nullptr;
    if (!png || !info) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        throw std::runtime_error("libpng could not start writing " + path);
    }
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        std::fclose(f);
        throw OutputError(path, "writing failed (is the disk full?)");
    }
    png_init_io(png, f);
    png_set_IHDR(png, info, png_uint_32(img.w), png_uint_32(img.h), 8, PNG_COLOR_TYPE_RGB, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_DEFAULT, PNG_FILTER_TYPE_DEFAULT);
    png_write_info(png, info);
    for (int y = 0; y < img.h; ++y)
        png_write_row(png, const_cast<png_bytep>(&img.rgb[size_t(y) * size_t(img.w) * 3]));
    png_write_end(png, info);
    png_destroy_write_struct(&png, &info);
    if (std::fclose(f) != 0) throw OutputError(path, std::string("cannot finish writing: ") + std::strerror(errno));
}

}  // namespace

uint32_t forceColour(double fraction) {
    // Blue -> cyan -> green -> yellow -> red: readable on grey, ordered by hue.
    static const double kStops[5][3] = {{40, 70, 220}, {0, 190, 220}, {40, 200, 60}, {250, 220, 0}, {230, 30, 30}};
    double f = std::isfinite(fraction) ? std::clamp(fraction, 0.0, 1.0) * 4.0 : 0.0;
    const int i = std::min(3, int(f));
    f -= i;
    uint32_t c = 0;
    for (int k = 0; k < 3; ++k) c = (c << 8) | uint32_t(std::lround(kStops[i][k] + (kStops[i + 1][k] - kStops[i][k]) * f));
    return c;
}

void writeForcePlotPng(const std::string& path, const HeightGrid& grid, const FieldMapping& mapping,
                       const ForceLog& log, double max_force_N, const PlotOptions& options) {
    const int longest = std::max(grid.cols, grid.rows);
    const double px_per_cell = std::max(1.0, double(std::max(64, options.max_field_px)) / longest);
    const int fw = std::max(1, int(std::lround(grid.cols * px_per_cell)));
    const int fh = std::max(1, int(std::lround(grid.rows * px_per_cell)));
    constexpr int kMargin = 12, kBarW = 18, kLegendW = 70;
    Image img;
    img.w = kMargin + fw + kMargin + kBarW + kLegendW;
    img.h = std::max(fh + 2 * kMargin, 160);
    img.rgb.assign(size_t(img.w) * size_t(img.h) * 3, 255);
    // Field: grey relief, north up.
    for (int y = 0; y < fh; ++y)
        for (int x = 0; x < fw; ++x) {
            const double gi = (x + 0.5) / px_per_cell - 0.5;
            const double gj = (grid.rows - (y + 0.5) / px_per_cell) - 0.5;
            const double h = std::clamp(sampleHeightOnly(grid, gi, gj, Interpolation::kBilinear), 0.0, 1.0);
            const uint32_t g = uint32_t(std::lround(60 + 170 * h));
            img.set(kMargin + x, kMargin + y, (g << 16) | (g << 8) | g);
        }
    // Path.
    auto toPixel = [&](const Vec3& p, int& x, int& y) {
        const GridPoint g = deviceToGrid(mapping, p);
        const double fx = (g.gi + 0.5) * px_per_cell, fy = (grid.rows - (g.gj + 0.5)) * px_per_cell;
        x = kMargin + int(std::lround(std::clamp(fx, 0.0, double(fw - 1))));
        y = kMargin + int(std::lround(std::clamp(fy, 0.0, double(fh - 1))));
    };
    const double limit = max_force_N > 0.0 ? max_force_N : 1.0;
    for (size_t i = 0; i < log.size(); ++i) {
        const LogRecord& r = log[i];
        if (r.flags & kFlagContact) continue;
        int x, y;
        toPixel(r.position_m, x, y);
        img.set(x, y, 0x9ec9ff);
    }
    for (size_t i = 0; i < log.size(); ++i) {
        const LogRecord& r = log[i];
        if (!(r.flags & kFlagContact)) continue;
        int x, y;
        toPixel(r.position_m, x, y);
        img.dot(x, y, 2, forceColour(glm::length(r.force_N) / limit));
    }
    // Colour bar and labels.
    const int bx = kMargin + fw + kMargin, top = kMargin, bottom = img.h - kMargin - 1;
    for (int y = top; y <= bottom; ++y) {
        const uint32_t c = forceColour(double(bottom - y) / double(bottom - top));
        for (int x = 0; x < kBarW; ++x) img.set(bx + x, y, c);
    }
    char label[32];
    std::snprintf(label, sizeof label, "%.1f N", max_force_N);
    text(img, bx + kBarW + 4, top, label, 2, 0x202020);
    text(img, bx + kBarW + 4, bottom - 9, "0 N", 2, 0x202020);
    AtomicFile out(path);
    writePng(out.tempPath(), img);
    out.commit();
}

}  // namespace tsf::haptics
