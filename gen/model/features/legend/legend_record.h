// The braille legend in the scene sidecar (gen/model/scene_json.h), as placed:
// its request (for reports), the standard its dots were laid out at, the
// text and braille cells, every dot and the plate. Read back as is:
// verifying a model needs no braille table and no placement.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"

namespace tsf {

/// {title, units, table, standard {name, dot_base_mm, dot_height_mm,
/// dot_pitch_mm, cell_pitch_mm, line_pitch_mm}, text, cells, dots, size_mm,
/// origin_mm, reach_row, plate_mm {south, north, east}, plate_top_units,
/// plate_bottom_units}; null without a legend.
nlohmann::json legendRecord(const Scene& scene);

/// Reads a record legendRecord wrote (FeatureRecord::read,
/// gen/model/feature_records.h). Throws InputError naming the member's path.
void readLegendRecord(const nlohmann::json& record, const std::string& path, int version, Scene& scene);

/// Its facts for the summary's --json (FeatureFacts,
/// gen/model/feature_records.h): its lines in text and braille, the table, the plate and the standard; null without it.
nlohmann::json legendFactsJson(const Scene& scene);

/// Its lines in the summary ("  label     text\n" each): the plate, the dots and every line in braille; ""
/// without it.
std::string legendFactsLines(const Scene& scene);

}  // namespace tsf
