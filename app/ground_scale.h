// The ground a georeferenced raster covers and the model's scale on it, for
// the summary and the key: "1800 m x 1200 m; scale 1 : 15 000".
#pragma once

#include <optional>
#include <string>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf::cli {

struct GroundScale {
    double width_m = 0, depth_m = 0;        ///< the ground the raster covers
    double east_west = 0, north_south = 0;  ///< N of 1 : N (the same with true aspect)
    double hexagon_area_km2 = 0;            ///< points: the ground one hexagon covers (0: not said)
};

/// None when the file does not say how long its units are (FieldInput::metres_per_unit).
std::optional<GroundScale> groundScale(const Scene& scene, const HexField& field);

/// N of a scale 1 : N as a map gives it: three significant digits, whole,
/// thousands apart ("15 000", "1 250 000").
std::string scaleNumber(double n);

/// The summary's "  ground    ..." line.
std::string groundLine(const GroundScale& g, const FieldInput& in);

/// The key's sentence: "The model shows 1800 m x 1200 m of ground at a scale
/// of 1 : 15 000: 1 mm on it is 15 m on the ground." For points, and the
/// area of ground one hexagon covers.
std::string groundSentence(const GroundScale& g);

}  // namespace tsf::cli
