#include "gen/readers/point_projection.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

#include "gen/field/raster.h"
#include "gen/readers/gdal_reader.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kDeg = kPi / 180.0;
// WGS84: semi-major axis (km) and first eccentricity squared.
constexpr double kWgs84A = 6378.137;
constexpr double kWgs84E2 = 0.00669437999014;
const char* kLonLat = "EPSG:4326";
// Points sampled for the area distortion (every n-th).
constexpr size_t kDistortionSamples = 2000;

std::string lower(std::string s) {
    std::transform(s.begin(), s.end(), s.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return s;
}

bool nameIs(const std::string& name, std::initializer_list<const char*> options) {
    const std::string n = lower(name);
    for (const char* o : options)
        if (n == o) return true;
    return false;
}

bool inRange(const PointTable& p) {
    for (size_t k = 0; k < p.size(); ++k)
        if (!(std::fabs(p.x[k]) <= 180.0) || !(std::fabs(p.y[k]) <= 90.0)) return false;
    return p.size() > 0;
}

// Ground area (km^2) of a small cell of dlon x dlat degrees at latitude lat
// on the WGS84 ellipsoid: M(lat) N(lat) cos(lat) dlat dlon (radians).
double groundAreaKm2(double lat_deg, double dlon_deg, double dlat_deg) {
    const double s = std::sin(lat_deg * kDeg), w = 1 - kWgs84E2 * s * s;
    const double m = kWgs84A * (1 - kWgs84E2) / (w * std::sqrt(w)), n = kWgs84A / std::sqrt(w);
    return m * n * std::cos(lat_deg * kDeg) * dlon_deg * kDeg * dlat_deg * kDeg;
}

// The spread of map area per ground area over (a sample of) the points:
// max / min - 1, from the map positions of each point and of two points a
// small step east and north of it. `project` maps lon/lat vectors in place.
template <class Project>
double areaDistortion(const std::vector<double>& lon, const std::vector<double>& lat, Project project) {
    const size_t every = std::max<size_t>(1, lon.size() / kDistortionSamples);
    std::vector<double> x, y;
    constexpr double d = 1e-3;  // degrees
    for (size_t k = 0; k < lon.size(); k += every) {
        // Keep the little cell on the globe (away from the poles and the antimeridian).
        const double la = std::clamp(lat[k], -89.9, 89.9 - d), lo = std::min(lon[k], 180.0 - d);
        x.insert(x.end(), {lo, lo + d, lo});
        y.insert(y.end(), {la, la, la + d});
    }
    const std::vector<double> lon0 = x, lat0 = y;
    project(x, y);
    double lo = INFINITY, hi = 0;
    for (size_t k = 0; k + 2 < x.size(); k += 3) {
        const double ax = x[k + 1] - x[k], ay = y[k + 1] - y[k], bx = x[k + 2] - x[k], by = y[k + 2] - y[k];
        const double map = std::fabs(ax * by - ay * bx), ground = groundAreaKm2(lat0[k], d, d);
        if (!(ground > 0) || !(map > 0)) continue;
        lo = std::min(lo, map / ground);
        hi = std::max(hi, map / ground);
    }
    return hi > 0 && lo > 0 ? hi / lo - 1 : 0.0;
}

/// Where lon/lat points lie on the sphere: their spherical mean (the
/// normalised sum of their unit vectors; a pole whatever the longitudes
/// given there), the largest angle from it to a point, and the middle of
/// their longitudes unwrapped across the antimeridian (the largest gap
/// between sorted longitudes is where the map is cut).
struct SphereExtent {
    double lat0 = 0, lon0 = 0;  ///< the spherical mean, degrees
    double max_angle_deg = 0;   ///< the farthest point from it, degrees of arc
    double lon_middle = 0;      ///< the middle of the unwrapped longitudes, in [-180, 180)
    double lon_span = 0;        ///< their span, degrees
};

// Below this length per point the sum of the unit vectors has no direction
// (points spread evenly round the globe), and below this share of its
// length its horizontal part has none (a mean at a pole): both far above the
// rounding of a sum of unit vectors, far below any real spread.
constexpr double kNoMeanPerPoint = 1e-9;
constexpr double kAtPole = 1e-12;

SphereExtent sphereExtent(const std::vector<double>& lon, const std::vector<double>& lat) {
    SphereExtent e;
    double sx = 0, sy = 0, sz = 0;
    for (size_t k = 0; k < lon.size(); ++k) {
        const double cl = std::cos(lat[k] * kDeg);
        sx += cl * std::cos(lon[k] * kDeg);
        sy += cl * std::sin(lon[k] * kDeg);
        sz += std::sin(lat[k] * kDeg);
    }
    const double norm = std::sqrt(sx * sx + sy * sy + sz * sz);
    // Points that cancel out (spread evenly round the globe) have no mean: the
    // farthest-angle test below then sends them to the world projection.
    if (norm > kNoMeanPerPoint * double(lon.size())) {
        e.lat0 = std::asin(std::clamp(sz / norm, -1.0, 1.0)) / kDeg;
        e.lon0 = std::hypot(sx, sy) > kAtPole * norm ? std::atan2(sy, sx) / kDeg : 0.0;
        for (size_t k = 0; k < lon.size(); ++k) {
            const double cl = std::cos(lat[k] * kDeg);
            const double dot = (cl * std::cos(lon[k] * kDeg) * sx + cl * std::sin(lon[k] * kDeg) * sy +
                                std::sin(lat[k] * kDeg) * sz) / norm;
            e.max_angle_deg = std::max(e.max_angle_deg, std::acos(std::clamp(dot, -1.0, 1.0)) / kDeg);
        }
    } else {
        e.max_angle_deg = 180;
    }
    std::vector<double> sorted = lon;
    for (double& v : sorted) v = v >= 180 ? v - 360 : v;  // 180 and -180 are one meridian
    std::sort(sorted.begin(), sorted.end());
    double gap = sorted.front() + 360 - sorted.back(), start = sorted.front();  // the gap across the antimeridian
    for (size_t k = 1; k < sorted.size(); ++k)
        if (sorted[k] - sorted[k - 1] > gap) {
            gap = sorted[k] - sorted[k - 1];
            start = sorted[k];
        }
    e.lon_span = 360 - gap;
    e.lon_middle = start + e.lon_span / 2;
    if (e.lon_middle >= 180) e.lon_middle -= 360;
    return e;
}

std::string distortionText(double d) {
    return "area distortion at most " + formatFixed(100 * d, 1) + " %" +
           (d < 0.02 ? " (equal-area: a count per hexagon is a density)" : " (a count per hexagon is not a density)");
}

}  // namespace

