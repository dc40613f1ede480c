// readRaster: reads any supported raster file into a tsf::Raster.
//
// Formats (see each reader's header for details and errors):
//   csv         grid of numbers (csv_grid_reader.h); also .txt, .tsv
//   pgm         netpbm greymap P2/P5 (pgm_reader.h)
//   png         greyscale PNG (png_reader.h)
//   esri-ascii  ESRI ASCII grid .asc (esri_ascii_reader.h)
//   gdal        GeoTIFF and any other raster GDAL reads (gdal_reader.h)
// Detection (RasterFormat::Auto): the content decides first - a PNG
// signature, "P2"/"P5" (or another netpbm magic, to name it in the error),
// any other binary file (a TIFF or JPEG magic number, a NUL byte;
// file_magic.h) goes to GDAL and is never parsed as text, a first word
// "ncols"/"nrows" is ESRI (any case); then the extension (.png, .pgm/.pnm,
// .asc; .tif, .tiff, .hgt, .img, .vrt, .nc, .jp2, .bil, .flt, .dem, .dt0-2
// go to GDAL); anything else is read as grid CSV. When GDAL cannot read a
// binary file the error says what its magic bytes say it is.
#pragma once

#include <string>
#include <string_view>

#include "gen/readers/decimal_mark.h"
#include "gen/field/raster.h"

namespace tsf {

enum class RasterFormat { Auto, Csv, Pgm, Png, EsriAscii, Gdal };

struct RasterReadOptions {
    RasterFormat format = RasterFormat::Auto;
    /// Grid CSV only: 0 = detect, else ',', ';', '\t' or ' ' (runs of blanks).
    char delimiter = 0;
    /// Grid CSV only: Detect, or Comma for "1,5" (decimal_mark.h).
    DecimalMark decimal = DecimalMark::Detect;
    /// Rasters GDAL reads: which band, 1-based. Other formats have one band
    /// and refuse another number.
    int band = 1;
    /// Rasters GDAL reads: which variable of a file with several (NetCDF,
    /// HDF5, GeoPackage); "" = the only one.
    std::string variable;
    /// Rasters GDAL reads: ignore the geotransform and the CRS and read the
    /// plain grid (--ignore-georef; gdal_reader.h).
    bool ignore_georef = false;
};

/// Reads `path`. Throws InputError for a missing file or any format error.
Raster readRaster(const std::string& path, const RasterReadOptions& opts = {});

/// Same as readRaster on bytes already in memory (`path` is used for the
/// extension and in messages).
Raster parseRaster(std::string_view bytes, const std::string& path, const RasterReadOptions& opts = {});

/// The format Auto would choose for these bytes and this file name.
RasterFormat detectRasterFormat(std::string_view bytes, const std::string& path);

/// "csv", "pgm", "png", "esri-ascii", "gdal" or "auto"; the same strings as
/// Raster::kind (which for GDAL adds the driver: "gdal/GTiff").
const char* rasterFormatName(RasterFormat format);

/// Inverse of rasterFormatName (also accepts "asc", "esri"); throws
/// InputError listing the valid names otherwise.
RasterFormat parseRasterFormat(const std::string& name);

}  // namespace tsf
