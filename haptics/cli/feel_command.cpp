// Placeholder until the 'feel' command lands; registers nothing.
#include "gen/cli/commands.h"

namespace tsf::cli {
void addFeelCommand(CLI::App&) {}
}  // namespace tsf::cli
