// The options that turn an input file into a Scene, shared by the commands
// that need a Scene: `tsf gen`, `tsf info` and `tsf verify --against`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "gen/readers/load_field.h"
#include "gen/model/scene.h"

namespace tsf::cli {

struct GenOptions : FieldLoadOptions {
    // input interpretation: FieldLoadOptions (gen/readers/load_field.h)
    // model
    SceneParams scene;
    std::string cell_arg, width_arg, depth_arg;  ///< raw, for validation messages
};

/// Adds the field and model options (input, size, heights, transfer, culling,
/// bottom, snap) to a command. `with_input` adds the positional input file.
void addGenOptions(CLI::App* cmd, GenOptions& opts, bool with_input = true);

}  // namespace tsf::cli
