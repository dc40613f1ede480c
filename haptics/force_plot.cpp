#include "haptics/force_plot.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <glm/geometric.hpp>

#include "gen/util/error.h"
#include "gen/util/rgb_image.h"
#include "haptics/force_model.h"
#include "haptics/height_sampling.h"

namespace tsf::haptics {
namespace {

constexpr uint32_t kInk = 0x202020;
constexpr uint32_t kAirColour = 0x7fb2ff;  // light blue: the probe in the air
constexpr int kMaxFieldPx = 2048;          // the field part's longer side, at most

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
    // The field part's longer side is max_field_px whatever the grid's size,
    // so the picture stays bounded (a 20000-column grid is drawn smaller, not
    // 20000 pixels wide).
    const int longest = std::max(grid.cols, grid.rows);
    const int max_px = std::clamp(options.max_field_px, 64, kMaxFieldPx);
    const double px_per_cell = double(max_px) / std::max(1, longest);
    const int fw = std::max(1, int(std::lround(grid.cols * px_per_cell)));
    const int fh = std::max(1, int(std::lround(grid.rows * px_per_cell)));
    constexpr int kMargin = 12, kBarW = 18, kLegendW = 230, kScale = 2;
    const int title_h = options.title.empty() ? 0 : textHeight(kScale) + kMargin;
    const int top = kMargin + title_h;
    RgbImage img(kMargin + fw + kMargin + kBarW + kLegendW, std::max(top + fh + kMargin, top + 150), 0xffffff);
    if (!options.title.empty()) drawText(img, kMargin, kMargin, options.title, kScale, kInk);
    // Field: grey relief, north up.
    for (int y = 0; y < fh; ++y)
        for (int x = 0; x < fw; ++x) {
            const double gi = (x + 0.5) / px_per_cell - 0.5;
            const double gj = (grid.rows - (y + 0.5) / px_per_cell) - 0.5;
            const double h = std::clamp(sampleHeightOnly(grid, gi, gj, Interpolation::kBilinear), 0.0, 1.0);
            const uint32_t g = uint32_t(std::lround(60 + 170 * h));
            img.set(kMargin + x, top + y, (g << 16) | (g << 8) | g);
        }
    // Path.
    auto toPixel = [&](const Vec3& p, int& x, int& y) {
        const GridPoint g = deviceToGrid(mapping, p);
        const double fx = (g.gi + 0.5) * px_per_cell, fy = (grid.rows - (g.gj + 0.5)) * px_per_cell;
        x = kMargin + int(std::lround(std::clamp(fx, 0.0, double(fw - 1))));
        y = top + int(std::lround(std::clamp(fy, 0.0, double(fh - 1))));
    };
    const double limit = max_force_N > 0.0 ? max_force_N : 1.0;
    for (size_t i = 0; i < log.size(); ++i) {
        const LogRecord& r = log[i];
        if (r.flags & kFlagContact) continue;
        int x, y;
        toPixel(r.position_m, x, y);
        img.set(x, y, kAirColour);
    }
    for (size_t i = 0; i < log.size(); ++i) {
        const LogRecord& r = log[i];
        if (!(r.flags & kFlagContact)) continue;
        int x, y;
        toPixel(r.position_m, x, y);
        img.dot(x, y, 2, forceColour(glm::length(r.force_N) / limit));
    }
    // Colour bar, labelled in newtons.
    const int bx = kMargin + fw + kMargin, bottom = top + std::max(fh, 150 - kMargin) - 1;
    for (int y = top; y <= bottom; ++y) {
        const uint32_t c = forceColour(double(bottom - y) / double(std::max(1, bottom - top)));
        for (int x = 0; x < kBarW; ++x) img.set(bx + x, y, c);
    }
    char label[32];
    std::snprintf(label, sizeof label, "%.1f N", max_force_N);
    const int lx = bx + kBarW + 6;
    drawText(img, lx, top, label, kScale, kInk);
    drawText(img, lx, bottom - textHeight(kScale), "0 N", kScale, kInk);
    // Legend: what the marks mean.
    const int ly = top + (bottom - top) / 2 - 3 * textHeight(kScale);
    img.line(lx, ly + 4, lx + 16, ly + 4, 1, kAirColour);
    drawText(img, lx + 22, ly, "path in the air", kScale, kInk);
    img.dot(lx + 8, ly + 4 + 3 * textHeight(kScale), 3, forceColour(0.75));
    drawText(img, lx + 22, ly + 3 * textHeight(kScale), "touch: force", kScale, kInk);
    drawText(img, lx + 22, ly + 5 * textHeight(kScale), "(colour bar)", kScale, kInk);
    drawText(img, lx + 22, ly + 7 * textHeight(kScale), "north is up", kScale, kInk);
    writePng(path, img);
}

}  // namespace tsf::haptics
