// The ground a georeferenced raster covers and the model's scale on it, for
// the summary and the key: "1,800 m by 1,200 m; scale 1 to 15,000".
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

/// N of a scale "1 to N": three significant digits, whole, thousands
/// grouped by commas ("15,000", "1,250,000"). Commas, not spaces: braille
/// reads "1 250 000" as three numbers and so does a screen reader. "1 to N"
/// rather than "1 : N", as a scale is said aloud; in braille a colon
/// between numbers is a lower-cell sign a reader can take for a digit.
std::string scaleNumber(double n);

/// The summary's "  ground    ..." line.
std::string groundLine(const GroundScale& g, const FieldInput& in);

/// The key's sentence: "The model shows ground 1,800 metres from west to
/// east and 1,200 metres from south to north, at a scale of 1 to 15,000: 1
/// millimetre on the model is 15 metres on the ground." Numbers joined to
/// their units by no-break spaces (model_key.h). For points, also the
/// area of ground one hexagon covers.
std::string groundSentence(const GroundScale& g);

}  // namespace tsf::cli
