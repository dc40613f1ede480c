// Scale space of a HeightGrid: progressively smoothed levels for volume mode
// and level of detail (thesis sections 4.5 and 5.2).
//
// Two constructions:
//   mipmap    thesis eq. 5.2: level n+1 cell (i, j) is the mean of level n
//             cells (2i, 2j), (2i+1, 2j), (2i, 2j+1), (2i+1, 2j+1). Each level
//             halves the resolution (rounding up: an odd last row or column
//             averages with itself, i.e. the edge cell is replicated). Cheap,
//             but only an approximation of a Gaussian and shift-variant.
//   gaussian  the scale-space L(x, y, t) = g(., t) * f with the Gaussian
//             kernel of variance t (cells^2), t = 0, 4, 16, 64, ... = 4^n for
//             level n >= 1 (thesis section 4.5). Every level keeps the full
//             resolution. Built by cascading (semigroup property: level n =
//             g(t_n - t_{n-1}) * level n-1), separably, with the sampled
//             Gaussian truncated at kGaussianTruncationSigmas standard
//             deviations and renormalised to sum 1. Borders mirror about the
//             outer cell edge (cell -1 reads cell 0, -2 reads 1), so a
//             constant field stays constant and no mass leaks.
//
// Level 0 is always the grid itself. All levels are sampled in the BASE
// grid's continuous coordinates (height_grid.h): a mipmap texel at level n
// covers 2^n x 2^n base cells and its centre is at base coordinate
// 2^n i + (2^n - 1) / 2.
#pragma once

#include <vector>

#include "haptics/height_grid.h"
#include "haptics/height_sampling.h"

namespace tsf::haptics {

enum class ScaleSpaceKind { kMipmap, kGaussian };

/// Most levels a ScaleSpace holds (the thesis used 10 mipmap levels).
inline constexpr int kMaxScaleLevels = 10;

/// Gaussian kernels are cut where the tail mass is below about 6e-5 of the
/// total (4 sigma each side); the cut weight is renormalised away.
inline constexpr double kGaussianTruncationSigmas = 4.0;

struct ScaleLevel {
    HeightGrid grid;
    double base_cells_per_texel = 1.0;  ///< 2^n for mipmap level n, 1 for Gaussian levels
    double t_cells2 = 0.0;              ///< Gaussian variance in base samples^2 (0 for mipmaps)
};

struct ScaleSpace {
    ScaleSpaceKind kind = ScaleSpaceKind::kMipmap;
    std::vector<ScaleLevel> levels;  ///< levels[0] is the base grid; never empty once built
    int count() const { return int(levels.size()); }
};

/// How a level is sampled: interpolation, and the gradient either analytic
/// (derivative of the interpolant) or by central differences of
/// central_step_texels of that level's own texels.
struct SamplingParams {
    Interpolation interpolation = Interpolation::kBicubic;
    bool central_differences = false;
    double central_step_texels = 0.5;
};

/// One mipmap step (eq. 5.2). A 1-cell axis stays 1 cell. Empty in, empty out.
HeightGrid mipmapDown(const HeightGrid& finer);

/// The grid convolved with a sampled 2D Gaussian of variance t_cells2
/// (separable), truncated at truncation_sigmas, mirrored borders.
/// t_cells2 <= 0 returns a copy.
HeightGrid gaussianBlur(const HeightGrid& grid, double t_cells2,
                        double truncation_sigmas = kGaussianTruncationSigmas);

/// Variance of Gaussian level n: 0 for n = 0, else 4^n cells^2.
double gaussianLevelVariance(int level);

/// Builds `levels` levels (clamped to [1, kMaxScaleLevels]) of the given kind.
/// An empty base gives an empty ScaleSpace.
///
/// samples_per_cell: base samples per data cell along each axis (1 for a
/// raster sampled cell by cell; printed_relief.h samples each hexagon more
/// finely). Levels are scaled in data cells, so level n smooths over about
/// 2^n data cells whatever the sampling: Gaussian level n has variance
/// 4^n data cells^2 (4^n samples_per_cell^2 samples^2), and mipmap level n
/// is the first halving whose texel spans at least 2^n data cells.
ScaleSpace buildScaleSpace(const HeightGrid& base, int levels, ScaleSpaceKind kind, double samples_per_cell = 1.0);

/// Height and gradient of one level at base coordinates (gi, gj); the
/// gradient is per BASE cell. level is clamped to the valid range.
HeightSample sampleLevel(const ScaleSpace& space, int level, double gi, double gj,
                         const SamplingParams& sampling) noexcept;

/// Thesis eq. 4.9: (1 - f) h_i + f h_{i+1} with i = floor(level), f its
/// fraction, for a continuous level in [0, count - 1] (clamped; NaN -> 0).
/// The gradient is blended the same way (eq. 4.11).
HeightSample sampleScale(const ScaleSpace& space, double level, double gi, double gj,
                         const SamplingParams& sampling) noexcept;

}  // namespace tsf::haptics
