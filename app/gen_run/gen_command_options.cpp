#include "app/gen_run/gen_command_options.h"

#include <filesystem>

#include "app/key_stamp.h"

namespace tsf::cli {

std::string sidecarPath(const GenCommandOptions& o) { return (o.output.empty() ? o.scad : o.output) + ".scene.json"; }

std::pair<std::string, std::string> keyPaths(const GenCommandOptions& o) {
    return keyPathsBeside(o.output.empty() ? o.scad : o.output);
}

ScadOptions scadOptions(const GenCommandOptions& o) {
    ScadOptions so;
    parseScadStrategy(o.scad_strategy, so.strategy);
    so.inline_library = !o.scad_library_beside;
    // The file name only: a shared .scad must not carry the folders it was made in.
    so.source = std::filesystem::path(o.gen.input).filename().string();
    so.command = o.command_line;
    return so;
}

}  // namespace tsf::cli
