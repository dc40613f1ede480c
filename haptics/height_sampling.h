// Continuous height and gradient of a HeightGrid at any grid coordinate.
//
// Coordinates: continuous grid coordinates (gi, gj) as in height_grid.h -
// cell (i, j) has its centre at (i, j); gi runs east, gj north.
//
// Interpolation:
//   bilinear  thesis eq. 5.1: weights (1-a)(1-b), a(1-b), (1-a)b, ab over the
//             four surrounding cell centres. C0: the gradient jumps where a
//             cell border is crossed (a felt ridge on slopes that bend).
//   bicubic   Catmull-Rom in each direction over the 4x4 surrounding centres.
//             Interpolating (passes through every cell value) and C1: height
//             and gradient are continuous everywhere, so no ridge is felt at
//             cell borders. It may overshoot the cell values slightly (at
//             most 1/8 of a step) next to sharp steps.
//
// Outside the field: coordinates are clamped to the outermost cell centres,
// so the surface continues flat beyond the border with the edge value and a
// zero gradient across the edge. Bicubic taps beyond the border mirror the
// interior (tap -1 reads cell 1), which makes the slope across the edge zero
// at the last centre - the clamped outside then joins with C1 continuity.
//
// Gradients are in height units per grid cell. Fields of 1 x N, N x 1 and
// 1 x 1 are valid (constant along a one-cell direction). Every function here
// is noexcept, allocation-free and returns finite values for finite input;
// a NaN coordinate is treated as the field centre (callers reject NaN before,
// this is the last line of defence).
#pragma once

#include "haptics/height_grid.h"

namespace tsf::haptics {

enum class Interpolation { kBilinear, kBicubic };

/// Height (0..1, bicubic may overshoot slightly) and its gradient per cell.
struct HeightSample {
    double height = 0.0;
    double d_di = 0.0;  ///< d height / d gi (east)
    double d_dj = 0.0;  ///< d height / d gj (north)
};

/// Height with its analytic gradient (the exact derivative of the
/// interpolant; on a bilinear cell border, the derivative of the cell on the
/// east/north side).
HeightSample sampleHeight(const HeightGrid& grid, double gi, double gj, Interpolation interpolation) noexcept;

/// Height only (same surface as sampleHeight, cheaper for bilinear).
double sampleHeightOnly(const HeightGrid& grid, double gi, double gj, Interpolation interpolation) noexcept;

/// Height with the gradient by central differences of the interpolant
/// (thesis eq. 4.4): (h(g + step) - h(g - step)) / (2 step) per axis. A step of
/// about half a cell smooths the bilinear gradient jump into a continuous
/// ramp one cell wide. step_cells must be > 0.
HeightSample sampleHeightCentral(const HeightGrid& grid, double gi, double gj, Interpolation interpolation,
                                 double step_cells) noexcept;

}  // namespace tsf::haptics
