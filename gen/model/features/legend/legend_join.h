// The braille legend's solid in the model frame, drawn from the plate and
// dots placeLegend recorded in the Scene (gen/model/features/legend/legend_scene.h)
// on the outline the plate stands on beside the pillars
// (gen/model/features/legend/legend_plate.h).
#pragma once

#include "gen/geometry/mesh.h"
#include <cstdint>
#include <optional>

#include "gen/model/feature.h"
#include "gen/model/features/legend/legend_mesh.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

struct Scene;

/// The legend plate in the model frame as a closed solid, with its dots
/// standing on it, or without them (dots = false). Empty without a legend.
Mesh legendPlateMesh(const Scene& scene, bool dots = true);

/// The legend as an attachment (gen/model/scene_attachments.h), part
/// "legend": the plate stands against the pillars' walls over its z band;
/// its body is the plate without its sides against them (from 0 to their
/// tops, or to the plate's top where a pillar is lower), whose lattice
/// corners are the pillars' own vertices. In one piece the dots stand on
/// it; in parts the plate stays with the pillars and the dots are the
/// legend's own part. None without a legend.
std::optional<Attachment> legendAttachment(const Scene& scene, Assembly assembly);

/// The legend's read-back: its plate's top north of the braille (both ends)
/// and the apex of every braille dot (plate top + dot height, on the 1 um
/// grid). Empty without a legend.
ProbeSet legendProbes(const Scene& scene);

/// The legend's x, y box (mm): from its frame's west edge to the plate's
/// east, the plate's south to north; none without a legend.
std::optional<BoxMm> legendBoxMm(const Scene& scene);

/// The plate's box as the footprint it claims (gen/model/feature.h): what a
/// feature placed after it keeps clear of; none without a legend.
std::optional<FootprintClaim> legendClaim(const Scene& scene);

/// z (units) of the legend plate's top at (x, y) mm, or none beside the plate.
std::optional<int64_t> legendTopAt(const Scene& scene, double x_mm, double y_mm);

/// The legend's dots alone in the model frame: one closed dome per dot on the
/// plate's top (gen/model/features/legend/legend_mesh.h meshLegendDots). Empty without a legend.
Mesh legendDotsMesh(const Scene& scene);

/// Its piece of the generated OpenSCAD file (gen/model/feature.h), made in
/// legend_scad.cpp: the "Braille legend" switch and `legend_plate =
/// [points, faces];` (mm) for scad_lib/tsf_legend.scad, which wraps the
/// terrain in tsf_with_legend(legend_plate, braille_legend); none without
/// a legend.
std::optional<ScadPiece> legendScadPiece(const Scene& scene);

}  // namespace tsf
