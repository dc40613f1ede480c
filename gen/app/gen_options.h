// The options that turn an input file into a Scene, shared by the commands
// that need a Scene: `tsf gen`, `tsf info` and `tsf verify --against`.
#pragma once

#include <string>

#include <CLI/CLI.hpp>

#include "gen/hex_field.h"
#include "gen/scene.h"

namespace tsf::cli {

struct GenOptions {
    std::string input;          ///< field file
    // input interpretation
    std::string points;         ///< "x=COL,y=COL[,w=COL]": read the CSV as points and bin them
    std::string aggregate = "count";  ///< count | sum | mean (points)
    double bin_size = 0.0;      ///< hex pitch in data units (points); 0 = from --bins
    int bins = 0;               ///< target number of hex columns (points and rasters); 0 = default
    std::string sample = "mean";  ///< raster -> hexes: mean | nearest | bilinear
    std::string delimiter;      ///< CSV delimiter; empty = detect
    // model
    SceneParams scene;
    std::string cell_arg, width_arg, depth_arg;  ///< raw, for validation messages
};

/// Adds the field and model options (input, size, heights, transfer, culling,
/// bottom, snap) to a command. `with_input` adds the positional input file.
void addGenOptions(CLI::App* cmd, GenOptions& opts, bool with_input = true);

/// Reads the input named in opts and builds its hex field (rasters are
/// resampled, points are binned). Throws InputError.
HexField loadField(const GenOptions& opts);

/// loadField + buildScene.
Scene loadScene(const GenOptions& opts);

}  // namespace tsf::cli
