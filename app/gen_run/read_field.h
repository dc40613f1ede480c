// The field of a `tsf gen` run, read with word of a long read on stderr,
// and the legend's units taken from the file when the user gave none.
#pragma once

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "gen/field/hex_field.h"

namespace tsf::cli {

/// Reads o.gen.input. Sets o.gen.scene.words.units to the file's units
/// when a legend has a title and no --units, with a line in the summary.
HexField readGenField(GenCommandOptions& o, GenSummary& summary);

}  // namespace tsf::cli
