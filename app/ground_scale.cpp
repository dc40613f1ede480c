// The ground and the scale. See ground_scale.h.
#include "app/ground_scale.h"

#include <cmath>
#include <cstdint>

#include "gen/util/number_format.h"

namespace tsf::cli {

namespace {

std::string groundLength(double m) {
    return m >= 10000 ? formatSignificant(m / 1000, 4) + " km" : formatSignificant(m, 4) + " m";
}

// An area for a reader: square kilometres, or hectares below one.
std::string areaText(double km2) {
    if (km2 >= 1) return "about " + scaleNumber(km2) + " square kilometres";
    return "about " + formatSignificant(km2 * 100, 3) + " hectares";
}

}  // namespace

std::optional<GroundScale> groundScale(const Scene& scene, const HexField& field) {
    const FieldInput& in = field.input;
    if (!(in.metres_per_unit > 0) || !(scene.pitch_mm > 0)) return std::nullopt;
    GroundScale g;
    g.width_m = in.ground_width_m;
    g.depth_m = in.ground_depth_m;
    g.hexagon_area_km2 = in.hexagon_area_km2;
    const double across_m = field.pitch_data * in.metres_per_unit;  // one pitch on the ground
    g.east_west = across_m * 1000.0 / scene.pitch_mm;
    // Rows: a raster's own a pixel apart, a lattice's laid over the ground
    // sqrt(3)/2 of a pitch; on the model 3 lattice steps, stretched or not.
    const double row_ground_m = field.rows_a_pitch_apart ? across_m * field.row_aspect : across_m * kSqrt3 / 2;
    g.north_south = row_ground_m * 1000.0 / latticeY({0, 3}, scene.pitch_mm, scene.y_scale);
    return g;
}

std::string scaleNumber(double n) {
    if (!(n >= 1) || !std::isfinite(n)) return formatSignificant(n, 3);
    const double unit = std::pow(10.0, std::max(0.0, std::floor(std::log10(n)) - 2));
    std::string digits = std::to_string(int64_t(std::llround(n / unit) * int64_t(unit)));
    for (int at = int(digits.size()) - 3; at > 0; at -= 3) digits.insert(size_t(at), " ");
    return digits;
}

std::string groundLine(const GroundScale& g, const FieldInput& in) {
    std::string o = "  ground    " + groundLength(g.width_m) + " x " + groundLength(g.depth_m) + "; scale 1 : " +
                    scaleNumber(g.east_west) + " (1 mm on the model is " + groundLength(g.east_west / 1000) +
                    " on the ground)";
    if (std::abs(g.north_south / g.east_west - 1) > 1e-6) o += ", north-south 1 : " + scaleNumber(g.north_south);
    if (g.hexagon_area_km2 > 0) o += "; each hexagon " + areaText(g.hexagon_area_km2);
    if (in.longitude_scale > 0)
        o += "; longitude and latitude: a degree of longitude counted as cos(mean latitude) = " +
             formatSignificant(in.longitude_scale, 4) + " of a degree of latitude";
    return o + "\n";
}

std::string groundSentence(const GroundScale& g) {
    std::string o = "The model shows " + groundLength(g.width_m) + " by " + groundLength(g.depth_m) +
                    " of ground at a scale of 1 : " + scaleNumber(g.east_west) + ": 1 mm on it is " +
                    groundLength(g.east_west / 1000) + " on the ground";
    if (std::abs(g.north_south / g.east_west - 1) > 1e-6)
        o += " from west to east, and 1 : " + scaleNumber(g.north_south) + " from south to north";
    if (g.hexagon_area_km2 > 0) o += ". Each hexagon covers " + areaText(g.hexagon_area_km2) + " of ground";
    return o + ".";
}

}  // namespace tsf::cli
