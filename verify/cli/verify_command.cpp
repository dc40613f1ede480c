// Placeholder until the 'verify' command lands; registers nothing.
#include "gen/cli/commands.h"

namespace tsf::cli {
void addVerifyCommand(CLI::App&) {}
}  // namespace tsf::cli
