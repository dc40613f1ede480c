// The OpenSCAD pieces of whichever features a Scene has
// (gen/scad/scad_attachment.h): the one place that lists the features with
// a piece of their own in a generated file.
#pragma once

#include <vector>

#include "gen/scad/scad_attachment.h"

namespace tsf {

struct Scene;

/// Every feature's OpenSCAD piece the Scene has, in the order the file
/// carries their data and library files (the legend, the scale, the
/// orientation tab, the halves); the terrain call is wrapped in the reverse
/// order, so the first is innermost.
/// join: the terrain is one polyhedron (the polyhedron strategy, or any
/// shaped model), so an attachment that can be joined (gen/scad/scad_joined.h)
/// is written as its contacts and open body; otherwise as a closed body the
/// terrain is unioned with.
std::vector<ScadAttachment> scadAttachments(const Scene& scene, bool join);

}  // namespace tsf
