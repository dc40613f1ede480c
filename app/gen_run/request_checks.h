// What `tsf gen` refuses before it reads anything: options that contradict
// each other, an output that is the input or another output, and a file tsf
// names itself that tsf did not write (unless --force).
#pragma once

#include "app/gen_run/gen_command_options.h"

namespace tsf::cli {

/// Throws InputError naming the option or file and what to give instead.
void checkGenRequest(const GenCommandOptions& o, const ScadOptions& so);

}  // namespace tsf::cli
