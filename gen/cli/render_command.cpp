// Placeholder until the 'render' command lands; registers nothing.
#include "gen/cli/commands.h"

namespace tsf::cli {
void addRenderCommand(CLI::App&) {}
}  // namespace tsf::cli
