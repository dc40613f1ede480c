// What `tsf gen` asks of the pipeline (pipeline/verified_model.h): verify
// or not, parts, float32, the printer's nozzle and layer for the checks,
// and what to do with the mesh before it is verified (the bed fit).
#pragma once

#include "app/gen_run/gen_command_options.h"
#include "app/stage_timer.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"

namespace tsf::cli {

/// The request for the run's model. Its on_mesh reads o and scene when
/// called: both must outlive it (they may change before: a Scene built
/// again by the legibility pass is fitted as the first was). When the run
/// writes one solid and verifies it, its write_ahead writes o.output while
/// the model is verified: an OutputSet must then be alive, to discard the
/// file if a check fails.
ModelRequest modelRequest(const GenCommandOptions& o, const Scene& scene);

/// A model (or piece) that fails its own checks is a bug in tsf: never hand
/// it to a printer. Prints the report and ends with kExitCheckFailed.
[[noreturn]] void refuseUnverified(const ModelVerificationFailed& e, StageTimer& timer);

/// makeVerifiedModel, each stage timed, or refuseUnverified.
VerifiedModel makeModelOrRefuse(const Scene& scene, const ModelRequest& rq, StageTimer& timer);

}  // namespace tsf::cli
