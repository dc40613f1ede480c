// The braille legend's solid in the model frame, drawn from the plate and
// dots placeLegend recorded in the Scene (gen/model/features/legend_scene.h),
// and its exact join to the pillars.
#pragma once

#include "gen/geometry/mesh.h"

namespace tsf {

struct Scene;

/// The legend plate in the model frame (closed, on the 1 um grid), with its
/// dots standing on it, or without them (dots = false).
Mesh legendPlateMesh(const Scene& scene, bool dots = true);

/// The legend's dots alone in the model frame: one closed dome per dot on the
/// plate's top (gen/mesh/legend_mesh.h meshLegendDots). Empty without a legend.
Mesh legendDotsMesh(const Scene& scene);

/// The union of the pillars' mesh and the legend plate (with its dots, or
/// without them: dots = false), computed with exact arithmetic (CGAL
/// corefinement); every vertex lands on the model's grid.
Mesh unionWithLegend(const Mesh& pillars, const Scene& scene, bool dots = true);

}  // namespace tsf
