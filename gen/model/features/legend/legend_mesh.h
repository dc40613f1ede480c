// The braille legend as a closed solid: a plate with the legend's domed
// dots standing on its top, every dot's base sharing its vertices with the
// plate's top (one piece, no T-junctions).
//
// The plate stands from z = 0 to height_mm on its outline
// (gen/model/features/legend/legend_plate.h: the plate's box less the pillars in
// it; without one, the box [x0, x1] x [y0, y1]). Its top is a constrained
// Delaunay triangulation of the outline and each dot's base octagon
// (vertices at 0, 45, ..., 315 degrees); the bottom is the outline's at
// z = 0; the sides stand on every outline edge. A dot is a low-poly
// spherical cap: the base octagon (diameter dot_base_mm), kDomeRings smaller
// octagons on the sphere, and an apex dot_height_mm above the plate. Every
// input position must be on the model's xy grid; the mesh adds no other xy
// position except the dots' rings.
#pragma once

#include <array>
#include <vector>

#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_plate.h"
#include "gen/geometry/mesh.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Octagons above the base of a dome, before the apex.
inline constexpr int kDomeRings = 2;
/// Corners of a dome's base and rings.
inline constexpr int kDomeSides = 8;

struct PlateSpec {
    double x0_mm = 0, y0_mm = 0, x1_mm = 0, y1_mm = 0;  ///< the box's footprint
    double height_mm = 0;                              ///< its top, > bottom_mm
    double bottom_mm = 0;                              ///< its bottom: the bed, or a mirrored model's band
    std::vector<LegendDot> dots;                       ///< centres, same frame as the box
    BrailleStandard standard = kNlsSpec800;
    /// The plate's footprint (empty: the box). Its corners are those of the
    /// plate's top and bottom, in order.
    PlateOutline outline;
    /// Per outline edge, with `joined`: where its side starts, mm. bottom_mm
    /// is a whole side; at or above height_mm no side (a pillar's wall stands
    /// there); between, a pillar lower than the plate (a no-data pit).
    std::vector<double> side_from_mm;
    /// Per outline point (or empty): more heights its corner line carries,
    /// mm, where the pillars meeting it there have vertices (a pit's top
    /// beside the plate's own side), so the sides split there too.
    std::vector<std::vector<double>> point_heights_mm;
};

/// The plate and its dots as a closed solid. `joined`: the sides
/// side_from_mm leaves out are left open, to be closed by the pillars the
/// outline stands against (the part of a joined mesh). lattice_id[v] is the
/// outline point's lattice id a vertex stands on, -1 for the plate's own.
JoinedBody meshPlateBody(const PlateSpec& spec, bool joined);

/// The plate and its dots as one closed, outward-facing, 2-manifold mesh.
Mesh meshLegendPlate(const PlateSpec& spec);

/// The spec's dots alone, each a closed dome: its base octagon (the same
/// points as the plate's, facing down at z = height_mm) under the cap. The
/// domes stand on the plate's top without sharing its volume: the legend as
/// a part of its own (gen/mesh/scene_parts.h).
Mesh meshLegendDots(const PlateSpec& spec);

/// The plate under a laid-out legend alone: [0, width] x [0, depth], no extra edges.
/// An empty layout gives an empty mesh.
Mesh meshLegendPlate(const LegendLayout& layout, double plate_height_mm);

}  // namespace tsf
