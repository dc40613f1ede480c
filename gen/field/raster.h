// Raster: a rectangular grid of scalar values as read from a file.
//
// Layout: row-major, row 0 is the TOP (north) edge of the picture or map,
// column 0 the left (west) edge. values.size() == cols * rows.
// A missing value ("no data") is stored as quiet NaN; readers never store Inf.
#pragma once

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/data_place.h"

namespace tsf {

/// One thing a reader detected or assumed about a file, for `tsf info`:
/// ("delimiter", "semicolon (detected)"), ("header", "line 1 skipped").
struct ReadFact {
    std::string name;
    std::string value;
};

/// A class of a categorical raster as the file names it.
struct RasterClass {
    double code = 0;   ///< the value the raster holds for it
    std::string name;  ///< its name in the file ("Open water"); "" when the file gives none
};

/// Metres along a meridian per degree of latitude on the mean Earth sphere
/// (radius 6 371 008.8 m, IUGG): within 0.6 % of the ellipsoid's at any latitude.
inline constexpr double kMetresPerDegreeOfLatitude = 6371008.8 * 3.14159265358979323846 / 180.0;

struct Raster {
    int32_t cols = 0;
    int32_t rows = 0;
    std::vector<double> values;  ///< row-major, row 0 = north; NaN = no data
    /// The values are class codes, not measurements (a band with a colour
    /// table): a hexagon takes the class most of its pixels have, never a
    /// mean of codes (gen/field/resample.h, Method::Mode).
    bool categorical = false;
    /// The classes the file names (category names, or a raster attribute
    /// table's name column), by code; empty when it names none.
    std::vector<RasterClass> classes;
    std::string units;           ///< the values' units as the file names them ("" when it does not)
    /// What the values are, in the file's own words: a NetCDF variable's
    /// long_name, a band's description ("elevation"); "" when it says none.
    std::string description;
    std::string variable;        ///< the variable read from a file of several ("pr"); "" otherwise
    /// The band's time step or level, short ("2000-02-01"); "" for a file of one band without one.
    std::string step;
    /// 1: every value is one of the file's. More: the file was too large to
    /// read whole, and each value is the mean (or most common class) of a
    /// block of about decimation x decimation of its pixels.
    int decimation = 1;
    std::string source;          ///< file it came from, for messages and SCAD headers
    std::string kind;            ///< "csv", "pgm", "png", "esri-ascii", ...
    /// Size of one raster cell in data units (ESRI cellsize; 1 for images/CSV):
    /// the distance between columns.
    double cell_size = 1.0;
    /// The distance between rows on the ground over the distance between
    /// columns: 1 for square pixels; a geographic grid's pixels of equal
    /// degrees are 1 / cos(latitude) as tall as wide (gen/field/resample.h).
    double row_aspect = 1.0;
    /// Rows or columns were repeated to make the pixels square (squarePixels,
    /// gen/field/resample.h): a hexagon per pixel is then no longer one per value.
    bool pixels_repeated = false;
    /// Metres on the ground per data unit of cell_size: a projected CRS's
    /// linear unit, kMetresPerDegreeOfLatitude for degrees; 0 when the file
    /// does not say (a picture, a CSV, a grid without a CRS).
    double metres_per_unit = 0.0;
    /// Geographic coordinates: a degree of longitude counted as this much of
    /// a degree of latitude (cos of the mean latitude); 0 otherwise.
    double longitude_scale = 0.0;
    /// Lower-left corner of the lower-left cell in data units (ESRI xllcorner/yllcorner).
    double x_origin = 0.0;
    double y_origin = 0.0;
    /// Where the pixels lie in the file's own coordinates (x_origin and
    /// cell_size are on the ground, this in the file's units); unknown for
    /// formats without coordinates.
    PixelPlace place;
    /// What the reader detected (dialect, header, no-data value, ...), in reading order.
    std::vector<ReadFact> facts;

    double at(int32_t col, int32_t row) const { return values[size_t(row) * size_t(cols) + size_t(col)]; }
    double& at(int32_t col, int32_t row) { return values[size_t(row) * size_t(cols) + size_t(col)]; }
    bool empty() const { return cols == 0 || rows == 0; }
    /// The value of the first fact named `name`; "" when there is none.
    std::string fact(const std::string& name) const {
        for (const ReadFact& f : facts)
            if (f.name == name) return f.value;
        return "";
    }
};

}  // namespace tsf
