#include "haptics/scale_space.h"

#include <algorithm>
#include <cmath>

namespace tsf::haptics {
namespace {

/// Source index for a tap at i on an axis of n cells, mirrored about the
/// outer cell edges (half-sample symmetric, period 2n).
inline int32_t mirrorEdge(int64_t i, int32_t n) {
    const int64_t period = 2 * int64_t(n);
    int64_t k = i % period;
    if (k < 0) k += period;
    return int32_t(k < n ? k : period - 1 - k);
}

std::vector<double> gaussianKernel(double t_cells2, double truncation_sigmas) {
    const double sigma = std::sqrt(t_cells2);
    const int radius = std::max(1, int(std::ceil(truncation_sigmas * sigma)));
    std::vector<double> k(size_t(2 * radius + 1));
    double sum = 0.0;
    for (int d = -radius; d <= radius; ++d) {
        const double w = std::exp(-double(d) * double(d) / (2.0 * t_cells2));
        k[size_t(d + radius)] = w;
        sum += w;
    }
    for (double& w : k) w /= sum;
    return k;
}

}  // namespace

HeightGrid mipmapDown(const HeightGrid& finer) {
    HeightGrid out;
    if (finer.empty()) return out;
    out.cols = (finer.cols + 1) / 2;
    out.rows = (finer.rows + 1) / 2;
    out.heights.resize(size_t(out.cols) * size_t(out.rows));
    for (int32_t j = 0; j < out.rows; ++j) {
        const int32_t j0 = 2 * j, j1 = std::min(2 * j + 1, finer.rows - 1);
        for (int32_t i = 0; i < out.cols; ++i) {
            const int32_t i0 = 2 * i, i1 = std::min(2 * i + 1, finer.cols - 1);
            const double sum = double(finer.at(i0, j0)) + finer.at(i1, j0) + finer.at(i0, j1) + finer.at(i1, j1);
            out.at(i, j) = float(0.25 * sum);
        }
    }
    return out;
}

HeightGrid gaussianBlur(const HeightGrid& grid, double t_cells2, double truncation_sigmas) {
    if (grid.empty() || !(t_cells2 > 0.0)) return grid;
    const std::vector<double> k = gaussianKernel(t_cells2, truncation_sigmas);
    const int radius = int(k.size() / 2);
    const int32_t cols = grid.cols, rows = grid.rows;
    std::vector<double> tmp(size_t(cols) * size_t(rows));
    std::vector<int32_t> idx;
    // Horizontal pass.
    idx.resize(size_t(cols) + 2 * size_t(radius));
    for (int64_t i = -radius; i < cols + radius; ++i) idx[size_t(i + radius)] = mirrorEdge(i, cols);
    for (int32_t j = 0; j < rows; ++j) {
        const float* src = &grid.heights[size_t(j) * size_t(cols)];
        double* dst = &tmp[size_t(j) * size_t(cols)];
        for (int32_t i = 0; i < cols; ++i) {
            double acc = 0.0;
            const int32_t* tap = &idx[size_t(i)];
            for (size_t d = 0; d < k.size(); ++d) acc += k[d] * src[tap[d]];
            dst[i] = acc;
        }
    }
    // Vertical pass.
    idx.assign(size_t(rows) + 2 * size_t(radius), 0);
    for (int64_t j = -radius; j < rows + radius; ++j) idx[size_t(j + radius)] = mirrorEdge(j, rows);
    HeightGrid out;
    out.cols = cols;
    out.rows = rows;
    out.heights.assign(size_t(cols) * size_t(rows), 0.0f);
    std::vector<double> acc(static_cast<size_t>(cols));
    for (int32_t j = 0; j < rows; ++j) {
        std::fill(acc.begin(), acc.end(), 0.0);
        for (size_t d = 0; d < k.size(); ++d) {
            const double w = k[d];
            const double* src = &tmp[size_t(idx[size_t(j) + d]) * size_t(cols)];
            for (int32_t i = 0; i < cols; ++i) acc[size_t(i)] += w * src[i];
        }
        float* dst = &out.heights[size_t(j) * size_t(cols)];
        for (int32_t i = 0; i < cols; ++i) dst[i] = float(std::clamp(acc[size_t(i)], 0.0, 1.0));
    }
    return out;
}

double gaussianLevelVariance(int level) { return level <= 0 ? 0.0 : std::pow(4.0, level); }

ScaleSpace buildScaleSpace(const HeightGrid& base, int levels, ScaleSpaceKind kind, double samples_per_cell) {
    ScaleSpace space;
    space.kind = kind;
    if (base.empty()) return space;
    levels = std::clamp(levels, 1, kMaxScaleLevels);
    if (!(samples_per_cell >= 1.0)) samples_per_cell = 1.0;
    space.levels.reserve(size_t(levels));
    space.levels.push_back({base, 1.0, 0.0});
    for (int n = 1; n < levels; ++n) {
        const ScaleLevel& prev = space.levels.back();
        ScaleLevel next;
        if (kind == ScaleSpaceKind::kMipmap) {
            next.grid = mipmapDown(prev.grid);
            next.base_cells_per_texel = 2.0 * prev.base_cells_per_texel;
            // Halve on until a texel spans 2^n data cells.
            while (next.base_cells_per_texel < std::ldexp(samples_per_cell, n) - 1e-9 &&
                   (next.grid.cols > 1 || next.grid.rows > 1)) {
                next.grid = mipmapDown(next.grid);
                next.base_cells_per_texel *= 2.0;
            }
        } else {
            next.t_cells2 = gaussianLevelVariance(n) * samples_per_cell * samples_per_cell;
            next.grid = gaussianBlur(prev.grid, next.t_cells2 - prev.t_cells2);
        }
        space.levels.push_back(std::move(next));
    }
    return space;
}

HeightSample sampleLevel(const ScaleSpace& space, int level, double gi, double gj,
                         const SamplingParams& sampling) noexcept {
    if (space.levels.empty()) return {};
    level = std::clamp(level, 0, space.count() - 1);
    const ScaleLevel& l = space.levels[size_t(level)];
    const double s = l.base_cells_per_texel;
    const double li = (gi + 0.5) / s - 0.5;
    const double lj = (gj + 0.5) / s - 0.5;
    HeightSample h = sampling.central_differences
                         ? sampleHeightCentral(l.grid, li, lj, sampling.interpolation, sampling.central_step_texels)
                         : sampleHeight(l.grid, li, lj, sampling.interpolation);
    h.d_di /= s;
    h.d_dj /= s;
    return h;
}

HeightSample sampleScale(const ScaleSpace& space, double level, double gi, double gj,
                         const SamplingParams& sampling) noexcept {
    if (space.levels.empty()) return {};
    const double top = double(space.count() - 1);
    if (!(level >= 0.0)) level = 0.0;  // also NaN
    if (level > top) level = top;
    const int i = int(std::floor(level));
    const double f = level - double(i);
    const HeightSample a = sampleLevel(space, i, gi, gj, sampling);
    if (f <= 0.0 || i + 1 > int(top)) return a;
    const HeightSample b = sampleLevel(space, i + 1, gi, gj, sampling);
    return {(1.0 - f) * a.height + f * b.height, (1.0 - f) * a.d_di + f * b.d_di, (1.0 - f) * a.d_dj + f * b.d_dj};
}

}  // namespace tsf::haptics
