// Map projection for points given as longitude / latitude.
//
// Binning raw degrees would stretch a map east-west by 1 / cos(latitude)
// (Europe at 50 N comes out 1.56 times too wide). Equirectangular projection
// about the points' mean latitude phi0 fixes that near phi0:
//     x' = lon * cos(phi0),   y' = lat        (both in degrees of latitude)
// Bin sizes (--bin) are then in degrees of latitude (about 111 km).
#pragma once

#include <string>

#include "gen/readers/point_reader.h"

namespace tsf {

enum class Projection {
    Auto,      ///< Equirect when the columns look like longitude / latitude, else None
    None,      ///< use x and y as they are
    Equirect,  ///< equirectangular about the mean latitude (x = lon, y = lat)
};

/// "auto", "none", "equirect"; InputError otherwise.
Projection parseProjection(const std::string& name);

/// True when the x column is named like a longitude (lon, lng, long,
/// longitude, ...) and y like a latitude (lat, latitude, ...), case-insensitive,
/// and every x is within [-180, 180] and every y within [-90, 90].
bool looksLikeLonLat(const PointTable& points);

/// Projects points in place as `projection` asks. Returns a one-line
/// description of what was done ("" when nothing was). Equirect on values
/// outside [-180, 180] x [-90, 90] is an InputError.
std::string projectPoints(PointTable& points, Projection projection);

}  // namespace tsf
