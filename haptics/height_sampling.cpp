#include "haptics/height_sampling.h"

#include <algorithm>
#include <cmath>

namespace tsf::haptics {
namespace {

/// One axis of a lookup: the base cell, the fraction inside it, and whether
/// the coordinate lay outside the field (then the surface is flat along it).
struct Axis {
    int32_t i0 = 0;
    double t = 0.0;
    bool clamped = false;
};

Axis locate(double g, int32_t n) noexcept {
    Axis a;
    const double last = double(n - 1);
    if (!(g == g)) g = 0.5 * last;  // NaN: last line of defence, see header
    if (g <= 0.0) {
        a.clamped = g < 0.0;
        g = 0.0;
    } else if (g >= last) {
        a.clamped = g > last;
        g = last;
    }
    if (n <= 1) return a;  // i0 = 0, t = 0
    const double f = std::floor(g);
    a.i0 = std::min(int32_t(f), n - 2);
    a.t = g - double(a.i0);
    return a;
}

/// Tap index mirrored about the outermost centres (bicubic border rule).
inline int32_t mirror(int32_t i, int32_t n) noexcept {
    if (i < 0) i = -i;
    if (i > n - 1) i = 2 * (n - 1) - i;
    return std::clamp(i, 0, n - 1);
}

/// Catmull-Rom weights and their derivatives for taps -1, 0, 1, 2.
inline void catmullRom(double t, double w[4], double dw[4]) noexcept {
    const double t2 = t * t;
    const double t3 = t2 * t;
    w[0] = 0.5 * (-t3 + 2.0 * t2 - t);
    w[1] = 0.5 * (3.0 * t3 - 5.0 * t2 + 2.0);
    w[2] = 0.5 * (-3.0 * t3 + 4.0 * t2 + t);
    w[3] = 0.5 * (t3 - t2);
    dw[0] = 0.5 * (-3.0 * t2 + 4.0 * t - 1.0);
    dw[1] = 0.5 * (9.0 * t2 - 10.0 * t);
    dw[2] = 0.5 * (-9.0 * t2 + 8.0 * t + 1.0);
    dw[3] = 0.5 * (3.0 * t2 - 2.0 * t);
}

HeightSample bilinear(const HeightGrid& g, const Axis& ax, const Axis& ay) noexcept {
    const int32_t i1 = std::min(ax.i0 + 1, g.cols - 1);
    const int32_t j1 = std::min(ay.i0 + 1, g.rows - 1);
    const double h00 = g.at(ax.i0, ay.i0), h10 = g.at(i1, ay.i0);
    const double h01 = g.at(ax.i0, j1), h11 = g.at(i1, j1);
    const double a = ax.t, b = ay.t;
    HeightSample s;
    s.height = (1 - a) * (1 - b) * h00 + a * (1 - b) * h10 + (1 - a) * b * h01 + a * b * h11;
    s.d_di = ax.clamped || g.cols == 1 ? 0.0 : (1 - b) * (h10 - h00) + b * (h11 - h01);
    s.d_dj = ay.clamped || g.rows == 1 ? 0.0 : (1 - a) * (h01 - h00) + a * (h11 - h10);
    return s;
}

HeightSample bicubic(const HeightGrid& g, const Axis& ax, const Axis& ay) noexcept {
    double wx[4], dwx[4], wy[4], dwy[4];
    catmullRom(ax.t, wx, dwx);
    catmullRom(ay.t, wy, dwy);
    int32_t ix[4], iy[4];
    for (int k = 0; k < 4; ++k) {
        ix[k] = mirror(ax.i0 - 1 + k, g.cols);
        iy[k] = mirror(ay.i0 - 1 + k, g.rows);
    }
    double h = 0.0, hx = 0.0, hy = 0.0;
    for (int r = 0; r < 4; ++r) {
        double row = 0.0, drow = 0.0;
        const float* line = &g.heights[size_t(iy[r]) * size_t(g.cols)];
        for (int c = 0; c < 4; ++c) {
            const double v = line[ix[c]];
            row += wx[c] * v;
            drow += dwx[c] * v;
        }
        h += wy[r] * row;
        hx += wy[r] * drow;
        hy += dwy[r] * row;
    }
    HeightSample s;
    s.height = h;
    s.d_di = ax.clamped || g.cols == 1 ? 0.0 : hx;
    s.d_dj = ay.clamped || g.rows == 1 ? 0.0 : hy;
    return s;
}

}  // namespace

HeightSample sampleHeight(const HeightGrid& grid, double gi, double gj, Interpolation interpolation) noexcept {
    if (grid.empty()) return {};
    const Axis ax = locate(gi, grid.cols);
    const Axis ay = locate(gj, grid.rows);
    return interpolation == Interpolation::kBicubic ? bicubic(grid, ax, ay) : bilinear(grid, ax, ay);
}

double sampleHeightOnly(const HeightGrid& grid, double gi, double gj, Interpolation interpolation) noexcept {
    return sampleHeight(grid, gi, gj, interpolation).height;
}

HeightSample sampleHeightCentral(const HeightGrid& grid, double gi, double gj, Interpolation interpolation,
                                 double step_cells) noexcept {
    HeightSample s;
    s.height = sampleHeightOnly(grid, gi, gj, interpolation);
    if (!(step_cells > 0.0)) return s;
    const double e = sampleHeightOnly(grid, gi + step_cells, gj, interpolation);
    const double w = sampleHeightOnly(grid, gi - step_cells, gj, interpolation);
    const double n = sampleHeightOnly(grid, gi, gj + step_cells, interpolation);
    const double so = sampleHeightOnly(grid, gi, gj - step_cells, interpolation);
    s.d_di = (e - w) / (2.0 * step_cells);
    s.d_dj = (n - so) / (2.0 * step_cells);
    return s;
}

}  // namespace tsf::haptics
