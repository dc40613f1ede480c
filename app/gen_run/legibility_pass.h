// Defaults that pass: a model made from tsf's defaults that fails a
// legibility check is made again with what the user left to tsf
// (app/legible_defaults.h); the summary says what changed and why, and
// the key where the model may still not read well.
#pragma once

#include <string>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "app/stage_timer.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"

namespace tsf::cli {

/// For the model's key.
struct LegibilityOutcome {
    std::string key;     ///< "Where the model may not read well: ..."; "" when it reads well
    std::string change;  ///< what the search changed, for the key's last section; "" when nothing
};

/// When made's report fails a legibility check: searches the defaults
/// that pass and, when some do, reads the field again (other bins),
/// builds the Scene and makes the model again with them (o.gen, field,
/// scene and made replaced). Without a report (--no-verify) nothing.
LegibilityOutcome passLegibility(GenCommandOptions& o, HexField& field, Scene& scene, VerifiedModel& made,
                                 const ModelRequest& rq, StageTimer& timer, GenSummary& summary);

}  // namespace tsf::cli
