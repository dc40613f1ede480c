// The verifier's verdict on the run's model in the summary: the checks
// passed, every check not passed, the read-back, the parts and the halves;
// and the one verdict that stops the run: walls thinner than the nozzle.
#pragma once

#include "app/gen_summary.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"

namespace tsf::cli {

/// Fills summary.mesh, verify, verify_text, checks_text, supports_text
/// and the halves'. Unless keep_unprintable, throws InputError (exit 2,
/// nothing written) when the model has walls thinner than the nozzle: the
/// options made it (cells or a model too small for the nozzle).
void summarizeVerdict(const VerifiedModel& made, const ModelRequest& rq, const Scene& scene, bool keep_unprintable,
                      GenSummary& summary);

}  // namespace tsf::cli
