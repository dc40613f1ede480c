// runPrintCheck: does a model print as it is? PrusaSlicer (prusa_slicer.h)
// slices it headless and its G-code says how long, how much filament, how
// many layers, and whether it needs supports.
//
// Method:
//   1. `--info`: "manifold = yes" means it slices without repair (PrusaSlicer
//      repairs a non-manifold mesh silently when slicing; the report says so).
//   2. Slice without supports: layers, print time and filament of the model
//      itself.
//   3. Slice again with automatic supports (PrusaSlicer's default overhang
//      threshold): supports are needed exactly when that G-code extrudes any
//      ";TYPE:Support material"; the report gives the time and filament with
//      them and the difference.
// The first layer is as high as the others, so a model of height h mm has
// ceil(h / layer) layers. Before the slicer runs, the model is read
// (readMesh: a broken file is an InputError with its position) and its
// footprint is compared with the bed: a model larger than the bed is an
// InputError too (PrusaSlicer would abort).
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "runners/prusa_slicer/prusa_slicer.h"

namespace tsf {

struct PrintCheckReport {
    std::string model;            ///< the file checked
    std::string slicer_version;   ///< "PrusaSlicer-2.5.0+UNKNOWN"
    SlicerSettings settings;
    long triangles = 0;           ///< as read by tsf
    double size_mm[3] = {0, 0, 0};
    SlicerModelInfo info;         ///< step 1
    GcodeSummary plain;           ///< step 2: no supports
    GcodeSummary supported;       ///< step 3: automatic supports

    bool repairNeeded() const { return !info.manifold; }
    bool supportsNeeded() const { return supported.has_support; }
};

/// Runs the three steps above on the STL or 3MF at model_path.
/// Throws InputError (bad file, larger than the bed) or SlicerError.
PrintCheckReport runPrintCheck(const std::string& model_path, const SlicerSettings& settings);

/// The report for people: one figure per line, units stated.
std::string formatPrintCheck(const PrintCheckReport& report);

/// Every figure for programs (mm, cm3, g, s).
nlohmann::json toJson(const PrintCheckReport& report);

/// The pieces of one model printed one after another (tiles, halves and
/// pins): time and filament summed, each without supports, and with them
/// where a piece needs them.
struct PrintCheckTotal {
    size_t pieces = 0;
    double print_time_s = 0, filament_mm = 0, filament_cm3 = 0, filament_g = 0;  ///< without supports
    double supported_time_s = 0, supported_filament_g = 0;  ///< each piece with supports where it needs them
    size_t pieces_needing_supports = 0;
};
PrintCheckTotal sumPrintChecks(const std::vector<PrintCheckReport>& reports);
std::string formatPrintCheckTotal(const PrintCheckTotal& total);
nlohmann::json toJson(const PrintCheckTotal& total);

}  // namespace tsf
