// Map projection for points given as longitude / latitude (or in a CRS).
//
// A count of points per hexagon is a density only when every hexagon
// covers the same ground. Binning raw degrees would stretch a map
// east-west by 1 / cos(latitude), and an equirectangular projection about
// the mean latitude still gives a hexagon cos(latitude) / cos(mean
// latitude) of the ground it should (the far north of Europe half as
// dense as it is). So lon/lat points are projected with PROJ (through
// tsf's GDAL module, gen/readers/gdal_reader.h) onto an equal-area
// projection chosen from their extent:
//   - a region: Lambert azimuthal equal-area centred on the extent's middle;
//   - the world (over 180 degrees of longitude or 100 of latitude): Equal Earth;
// with x, y in kilometres (--bin is then in km). North is up at the centre.
// `--project equirect` keeps the old equirectangular projection (x = lon x
// cos(mean latitude), in degrees of latitude); `--project DEF` projects onto
// any PROJ/EPSG definition; `--crs DEF` says the x, y columns are in that
// CRS (e.g. EPSG:3857 exports), and they are brought to lon/lat first.
// The description returned names the projection and the largest area
// distortion over the points (the spread of ground area per map area, from
// the WGS84 ellipsoid's own area), so a reader of the summary knows whether
// a count per hexagon is a density.
#pragma once

#include <string>

#include "gen/readers/point_reader.h"

namespace tsf {

enum class Projection {
    Auto,        ///< EqualArea when the columns look like longitude / latitude (or --crs), else None
    None,        ///< use x and y as they are
    Equirect,    ///< equirectangular about the mean latitude (x = lon, y = lat)
    EqualArea,   ///< Lambert azimuthal equal-area (a region) or Equal Earth (the world)
    Definition,  ///< any PROJ/EPSG definition
};

struct ProjectionChoice {
    Projection kind = Projection::Auto;
    std::string definition;  ///< with Projection::Definition
};

/// "auto", "none", "equirect", "equal-area", or a PROJ/EPSG definition
/// ("EPSG:3035", "+proj=..."); an empty name is an InputError.
ProjectionChoice parseProjection(const std::string& name);

/// True when the x column is named like a longitude (lon, lng, long,
/// longitude, ...) and y like a latitude (lat, latitude, ...), case-insensitive,
/// and every x is within [-180, 180] and every y within [-90, 90].
bool looksLikeLonLat(const PointTable& points);

/// Projects points in place as `projection` asks; `crs` (may be empty): the
/// CRS the x, y columns are in. Returns a one-line description of what was
/// done ("" when nothing was). Longitudes or latitudes out of range, an
/// unknown definition or a point PROJ cannot project are InputErrors.
/// `metres_per_unit` (may be null) is set to the projected x, y's unit in
/// metres when tsf chose the projection (1000: km; equirect: a degree of
/// latitude), 0 otherwise.
std::string projectPoints(PointTable& points, const ProjectionChoice& projection, const std::string& crs = "",
                          double* metres_per_unit = nullptr);

}  // namespace tsf
