// The orientation tab in the scene sidecar (gen/model/scene_json.h), as
// placed (version 6), read as recorded and checked against the cells
// (checkTab).
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"

namespace tsf {

/// {outline [[x, y, lattice id (-1: the tab's own)], ...] mm, counter-
/// clockwise, joined [0|1 per edge], touched [[kept index, edge 0..5]],
/// bottom_units, top_units, box_mm [west, east, south, north], notch null |
/// {depth_mm, width_mm, opening_deg}, triangle null | {corners_mm [[x, y] x
/// 3], raise_units, underside}}; null without a tab.
nlohmann::json tabRecord(const Scene& scene);

/// Reads a record tabRecord wrote (FeatureRecord::read,
/// gen/model/feature_records.h). Throws InputError naming the member's path.
void readTabRecord(const nlohmann::json& record, const std::string& path, int version, Scene& scene);

/// Its facts for the summary's --json (FeatureFacts,
/// gen/model/feature_records.h): its box, size, z span, area, the cells it touches, its notch and triangle; null without it.
nlohmann::json tabFactsJson(const Scene& scene);

/// Its lines in the summary ("  label     text\n" each): its size and place, the notch and the triangle and how to turn the model; ""
/// without it.
std::string tabFactsLines(const Scene& scene);

}  // namespace tsf
