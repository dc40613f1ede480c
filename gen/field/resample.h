// resampleRaster: a Raster (square pixels) onto the hexagonal lattice.
//
// Geometry. The raster covers the rectangle [0, cols] x [0, rows] in pixel
// units, x east, y DOWN from the top edge; pixel (c, r) has its centre at
// (c + 0.5, r + 0.5). The hex grid (pointy-top, odd-r, row 0 = north, see
// hex_grid.h) is laid over it so that the field keeps the raster's aspect
// ratio:
//   - C = hex_cols hexagon columns (0 = the raster's column count, at most
//     kMaxResampleCols);
//   - pitch p (centre spacing, pixels) = cols / (C + 0.5), so the even rows
//     and the half-cell-shifted odd rows both fit across the raster;
//   - R = max(1, round(rows / (p * sqrt(3) / 2))) hex rows (rows of hexagons
//     are p * sqrt(3) / 2 apart);
//   - except: if a single hex row results with p = cols / C (no odd row to
//     fit), that pitch is used and R = 1 (so a 1 x 1 raster gives 1 x 1, and
//     an N x 1 strip gives N hexagons);
//   - the lattice's bounding box (gridWidth x gridDepth of hex_grid.h) is
//     centred on the raster.
// So the grid's width/depth ratio matches the raster's within half a hex row.
//
// Methods (NaN pixels are "no data"):
//   - Mean: mean of the finite pixels whose CENTRES lie in the hexagon. A
//     hexagon that contains no pixel centre (hexagons smaller than pixels)
//     takes the pixel containing its centre. A hexagon whose pixels are all
//     NaN is NaN.
//   - Mode: the value most of the finite pixels whose centres lie in the
//     hexagon have (ties: the smallest of them), for class codes (land
//     cover): always a value of the raster, never an invented one. A
//     hexagon with no pixel centre takes the pixel containing its centre.
//   - Nearest: the pixel containing the hexagon's centre (clamped to the
//     raster at the edges).
//   - Bilinear: bilinear interpolation between the four pixel centres around
//     the hexagon's centre (clamped to the edge pixels); NaN if any of those
//     pixels that has a non-zero weight is NaN.
//
// Output: HexField.source = raster.source; how = one line naming the method
// and the sizes; pitch_data = p * raster.cell_size (data units).
// Errors: InputError for an empty raster, hex_cols < 0 or > kMaxResampleCols,
// or a grid over kMaxResampleCells hexagons.
#pragma once

#include <cstdint>
#include <string>

#include "gen/field/hex_field.h"
#include "gen/field/raster.h"

namespace tsf {

/// Largest number of hexagon columns resampleRaster makes (also the cap on
/// the default of one column per raster column). A 1000-column model is
/// already 0.1 mm per pillar on a 100 mm print.
inline constexpr int32_t kMaxResampleCols = 1000;
/// Largest number of hexagons resampleRaster makes (very tall thin rasters).
inline constexpr int64_t kMaxResampleCells = 4'000'000;

struct ResampleOptions {
    enum class Method { Mean, Nearest, Bilinear, Mode };
    int hex_cols = 0;  ///< hexagon columns; 0 = raster cols, capped at kMaxResampleCols
    Method method = Method::Mean;
};

/// Resamples `raster` onto a hex grid as described in the file comment.
HexField resampleRaster(const Raster& raster, const ResampleOptions& opts = {});

/// The lattice resampleRaster uses, without the values: grid size and the
/// pitch in pixels. Exposed for tests and for tools that show the layout.
struct ResampleLayout {
    HexGrid grid;
    double pitch_px = 1.0;
    /// Pixel position (x east, y down) of the grid's bounding-box lower-left
    /// corner: lattice point (i, j) is at x = x0_px + i * p / 2,
    /// y = y0_px - j * p / (2 sqrt 3).
    double x0_px = 0.0;
    double y0_px = 0.0;
};
ResampleLayout resampleLayout(int32_t raster_cols, int32_t raster_rows, int hex_cols);

/// Smallest hexagon (width across flats, mm) tsf chooses by default: about the
/// two-point threshold of a fingertip (2-4 mm, Weinstein 1968); smaller
/// pillars are felt as texture, not as separate values. docs/model.md.
inline constexpr double kMinTactileCellMm = 3.0;

/// One hexagon per raster cell: cell (col, row) of the raster becomes hex
/// (col, row) of the lattice (row 0 north, odd rows shifted east by half a
/// cell), with the raster's own value. Its rows are the raster's, a pixel
/// apart on the ground like its columns (HexField::rows_a_pitch_apart): a
/// Scene with true aspect stretches the hexagons north-south to keep that
/// (hex_grid.h). HexField::one_to_one is set.
HexField rasterOneToOne(const Raster& raster);

/// Rows this much farther apart on the ground than columns, or this much
/// closer (Raster::row_aspect), keep one pillar per value in stretched
/// hexagons; beyond, the hexagons would be slivers, and the pixels are made
/// square first (a geographic grid above 60 degrees of latitude).
inline constexpr double kMaxStretchedRowAspect = 2.0;

/// The raster with square pixels on the ground (Raster::row_aspect 1): the
/// shorter side repeated, nearest pixel, as a resampling must have them; a
/// "resampled" fact says so. A raster of square pixels is returned as is.
Raster squarePixels(const Raster& raster);

/// How a raster becomes hexagons by default (tsf gen without --bins).
struct RasterPlacement {
    int hex_cols = 0;           ///< --bins; 0 = decide here
    ResampleOptions::Method method = ResampleOptions::Method::Mean;
    double pitch_mm = 0;        ///< --cell; 0 = fit the box
    double fit_width_mm = 150;  ///< the box the model must fit (printer bed)
    double fit_depth_mm = 150;
    double min_cell_mm = kMinTactileCellMm;  ///< smallest default cell; never below kMinTactileCellMm (a wide nozzle raises it)
    bool true_aspect = true;    ///< one pillar per value keeps the ground's aspect (SceneParams::true_aspect)
};

/// One pillar per value when the grid fits the box at kMinTactileCellMm or
/// more (or a cell size was given); otherwise resampled to the most columns
/// that keep cells at least kMinTactileCellMm (or min_cell_mm when larger), and `how` says from what to
/// what and why. hex_cols > 0 always resamples to that many columns.
/// Pixels that are not square on the ground stay one pillar per value in
/// hexagons stretched to their shape (true aspect, within
/// kMaxStretchedRowAspect); resampling, regular hexagons and shapes beyond
/// that make them square first (squarePixels).
HexField placeRaster(const Raster& raster, const RasterPlacement& placement);

/// "mean", "nearest", "bilinear"; and the inverse (InputError otherwise).
const char* resampleMethodName(ResampleOptions::Method method);
ResampleOptions::Method parseResampleMethod(const std::string& name);

}  // namespace tsf
