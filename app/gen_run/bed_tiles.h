// --tile: the model cut into tiles that each fit the bed less its margins,
// each verified (pipeline/verified_tiles.h), or none when it fits in one piece.
#pragma once

#include <optional>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "app/stage_timer.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"
#include "pipeline/verified_tiles.h"

namespace tsf::cli {

/// With --tile: the tiles, summarized; none (and a note) when the model
/// fits the bed as it is, or without --tile. Throws InputError when a tile
/// would be written over the input.
std::optional<VerifiedTiles> tilesForBed(const GenCommandOptions& o, const HexField& field, const Scene& scene,
                                         const ModelRequest& rq, StageTimer& timer, GenSummary& summary);

}  // namespace tsf::cli
