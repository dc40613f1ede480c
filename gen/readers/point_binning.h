// binPoints: aggregates points into a hexagonal grid (a hexbin plot, thesis
// section 3.1).
//
// Frame: point x is east and y is NORTH in data units (lon/lat work as is);
// the hex grid is pointy-top, odd-r, row 0 = north (hex_grid.h).
//
// Lattice. The pitch p (centre spacing, data units) is bin_size when given,
// else chosen so the points' bounding box is hex_cols hexagons wide (for a
// box taller than wide the same rule is applied to its height, so the grid
// is about hex_cols hexagons along its longer side). Then the grid is the
// smallest one whose fully covered rectangle - x in [0.5, C] (or [0, C] for
// a single row) and y in [1/(2 sqrt 3), 3R/(2 sqrt 3)] pitches - holds the
// bounding box plus kCoverMargin on every side, and the box is centred in
// that rectangle. Every point therefore lies strictly inside one hexagon
// (found with hexCellAt) and is counted exactly once.
//
// Degenerate inputs: all points equal (or a single point) -> a 1 x 1 grid
// (pitch bin_size, or 1 data unit); points on a horizontal line -> one row;
// on a vertical line -> one column wide and hex_cols-ish rows tall.
// Coordinates are shifted by the bounding box's minimum before dividing by
// the pitch, so large offsets (1e9) do not cost precision.
//
// Aggregates per cell: Count = number of points (weights ignored); Sum = sum
// of the finite weights (0 for an empty cell); Mean = mean of the finite
// weights (NaN = no data for a cell without any). HexField.pitch_data = p;
// HexField.how is one line naming the aggregate, counts and sizes.
// Errors (InputError): no points, a non-finite coordinate, a coordinate
// range too large for a double, bin_size not finite or < 0, hex_cols < 0,
// Sum/Mean without a weight column, more than kMaxBinCells hexagons.
#pragma once

#include <cstdint>
#include <string>

#include "gen/field/hex_field.h"
#include "gen/field/hex_grid.h"
#include "gen/readers/point_reader.h"

namespace tsf {

/// hex_cols used when neither bin_size nor hex_cols is given.
inline constexpr int kDefaultPointBins = 30;
/// Largest grid binPoints makes.
inline constexpr int64_t kMaxBinCells = 4'000'000;
/// Gap (in pitches) kept between the points' bounding box and the edge of the
/// covered rectangle: far above the rounding error of the shifted, scaled
/// coordinates (about 1e-16 times the grid size in pitches), far below
/// anything visible.
inline constexpr double kCoverMargin = 1e-6;

struct BinOptions {
    enum class Aggregate { Count, Sum, Mean };
    Aggregate aggregate = Aggregate::Count;
    double bin_size = 0.0;  ///< pitch in data units; 0 = from hex_cols
    int hex_cols = 0;       ///< target hexagon columns when bin_size is 0; 0 = kDefaultPointBins
};

/// Where the lattice lies in data coordinates: a point (x, y) is at
///   x_pitch = (x - x_min) / pitch + u_min,  y_pitch = (y - y_min) / pitch + v_min
/// in the pitch units of hexCellAt (origin = grid bounding box lower-left).
struct BinLayout {
    HexGrid grid;
    double pitch = 1.0;  ///< data units
    double x_min = 0.0, y_min = 0.0;  ///< the points' bounding box minimum
    double u_min = 0.0, v_min = 0.0;  ///< its position on the lattice, pitches
};

/// The lattice binPoints uses for these points (validates as binPoints does).
BinLayout binLayout(const PointTable& points, const BinOptions& opts);

/// Bins the points; see the file comment.
HexField binPoints(const PointTable& points, const BinOptions& opts = {});

/// "count", "sum", "mean"; and the inverse (InputError otherwise).
const char* aggregateName(BinOptions::Aggregate aggregate);
BinOptions::Aggregate parseAggregate(const std::string& name);

}  // namespace tsf
