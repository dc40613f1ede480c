// The orientation tab in a generated OpenSCAD file: the tab tsf placed
// (gen/model/features/orientation_tab.h) as data for scad_lib/tsf_tab.scad.
#pragma once

#include <string>

namespace tsf {

struct Scene;

/// Appends the "Orientation marks" customizer switch and
/// `orientation_tab = [...];` (mm) when the Scene has a tab; nothing otherwise.
void emitTabData(std::string& out, const Scene& scene);

/// "tsf_with_tab(orientation_tab, show_orientation_tab) " when the Scene has
/// a tab (it prefixes the terrain call), "" otherwise.
std::string tabCallPrefix(const Scene& scene);

}  // namespace tsf
