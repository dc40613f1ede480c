#include "gen/readers/point_projection.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <vector>

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

std::string projectPoints(PointTable& p, const ProjectionChoice& projection, const std::string& crs) {
    if (projection.kind == Projection::None || p.size() == 0) return "";
    std::string how;
    if (!crs.empty()) {
        // Columns in a CRS of their own (e.g. Web Mercator exports): to lon/lat first.
        transformCoordinates(crs, kLonLat, p.x, p.y);
        how = "x, y read in " + crs + ", ";
    } else if (projection.kind == Projection::Auto && !looksLikeLonLat(p)) {
        return "";
    }
    if (!inRange(p))
        throw InputError(p.source, 0, 0,
                         "--project: x must be a longitude in [-180, 180] and y a latitude in [-90, 90] (degrees); give "
                         "--crs for columns in another coordinate system, or --project none");
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
        char buf[200];
        std::snprintf(buf, sizeof buf, "projected %s/%s equirectangular about latitude %.2f (longitude x %.3f); ",
                      p.x_name.c_str(), p.y_name.c_str(), lat0, k);
        return how + buf + distortionText(d);
    }
    std::string definition = projection.definition, name;
    if (projection.kind != Projection::Definition) {
        const auto [lon_lo, lon_hi] = std::minmax_element(p.x.begin(), p.x.end());
        const auto [lat_lo, lat_hi] = std::minmax_element(p.y.begin(), p.y.end());
        const double lon0 = (*lon_lo + *lon_hi) / 2, lat0 = (*lat_lo + *lat_hi) / 2;
        char buf[160];
        if (*lon_hi - *lon_lo > 180 || *lat_hi - *lat_lo > 100) {
            std::snprintf(buf, sizeof buf, "+proj=eqearth +lon_0=%.6f +datum=WGS84 +units=km +no_defs", lon0);
            name = "Equal Earth (the world)";
        } else {
            std::snprintf(buf, sizeof buf, "+proj=laea +lat_0=%.6f +lon_0=%.6f +datum=WGS84 +units=km +no_defs", lat0, lon0);
            name = "Lambert azimuthal equal-area centred at " + formatFixed(std::fabs(lat0), 2) + (lat0 < 0 ? " S, " : " N, ") +
                   formatFixed(std::fabs(lon0), 2) + (lon0 < 0 ? " W" : " E");
        }
        definition = buf;
    }
    const std::string target = transformCoordinates(kLonLat, definition, p.x, p.y);
    if (name.empty()) name = target;
    const double d = areaDistortion(lon, lat, [&](std::vector<double>& x, std::vector<double>& y) {
        transformCoordinates(kLonLat, definition, x, y);
    });
    return how + "projected " + p.x_name + "/" + p.y_name + " with PROJ onto " + name +
           (projection.kind == Projection::Definition ? "" : " (x, y in km; north up at the centre)") + "; " +
           distortionText(d);
}

}  // namespace tsf
