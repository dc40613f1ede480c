// The options that turn an input file into a Scene, shared by the commands
// that need a Scene: `tsf gen`, `tsf info` and `tsf verify --against`.
#pragma once

#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "gen/readers/load_field.h"
#include "gen/model/scene.h"

namespace tsf::cli {

struct GenOptions : FieldLoadOptions {
    // input interpretation: FieldLoadOptions (gen/readers/load_field.h)
    // model
    SceneParams scene;
    std::string cell_arg, width_arg, depth_arg;  ///< raw, for validation messages
    /// --band given as a series (1-12, 1,4,7): the bands in order; empty for
    /// one band (FieldLoadOptions::band). Only tsf gen makes a series.
    std::vector<int> band_series;
};

/// "3" -> {3}; "1-12" -> 1..12; "1,4,7-9" -> {1, 4, 7, 8, 9}. Throws
/// InputError for anything else, a band below 1 or more than 10000 bands.
std::vector<int> parseBandSpec(const std::string& spec);

/// Commands other than tsf gen read one band: a series is bad input.
void refuseBandSeries(const GenOptions& o, const char* command);

/// Adds the field and model options (input, size, heights, transfer, culling,
/// bottom, snap) to a command. `with_input` adds the positional input file.
void addGenOptions(CLI::App* cmd, GenOptions& opts, bool with_input = true);

}  // namespace tsf::cli
