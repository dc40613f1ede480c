// FieldInput: what was read from an input file before it became hexagons,
// for `tsf info` and the summary of `tsf gen`: the reader's detections and
// the raw values' range, in the file's own units.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "gen/field/raster.h"

namespace tsf {

struct FieldInput {
    std::string kind;             ///< "csv", "png", "esri-ascii", "points", ...
    int64_t cols = 0, rows = 0;   ///< raster size in values (0 for points)
    int64_t values = 0;           ///< values read: raster cells, or points
    int64_t nodata = 0;           ///< of them without data (NaN, a placeholder, --nodata)
    double min = NAN, max = NAN, mean = NAN;  ///< over the values with data; NaN when none
    std::vector<ReadFact> facts;  ///< what the reader detected, in reading order
    std::string units;            ///< the values' units as the file names them ("" when it does not)
    std::string description;      ///< what the values are in the file's words (Raster::description)
    std::string variable;         ///< the variable read (Raster::variable)
    std::string step;             ///< the band's time step or level (Raster::step)
    /// The values are class codes (a colour table or class names in the
    /// file, or --categorical): a hexagon takes one class, never a mean.
    bool categorical = false;
    std::vector<RasterClass> classes;  ///< the classes the file names, by code (empty: none named)
    /// --class-order: the class codes from lowest to highest. The field's
    /// values are then the classes' ranks (1 for class_order[0], ...), so
    /// each class is one even step of height; empty: the values are the
    /// codes and the heights follow them.
    std::vector<double> class_order;
    /// The ground the raster covers, metres (0 when the file does not say:
    /// Raster::metres_per_unit), and how longitude was scaled (Raster::longitude_scale).
    double ground_width_m = 0, ground_depth_m = 0;
    double metres_per_unit = 0;
    double longitude_scale = 0;
    /// Points binned on a projection tsf chose: the ground area of one
    /// hexagon, km^2 (0 otherwise).
    double hexagon_area_km2 = 0;
};

/// Counts `values` (NaN = no data) and takes min, max and mean of the others.
void describeValues(std::span<const double> values, FieldInput& into);

}  // namespace tsf
