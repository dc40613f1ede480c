// The end of a `tsf gen` run: the written model sliced by PrusaSlicer when
// asked (--print-check), and the summary printed for a person or, with
// --json, for a program.
#pragma once

#include <optional>

#include <nlohmann/json.hpp>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "runners/prusa_slicer/print_check.h"

namespace tsf::cli {

/// The written model sliced with the printer options given (else
/// PrusaSlicer's defaults). A slicer that fails ends the run with
/// kExitToolFailed: the model is written, its check is not.
PrintCheckReport printCheck(const GenCommandOptions& o);

/// Prints the summary (and the print check's report) on stdout, or with
/// --json hands the JSON to json_out when given (a series gathers them).
void reportRun(const GenCommandOptions& o, const GenSummary& summary, const std::optional<PrintCheckReport>& printed,
               nlohmann::json* json_out);

}  // namespace tsf::cli
