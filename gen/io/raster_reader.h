// readRaster: reads any supported raster file into a tsf::Raster.
//
// Formats (see each reader's header for details and errors):
//   csv         grid of numbers (csv_grid_reader.h); also .txt, .tsv
//   pgm         netpbm greymap P2/P5 (pgm_reader.h)
//   png         greyscale PNG (png_reader.h)
//   esri-ascii  ESRI ASCII grid .asc (esri_ascii_reader.h)
// Detection (RasterFormat::Auto): the content decides first - a PNG
// signature, "P2"/"P5" (or another netpbm magic, to name it in the error),
// or a first word "ncols"/"nrows" (ESRI, any case); then the extension
// (.png, .pgm/.pnm, .asc); anything else is read as grid CSV.
#pragma once

#include <string>
#include <string_view>

#include "gen/io/decimal_mark.h"
#include "gen/raster.h"

namespace tsf {

enum class RasterFormat { Auto, Csv, Pgm, Png, EsriAscii };

struct RasterReadOptions {
    RasterFormat format = RasterFormat::Auto;
    /// Grid CSV only: 0 = detect, else ',', ';', '\t' or ' ' (runs of blanks).
    char delimiter = 0;
    /// Grid CSV only: Detect, or Comma for "1,5" (decimal_mark.h).
    DecimalMark decimal = DecimalMark::Detect;
};

/// Reads `path`. Throws InputError for a missing file or any format error.
Raster readRaster(const std::string& path, const RasterReadOptions& opts = {});

/// Same as readRaster on bytes already in memory (`path` is used for the
/// extension and in messages).
Raster parseRaster(std::string_view bytes, const std::string& path, const RasterReadOptions& opts = {});

/// The format Auto would choose for these bytes and this file name.
RasterFormat detectRasterFormat(std::string_view bytes, const std::string& path);

/// "csv", "pgm", "png", "esri-ascii" or "auto"; same strings as Raster::kind.
const char* rasterFormatName(RasterFormat format);

/// Inverse of rasterFormatName (also accepts "asc", "esri"); throws
/// InputError listing the valid names otherwise.
RasterFormat parseRasterFormat(const std::string& name);

}  // namespace tsf
