// -o MODEL.ext written as the run made it: the halves and the pins, the
// tiles, one 3MF object in parts (--parts), or one solid.
#pragma once

#include <optional>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "gen/mesh_io/mesh_writer.h"
#include "pipeline/verified_model.h"
#include "pipeline/verified_tiles.h"

namespace tsf::cli {

/// How o.output is written: the STL's ASCII or binary form, its title.
MeshWriteOptions modelWriteOptions(const GenCommandOptions& o);

/// Writes the model's file or files to o.output and lists them in the
/// summary (a file made.written_ahead is only listed). Nothing when no -o
/// was given.
void writeModelFiles(const GenCommandOptions& o, const VerifiedModel& made, const std::optional<VerifiedTiles>& tiles,
                     GenSummary& summary);

}  // namespace tsf::cli
