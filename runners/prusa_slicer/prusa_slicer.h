// PrusaSlicer's command line, run headless: what it makes of a model
// (--info) and the G-code it slices from it (--export-gcode).
//
// Debian 12 ships PrusaSlicer 2.5 as the package `prusa-slicer`; it needs no
// display for these two uses. Nothing of the user's PrusaSlicer set-up is
// read: the slicer runs with its built-in profile and a data folder of its
// own (--datadir, a fresh temporary folder), changed only by the settings
// below, so two machines give the same figures.
//
// Failures of the slicer itself (missing, crashed, timed out, refused the
// file, wrote G-code without the expected comments) throw SlicerError with
// the slicer's own message; the caller maps it to "an external tool failed".
#pragma once

#include <stdexcept>
#include <string>
#include <vector>

#include "runners/prusa_slicer/gcode_summary.h"

namespace tsf {

/// PrusaSlicer failed, is missing, or said something we cannot read.
class SlicerError : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The PrusaSlicer settings a check varies; the rest is the built-in profile.
struct SlicerSettings {
    std::string executable = "prusa-slicer";  ///< name in PATH or a path
    double layer_mm = 0.2;                    ///< layer height; the first layer is as high (so layers = height / layer)
    double nozzle_mm = 0.4;                   ///< nozzle diameter; extrusion widths follow it
    double filament_density_g_cm3 = 1.24;     ///< PLA; gives the filament mass
    double bed_width_mm = 200, bed_depth_mm = 200;  ///< bed size; the model is centred on it (built-in bed: 200 x 200)
    double timeout_s = 1800;                  ///< per slicer run
};

/// What `prusa-slicer --info` says of a model.
struct SlicerModelInfo {
    long objects = 0;           ///< objects PrusaSlicer loaded (one block each; a multi-part 3MF is one)
    bool manifold = false;      ///< "manifold = yes" for every object: slices without repair
    long open_edges = 0;        ///< "open_edges" (only written for a non-manifold model)
    long facets = 0;            ///< "number_of_facets"
    long parts = 0;             ///< "number_of_parts": connected pieces (of the last object)
    double volume_mm3 = 0;      ///< "volume"
    double size_mm[3] = {0, 0, 0};  ///< "size_x/y/z"
};

/// "PrusaSlicer-2.5.0+..." (the first line of --help); throws SlicerError when it does not run.
std::string prusaSlicerVersion(const SlicerSettings& settings);

/// `prusa-slicer --info model`.
SlicerModelInfo prusaSlicerInfo(const std::string& model_path, const SlicerSettings& settings);

/// Slices model_path to G-code (a temporary file, removed afterwards) and
/// summarises it; with_support turns on automatic support material.
GcodeSummary prusaSlice(const std::string& model_path, const SlicerSettings& settings, bool with_support);

/// The options given to the slicer for a slice (for reports and tests).
std::vector<std::string> prusaSliceArguments(const SlicerSettings& settings, bool with_support);

}  // namespace tsf
