// The options of one `tsf gen` run, and what follows from them alone: the
// OpenSCAD options and the names of the files written beside the model.
#pragma once

#include <string>
#include <utility>

#include "app/gen_options.h"
#include "app/legible_defaults.h"
#include "app/printer_fit.h"
#include "gen/scad/scad_emitter.h"

namespace tsf::cli {

struct GenCommandOptions {
    GenOptions gen;
    std::string output;
    std::string scad;
    bool ascii = false;
    bool no_verify = false;
    bool json = false;
    bool progress = false;
    bool no_sidecar = false;
    bool no_key = false;  ///< --no-key: no MODEL.key.txt and MODEL.key.brf
    std::string scad_strategy = "polyhedron";
    bool scad_library_beside = false;
    std::string command_line;
    std::string preview;
    bool verify_full = false;
    bool keep_unprintable = false;  ///< write a model whose walls are thinner than the nozzle
    bool force = false;
    PrinterSpec printer;  ///< --bed, --nozzle, --layer (printer_fit.h)
    bool parts = false;        ///< --parts: the 3MF as one object with a part per feature
    std::string parts_layout = "portable";  ///< --parts-layout: portable | prusaslicer
    bool print_check = false;  ///< --print-check: slice the written model with PrusaSlicer
    GivenOptions given;   ///< model options the user gave himself
    LegibilityGiven legibility_given;  ///< what defaults that pass may not change (app/legible_defaults.h)
    std::string about;    ///< --about: what the model shows, in the maker's words (the key's first paragraph)
    int series_index = 0, series_count = 0;  ///< --band A-B: this model's place in the series (1-based; 0: none)
};

/// The scene sidecar's path: MODEL.stl.scene.json (or beside the .scad
/// when no model file is written).
std::string sidecarPath(const GenCommandOptions& o);

/// The model's key beside it: MODEL.key.txt and MODEL.key.brf for MODEL.stl
/// (or the .scad when no model file is written).
std::pair<std::string, std::string> keyPaths(const GenCommandOptions& o);

/// The OpenSCAD emitter's options: the strategy, the library inlined or
/// beside, and the input's file name and command line for the header.
ScadOptions scadOptions(const GenCommandOptions& o);

}  // namespace tsf::cli
