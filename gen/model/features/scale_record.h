// The tactile scale in the scene sidecar (gen/model/scene_json.h), as placed
// (written since version 4), read as recorded.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/feature.h"
#include "gen/model/scene.h"

namespace tsf {

/// {step, step_given, x0_i, y0_j, y1_j, x_mm [west, steps' west, east],
/// y_mm [south, north], foot_top_units, steps [[value, top_units,
/// y_south_mm, y_north_mm], ...], contacts [kept index], fillers [kept
/// index]}; null without a scale.
nlohmann::json scaleRecord(const Scene& scene);

/// Reads a record scaleRecord wrote (FeatureRecord::read,
/// gen/model/feature_records.h). Throws InputError naming the member's path.
void readScaleRecord(const nlohmann::json& record, const std::string& path, int version, Scene& scene);

/// Its facts for the summary's --json (FeatureFacts,
/// gen/model/feature_records.h): its step, floor, steps, footprint and treads; null without it.
nlohmann::json scaleFactsJson(const Scene& scene);

/// Its lines in the summary ("  label     text\n" each): its steps, treads and heights; ""
/// without it.
std::string scaleFactsLines(const Scene& scene);

/// Its paragraph in the model's key (gen/key/model_key.h): its steps, lowest
/// first, and how to read a value by them; "" without it.
/// What the scale asks a hand to find: each step rising at least
/// kScaleMinRiserMm above the one before it (the first above the floor),
/// on a tread at least kScaleTreadMm long, once printed.
std::vector<TactileClaim> scaleTactileClaims(const Scene& scene);

std::string scaleKeyParagraph(const Scene& scene, const KeyNumbers& numbers);

}  // namespace tsf