ProjectionChoice parseProjection(const std::string& name) {
    if (name == "auto") return {Projection::Auto, ""};
    if (name == "none") return {Projection::None, ""};
    if (name == "equirect") return {Projection::Equirect, ""};
    if (name == "equal-area") return {Projection::EqualArea, ""};
    if (name.empty())
        throw InputError("--project: expected auto, none, equirect, equal-area or a PROJ/EPSG definition (e.g. EPSG:3035)");
    return {Projection::Definition, name};
}

bool looksLikeLonLat(const PointTable& p) {
    return nameIs(p.x_name, {"lon", "lng", "long", "longitude", "lon_deg", "longitude_deg", "x_lon"}) &&
           nameIs(p.y_name, {"lat", "latitude", "lat_deg", "latitude_deg", "y_lat"}) && inRange(p);
}

std::string projectPoints(PointTable& p, const ProjectionChoice& projection, const std::string& crs,
                          double* metres_per_unit) {
    if (metres_per_unit) *metres_per_unit = 0;
    if (projection.kind == Projection::None || p.size() == 0) return "";
    std::string how;
    if (!crs.empty()) {
        // Columns in a CRS of their own (e.g. Web Mercator exports): to lon/lat first.
        transformCoordinates(crs, kLonLat, p.x, p.y);
        how = "x, y read in " + crs + ", ";
    } else if (projection.kind == Projection::Auto && !looksLikeLonLat(p)) {
        return "";
    }
    for (size_t k = 0; k < p.size(); ++k)
        if (!(std::fabs(p.x[k]) <= 180.0) || !(std::fabs(p.y[k]) <= 90.0)) {
            const bool bad_lat = !(std::fabs(p.y[k]) <= 90.0);
            throw InputError(p.source, 0, 0,
                             "point " + std::to_string(k + 1) + ": " + (bad_lat ? p.y_name : p.x_name) + " " +
                                 formatSignificant(bad_lat ? p.y[k] : p.x[k]) + " is not a " +
                                 (bad_lat ? "latitude (-90 to 90 degrees)" : "longitude (-180 to 180 degrees)") +
                                 (crs.empty() ? "; give --crs for columns in another coordinate system, or --project none"
                                              : " after reading the columns in --crs " + crs + ": are they in that CRS?"));
        }
    // A pole is one point whatever longitude it is given: the same one for all.
    for (size_t k = 0; k < p.size(); ++k)
        if (std::fabs(p.y[k]) == 90.0) p.x[k] = 0.0;
    const std::vector<double> lon = p.x, lat = p.y;
    if (projection.kind == Projection::Equirect) {
        double sum = 0;
        for (double v : p.y) sum += v;
        const double lat0 = sum / double(p.size());
        const double k = std::cos(lat0 * kDeg);
        for (double& v : p.x) v *= k;
        const double d = areaDistortion(lon, lat, [k](std::vector<double>& x, std::vector<double>&) {
            for (double& v : x) v *= k;
        });
        if (metres_per_unit) *metres_per_unit = kMetresPerDegreeOfLatitude;
        char buf[200];
        std::snprintf(buf, sizeof buf, "projected %s/%s equirectangular about latitude %.2f (longitude x %.3f); ",
                      p.x_name.c_str(), p.y_name.c_str(), lat0, k);
        return how + buf + distortionText(d);
    }
    std::string definition = projection.definition, name;
    if (projection.kind != Projection::Definition) {
        // Centred on the points' spherical mean (a cluster across the
        // antimeridian stays one cluster, points at a pole one point); points
        // farther than a quarter of the globe from it (more than a
        // hemisphere) keep a world map, cut where their longitudes leave the
        // widest gap.
        const SphereExtent e = sphereExtent(p.x, p.y);
        const double lon0 = e.lon0, lat0 = e.lat0;
        char buf[160];
        if (e.max_angle_deg > 90) {
            std::snprintf(buf, sizeof buf, "+proj=eqearth +lon_0=%.6f +datum=WGS84 +units=km +no_defs", e.lon_middle);
            name = "Equal Earth centred on " + formatFixed(std::fabs(e.lon_middle), 2) + (e.lon_middle < 0 ? " W" : " E") +
                   " (the points span more than a hemisphere: a world map, equal-area, its scale and shapes true "
                   "only near the equator and the central meridian)";
        } else {
            std::snprintf(buf, sizeof buf, "+proj=laea +lat_0=%.6f +lon_0=%.6f +datum=WGS84 +units=km +no_defs", lat0, lon0);
            name = "Lambert azimuthal equal-area centred at " + formatFixed(std::fabs(lat0), 2) + (lat0 < 0 ? " S, " : " N, ") +
                   formatFixed(std::fabs(lon0), 2) + (lon0 < 0 ? " W" : " E");
        }
        definition = buf;
    }
    const std::string target = transformCoordinates(kLonLat, definition, p.x, p.y);
    if (metres_per_unit && projection.kind != Projection::Definition) *metres_per_unit = 1000.0;  // +units=km
    if (name.empty()) name = target;
    const double d = areaDistortion(lon, lat, [&](std::vector<double>& x, std::vector<double>& y) {
        transformCoordinates(kLonLat, definition, x, y);
    });
    return how + "projected " + p.x_name + "/" + p.y_name + " with PROJ onto " + name +
           (projection.kind == Projection::Definition ? "" : " (x, y in km; north up at the centre)") + "; " +
           distortionText(d);
}

}  // namespace tsf
