// ESRI ASCII grid (.asc, "Arc/Info ASCII grid") reader.
//
// Header: "key value" pairs, keys in any order and any case:
//   ncols, nrows              required, whole numbers >= 1
//   xllcorner | xllcenter     required (one of them)
//   yllcorner | yllcenter     required (one of them)
//   cellsize                  required, > 0 (or dx and dy with dx == dy)
//   NODATA_value              optional; cells equal to it become NaN
// then nrows x ncols values, the first line being the TOP (north) row and
// each line running west to east. Values are decimal numbers; "nan" (as
// written by GDAL for NaN) is also no data. A UTF-8 byte-order mark at the
// start is skipped.
//
// Raster fields: cell_size = cellsize; x_origin, y_origin = lower-left
// corner of the lower-left cell (a *center value is moved by half a cell).
//
// Line structure: when the first data line has exactly ncols values, every
// data line must have ncols values (a line with too few or too many is an
// error naming that line and both counts). Otherwise values may wrap freely
// and only their total is checked.
// Errors (tsf::InputError with line/column): unknown, repeated or missing
// header keys, bad header values, non-square cells (dx != dy), a size over
// the limits of raster_limits.h, a value that is not a number or infinite,
// too few values (the line where they end) or too many (the first extra one).
#pragma once

#include <string>
#include <string_view>

#include "gen/field/raster.h"

namespace tsf {

/// Parses ESRI ASCII grid text. `path` names the source in errors and Raster::source.
Raster parseEsriAscii(std::string_view text, const std::string& path);

/// Reads and parses an ESRI ASCII grid file.
Raster readEsriAscii(const std::string& path);

}  // namespace tsf
