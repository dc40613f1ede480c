// --preview MODEL.png: the model as the run made it, drawn by tsf: the
// pieces side by side (--halves), the tiles drawn apart (--tile), or the
// one model (with --mirror its underside beside its top).
#pragma once

#include <optional>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"
#include "pipeline/verified_tiles.h"

namespace tsf::cli {

/// Draws the preview to o.preview and lists it in the summary.
void writeRunPreview(const GenCommandOptions& o, const HexField& field, const Scene& scene, const VerifiedModel& made,
                     const std::optional<VerifiedTiles>& tiles, GenSummary& summary);

}  // namespace tsf::cli
