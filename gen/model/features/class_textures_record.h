// A class map's textures in the scene sidecar (gen/model/scene_json.h), as
// decided (written since version 7), and in the summary.
#pragma once

#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"

namespace tsf {

/// {height_units, relief_units, textures_used, classes [[code, texture,
/// shared, cells], ...]}; null without textures.
nlohmann::json classTexturesRecord(const Scene& scene);

/// Reads a record classTexturesRecord wrote (FeatureRecord::read,
/// gen/model/feature_records.h). Throws InputError naming the member's path.
void readClassTexturesRecord(const nlohmann::json& record, const std::string& path, int version, Scene& scene);

/// {height_mm, relief_mm, textures_used, shared [codes]}; null without textures.
nlohmann::json classTexturesFactsJson(const Scene& scene);

/// The "  textures  ..." line; "" without textures.
std::string classTexturesFactsLines(const Scene& scene);

}  // namespace tsf
