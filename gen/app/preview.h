// A preview picture of a written model, so a sighted helper can check it
// before hours of printing. Drawn by OpenSCAD (under a virtual display when
// there is none) from the model file itself, so it shows what was written.
#pragma once

#include <string>

namespace tsf::cli {

/// Renders model_path (STL, 3MF or OFF) to png_path (width x height pixels).
/// Throws std::runtime_error with OpenSCAD's error lines on failure, and
/// ScadEngineMissing (verify/render/openscad_runner.h) when OpenSCAD is missing.
void writeModelPreview(const std::string& model_path, const std::string& png_path, int width_px = 1024,
                       int height_px = 768);

}  // namespace tsf::cli
