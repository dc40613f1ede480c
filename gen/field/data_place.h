// Where the values lie in the data's own coordinates (a raster's georeference,
// an ESRI grid's corner and cell size), carried from the reader to the model
// so that what marks a place on the model (the edge ruler) can say which x
// and y it marks. Known only where the file says it: a CSV grid, a PGM or a
// PNG has no coordinates, and nothing is invented for them.
#pragma once

#include <cstdint>
#include <string>

namespace tsf {

/// The axes' names and unit, for a reader: "x"/"y" (no unit known),
/// "easting"/"northing" in "metres", "longitude"/"latitude" in "degrees".
struct DataAxes {
    std::string x = "x", y = "y";
    std::string unit;  ///< plural, for a sentence; "" when the file does not say
};

/// A raster's pixels in the data's coordinates: the pixel position px (east,
/// from the west edge, in pixels) is x = x_west + px * dx; py (down from
/// the north edge, in pixels) is y = y_north - py * dy.
struct PixelPlace {
    bool known = false;
    double x_west = 0, dx = 1;
    double y_north = 0, dy = 1;
    DataAxes axes;
};

/// Each hexagon of a field in the data's coordinates: the point its value
/// stands for (a pixel's centre, one pillar per value; the hexagon's
/// centre, resampled). Row 0 is the north row; odd rows may be shifted
/// east by a share of a column (odd-r lattice, gen/field/hex_grid.h).
struct CellPlace {
    bool known = false;
    double x0 = 0, x_per_col = 1, odd_row_shift_cols = 0;
    double y0 = 0, y_per_row = -1;
    DataAxes axes;

    double x(int32_t col, int32_t row) const { return x0 + x_per_col * (double(col) + odd_row_shift_cols * double(row & 1)); }
    double y(int32_t row) const { return y0 + y_per_row * double(row); }
};

/// One hexagon per pixel: each stands for its pixel's centre.
CellPlace pixelCells(const PixelPlace& p);

}  // namespace tsf
