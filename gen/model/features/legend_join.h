// The braille legend's solid in the model frame, drawn from the plate and
// dots placeLegend recorded in the Scene (gen/model/features/legend_scene.h)
// on the outline the plate stands on beside the pillars
// (gen/model/features/legend_plate.h).
#pragma once

#include "gen/geometry/mesh.h"
#include "gen/model/features/legend_mesh.h"

namespace tsf {

struct Scene;

/// The legend plate in the model frame as a closed solid, with its dots
/// standing on it, or without them (dots = false). Empty without a legend.
Mesh legendPlateMesh(const Scene& scene, bool dots = true);

/// The same without its sides against the pillars (from 0 to their tops, or
/// to the plate's top where a pillar is lower): the part of the joined mesh,
/// whose lattice corners are the pillars' own vertices (lattice_id).
PlateBody legendJoinedBody(const Scene& scene, bool dots = true);

/// The legend's dots alone in the model frame: one closed dome per dot on the
/// plate's top (gen/model/features/legend_mesh.h meshLegendDots). Empty without a legend.
Mesh legendDotsMesh(const Scene& scene);

}  // namespace tsf
