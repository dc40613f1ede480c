// The model's key for a reader: what the model shows, its values and
// heights, how to find north, in words (MODEL.key.txt, for a screen
// reader) and in braille (MODEL.key.brf, for an embosser), each ending in
// the model's stamp (app/key_stamp.h).
#pragma once

#include <optional>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_run/legibility_pass.h"
#include "app/gen_summary.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "gen/util/file_stamp.h"
#include "pipeline/verified_tiles.h"

namespace tsf::cli {

/// Writes both keys to keyPaths(o) and lists them in the summary.
/// model_stamp: the one model file's (none for tiles, halves or no -o).
void writeKeyFiles(const GenCommandOptions& o, const HexField& field, const Scene& scene,
                   const std::optional<VerifiedTiles>& tiles, const LegibilityOutcome& legibility,
                   const std::optional<FileStamp>& model_stamp, GenSummary& summary);

}  // namespace tsf::cli
