// GDAL reader: GeoTIFF and every other raster GDAL reads (Debian libgdal-dev),
// the way elevation data usually comes.
//
// GDAL itself lives in a module, tsf-gdal.so (gdal/gdal_module.cpp, the only
// file that includes GDAL), loaded with dlopen on the first call: linked
// into tsf, GDAL's hundred-odd libraries cost every command about 70 ms at
// start. It is looked for in $TSF_GDAL_MODULE (alone, when set), beside the
// running binary, in <prefix>/lib/tsf for <prefix>/bin/tsf, and where the
// build put it. A missing or foreign module is a std::runtime_error naming
// the places looked in (exit code 3 in the CLI: a missing tool).
//
// Reads one band (band 1 unless asked) as doubles. Layout as every Raster: row 0 north, column 0
// west (GDAL's own order for north-up rasters).
//   - no data: the band's no-data value becomes NaN (so do NaN pixels);
//   - pixel size and CRS (from the geotransform and the spatial reference):
//       projected CRS (or none, or a local one): the pixels' width and height
//         in its units; true aspect is kept;
//       geographic CRS (degrees): a degree of longitude is cos(latitude)
//         of a degree of latitude, at the raster's mean latitude; the pixel
//         width is scaled by it;
//     when the pixels are then not square, the raster is resampled (nearest
//     neighbour, so no-data and values stay exact) to square pixels the size
//     of the smaller side, so the model keeps the ground's aspect;
//     Raster::cell_size is that side, in the CRS's units (degrees of
//     latitude for a geographic CRS);
//   - a rotated or sheared geotransform is resampled north-up in the CRS's
//     coordinates (nearest neighbour, so values and classes stay exact):
//     square pixels of the source pixel's ground area, no data outside the
//     raster's own outline; a fact gives the raster's sides on the ground
//     and the bearing its top edge faced; the ground size is the north-up
//     box the model shows;
//   - ignore_georef (--ignore-georef): the geotransform and CRS are not
//     read; the plain grid, pixels square, no ground size;
//   - a raster larger than 4 million values (or 20 000 a side) after that is
//     read DECIMATED: both sides divided by the smallest whole factor that
//     fits, each value the mean of the pixels with data in its block (the
//     most common class for a class map), strip by strip, so memory is the
//     result and one strip of source rows (a 40 000 x 40 000 GeoTIFF: 2000 x
//     2000 values in about 150 MB); Raster::decimation says by how much and
//     the field's description says the values are means. Sides up to a
//     million pixels are read so.
// Raster::facts names the GDAL driver, the band, the CRS, the pixel size, the
// no-data value and any resampling; Raster::kind is "gdal/<driver>"
// ("gdal/GTiff").
// Errors (tsf::InputError naming the file): GDAL cannot open it (GDAL's
// message), no raster band, a size over raster_limits.h, a read failure.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "gen/field/raster.h"

namespace tsf {

/// Reads the raster file at `path` through GDAL.
/// `band` is 1-based (a band, a time step or a level); a band the file does
/// not have is an InputError saying how many it has.
/// `variable` picks one of a file's variables (NetCDF, HDF5, GeoPackage
/// rasters; GDAL's subdatasets) by name; "" takes the only one, and a file
/// of several without one is an InputError listing them. `path` may also be
/// GDAL's own name of a variable: NETCDF:"file.nc":pr.
/// `ignore_georef` reads the plain grid: square pixels of one unit, no CRS,
/// no ground size (--ignore-georef).
Raster readGdalRaster(const std::string& path, int band = 1, const std::string& variable = "",
                      bool ignore_georef = false);

/// Transforms points in place from CRS `from` to `to` (anything GDAL reads
/// as user input: "EPSG:4326", a PROJ string, WKT) with PROJ, x east and y
/// north whatever the authority's axis order; returns the target's name.
/// An unknown CRS or a point that cannot be projected is an InputError.
std::string transformCoordinates(const std::string& from, const std::string& to, std::vector<double>& x,
                                 std::vector<double>& y);

/// Same on bytes in memory (GDAL's /vsimem/); `path` names them in messages
/// and tells GDAL the extension. Files that need a sidecar (.hdr, .prj)
/// must be read with readGdalRaster.
Raster parseGdalRaster(std::string_view bytes, const std::string& path, int band = 1, const std::string& variable = "",
                       bool ignore_georef = false);

/// True when path is GDAL's name of a dataset inside a file rather than a
/// file name: DRIVER:"file":variable or DRIVER:file:variable (NETCDF:,
/// HDF5:, GPKG:), with a driver name of two or more letters.
bool isGdalDatasetName(const std::string& path);

}  // namespace tsf
