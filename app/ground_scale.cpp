// The ground and the scale. See ground_scale.h.
#include "app/ground_scale.h"

#include <cmath>
#include <algorithm>
#include <cstdint>
#include <utility>

#include "gen/util/number_format.h"

namespace tsf::cli {

namespace {

std::string groundLength(double m) {
    return m >= 10000 ? formatForReader(m / 1000, 4) + " km" : formatForReader(m, 4) + " m";
}

/// Two lengths in one unit (never "9946 m by 10.03 km"): kilometres when
/// the larger is 10 km or more. `sep` joins a number to its unit.
std::pair<std::string, std::string> groundLengths(double a_m, double b_m, bool words, const std::string& sep) {
    const bool km = std::max(a_m, b_m) >= 10000;
    const double f = km ? 0.001 : 1.0;
    auto one = [&](double m) {
        const double v = m * f;
        const std::string unit = words ? (km ? (v == 1 ? "kilometre" : "kilometres") : (v == 1 ? "metre" : "metres"))
                                       : (km ? "km" : "m");
        return formatForReader(v, 4) + sep + unit;
    };
    return {one(a_m), one(b_m)};
}

/// One length for the key: "15 metres", "1.2 kilometres".
std::string groundWords(double m, const std::string& sep) {
    const bool km = m >= 1000;
    const double v = km ? m / 1000 : m;
    return formatForReader(v, 4) + sep + (km ? (v == 1 ? "kilometre" : "kilometres") : (v == 1 ? "metre" : "metres"));
}

// An area for a reader: square kilometres, or hectares below one.
std::string areaText(double km2) {
    if (km2 >= 1) return "about " + scaleNumber(km2) + " square kilometres";
    return "about " + formatForReader(km2 * 100, 3) + " hectares";
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
    if (!(n >= 1) || !std::isfinite(n)) return formatForReader(n, 3);
    const double unit = std::pow(10.0, std::max(0.0, std::floor(std::log10(n)) - 2));
    return formatForReader(double(std::llround(n / unit)) * unit, 15);
}

std::string groundLine(const GroundScale& g, const FieldInput& in) {
    const auto [w, d] = groundLengths(g.width_m, g.depth_m, false, " ");
    std::string o = "  ground    " + w + " by " + d + "; scale 1 to " + scaleNumber(g.east_west) +
                    " (1 mm on the model is " + groundLength(g.east_west / 1000) + " on the ground)";
    if (std::abs(g.north_south / g.east_west - 1) > 1e-6) o += ", north-south 1 to " + scaleNumber(g.north_south);
    if (g.hexagon_area_km2 > 0) o += "; each hexagon " + areaText(g.hexagon_area_km2);
    if (in.longitude_scale > 0)
        o += "; longitude and latitude: a degree of longitude counted as cos(mean latitude) = " +
             formatSignificant(in.longitude_scale, 4) + " of a degree of latitude";
    return o + "\n";
}

std::string groundSentence(const GroundScale& g) {
    const std::string nb = "\u00A0";  // a number and its unit stay on one braille line
    const auto [w, d] = groundLengths(g.width_m, g.depth_m, true, nb);
    std::string o = "The model shows ground " + w + " from west to east and " + d +
                    " from south to north, at a scale of 1 to " + scaleNumber(g.east_west) + ": 1" + nb +
                    "millimetre on the model is " + groundWords(g.east_west / 1000, nb) + " on the ground";
    if (std::abs(g.north_south / g.east_west - 1) > 1e-6)
        o += " from west to east, and 1 to " + scaleNumber(g.north_south) + " from south to north";
    if (g.hexagon_area_km2 > 0) o += ". Each hexagon covers " + areaText(g.hexagon_area_km2) + " of ground";
    return o + ".";
}

}  // namespace tsf::cli
