// Defaults that pass the legibility checks: when the model tsf gen made
// from its defaults fails a tactile check (a fingertip cannot reach a data
// cell's top, a pillar would break under a hand), gen tries what the user
// left to it and keeps the first setting that passes.
//
// What it may change: the height of the largest value (--height) and the
// value -> height transfer (--transfer); an option the user gave is kept,
// and the setting that would pass is named instead (tried, not guessed).
// Never by flattening: a setting is refused when a neighbouring step of
// kFeltHeightStepMm or more would drop below it. Each candidate is built,
// meshed and checked by the verifier's own tactile checks at its own
// sampling, so what gen says passes is what tsf verify --tactile says.
// When nothing passes, the first model is kept, and the lines say which
// check fails where and why (docs/tactile.md).
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "verify/report.h"
#include "verify/verify_model.h"

namespace tsf::cli {

/// The options the user gave (kept as given).
struct LegibilityGiven {
    bool height = false;
    bool transfer = false;
};

struct LegibleDefaults {
    std::optional<SceneParams> params;  ///< the parameters to build the model with; none: keep the first
    std::vector<std::string> lines;     ///< for the summary: what changed and why, what would pass, or why nothing does
    nlohmann::json json;                ///< the same for --json
};

/// The tactile checks `report` (gen's self-check of `first`) failed that a
/// setting can fix: tactile_finger_reach and tactile_slender_pillars. Empty
/// when none did.
std::vector<std::string> failedLegibility(const VerifyReport& report);

/// Searches the settings for a model of `field` that passes every check in
/// `failed`, starting from `first` (built from first.params).
LegibleDefaults legibleDefaults(const HexField& field, const Scene& first, const std::vector<std::string>& failed,
                                const LegibilityGiven& given, const VerifyOptions& verify_options);

}  // namespace tsf::cli
