// The orientation tab in a generated OpenSCAD file: the tab tsf placed
// (gen/model/features/orientation_tab.h) as data for scad_lib/tsf_tab.scad.
#pragma once

#include <optional>

#include "gen/scad/scad_attachment.h"

namespace tsf {

struct Scene;

/// The tab's piece of the file when the Scene has one: the "Orientation
/// marks" switch `show_orientation_tab` and `orientation_tab = [...];` (mm)
/// for scad_lib/tsf_tab.scad, wrapping the terrain in
/// tsf_with_tab(orientation_tab, show_orientation_tab).
/// join: written for scad_lib/tsf_joined.scad when it can be (gen/scad/scad_joined.h).
std::optional<ScadAttachment> scadTab(const Scene& scene, bool join);

}  // namespace tsf
