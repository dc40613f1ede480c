// A cut model's halves in the summary: where the cut is, the pin holes and
// the pins (FeatureFacts, gen/model/feature_records.h).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"

namespace tsf {

/// {cut_z_mm, slab_mm, thickness_grown_mm, hole_centres_mm,
/// hole_diameter_mm, hole_depth_mm, hole_tip_mm, pin_diameter_mm,
/// pin_length_mm, clearance_per_side_mm}; null without halves.
nlohmann::json halvesFactsJson(const Scene& scene);

/// The "  halves    ..." lines; "" without halves.
std::string halvesFactsLines(const Scene& scene);

}  // namespace tsf
