// --scad MODEL.scad: the parametric OpenSCAD file, its parameter sets and
// library beside it when asked, with a warning when it will render slowly.
#pragma once

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "gen/model/scene.h"

namespace tsf::cli {

/// Writes the OpenSCAD files of the Scene to o.scad and lists them in the summary.
void writeScadFiles(const GenCommandOptions& o, const ScadOptions& so, const Scene& scene, GenSummary& summary);

}  // namespace tsf::cli
