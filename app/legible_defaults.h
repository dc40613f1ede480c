// Defaults that pass the legibility checks: when the model tsf gen made
// from its defaults fails a tactile check (a fingertip cannot reach a data
// cell's top, a pillar would break under a hand), gen tries what the user
// left to it and keeps the first setting that passes.
//
// What it may change: the height of the largest value (--height), the
// value -> height transfer (--transfer), and, for a field tsf already
// resampled or binned to fit, the number of hexagons across (--bins: larger
// cells, each the mean of more pixels, so narrow lows widen and single-pixel
// noise evens out). A raster that fits one pillar per value is never
// resampled for it (the data is kept as read; the --bins that would pass is
// named). An option the user gave is kept, and the setting that would pass
// is named instead (tried, not guessed).
// Never by flattening: a setting is refused when a neighbouring step of
// kFeltHeightStepMm or more would drop below it. Each candidate is built,
// meshed and checked by the verifier's own tactile checks at its own
// sampling (the two a setting can fix; a candidate whose pillars are too
// slender fails before it is meshed), so what gen says passes is what tsf
// verify --tactile says; the first setting is taken as gen's own
// self-check found it.
// When nothing passes, the first model is kept, and the lines say which
// check fails where and why (docs/tactile.md).
#pragma once

#include <functional>
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
    bool cell = false;  ///< --cell, --bins or --bin
};

/// The field read again at `bins` hexagons across (tsf gen --bins); none
/// when the input cannot be (too few pixels, a bad option).
using FieldAtBins = std::function<std::optional<HexField>(int bins)>;

struct LegibleDefaults {
    std::optional<SceneParams> params;  ///< the parameters to build the model with; none: keep the first
    int bins = 0;                       ///< with params: read the field again at this many hexagons across (0: as it is)
    std::vector<std::string> lines;     ///< for the summary: what changed and why, what would pass, or why nothing does
    std::string key_note;               ///< with params: what changed, in a reader's words, for the model's key
    nlohmann::json json;                ///< the same for --json
};

/// The tactile checks `report` (gen's self-check of `first`) failed that a
/// setting can fix: tactile_finger_reach and tactile_slender_pillars. Empty
/// when none did.
std::vector<std::string> failedLegibility(const VerifyReport& report);

/// Searches the settings for a model of `field` that passes every check
/// `first_report` (gen's self-check of `first`, built from first.params)
/// failed that a setting can fix; the first setting is taken as that report
/// found it, not checked again. `field_at` reads the input at other --bins
/// (empty: the cell is not tried).
LegibleDefaults legibleDefaults(const HexField& field, const Scene& first, const VerifyReport& first_report,
                                const LegibilityGiven& given, const VerifyOptions& verify_options,
                                const FieldAtBins& field_at = {});

}  // namespace tsf::cli
