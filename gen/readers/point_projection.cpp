#include "gen/readers/point_projection.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "gen/util/error.h"

namespace tsf {
namespace {

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

}  // namespace

Projection parseProjection(const std::string& name) {
    if (name == "auto") return Projection::Auto;
    if (name == "none") return Projection::None;
    if (name == "equirect") return Projection::Equirect;
    throw InputError("--project: expected auto, none or equirect, got '" + name + "'");
}

bool looksLikeLonLat(const PointTable& p) {
    return nameIs(p.x_name, {"lon", "lng", "long", "longitude", "lon_deg", "longitude_deg", "x_lon"}) &&
           nameIs(p.y_name, {"lat", "latitude", "lat_deg", "latitude_deg", "y_lat"}) && inRange(p);
}

std::string projectPoints(PointTable& p, Projection projection) {
    if (projection == Projection::None || p.size() == 0) return "";
    if (projection == Projection::Auto && !looksLikeLonLat(p)) return "";
    if (!inRange(p))
        throw InputError(p.source, 0, 0,
                         "--project equirect: x must be a longitude in [-180, 180] and y a latitude in [-90, 90] (degrees)");
    double sum = 0;
    for (double lat : p.y) sum += lat;
    const double lat0 = sum / double(p.size());
    const double k = std::cos(lat0 * M_PI / 180.0);
    for (double& lon : p.x) lon *= k;
    char buf[160];
    std::snprintf(buf, sizeof buf, "projected %s/%s equirectangular about latitude %.2f (longitude x %.3f)",
                  p.x_name.c_str(), p.y_name.c_str(), lat0, k);
    return buf;
}

}  // namespace tsf
