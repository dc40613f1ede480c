// meshLegendPlate: the braille legend as a closed solid: a plate with the
// legend's domed dots standing on its top, every dot's base sharing its
// vertices with the plate's top (one piece, no T-junctions).
//
// The plate is the box [x0, x1] x [y0, y1] x [0, height] mm. Its top is a
// constrained Delaunay triangulation (exact kernel) of the box's outline,
// each dot's base octagon (vertices at 0, 45, ..., 315 degrees) and any
// extra segments the caller needs as edges of the top (the hexagon edges of
// the pillars the plate reaches under, so that joining the two meets walls
// only at lattice corners). The bottom is the same triangulation at z = 0;
// the sides join them at every vertex on the outline. A dot is a low-poly
// spherical cap: the base octagon (diameter dot_base_mm), kDomeRings smaller
// octagons on the sphere, and an apex dot_height_mm above the plate. Every
// input position must be on the 1 um grid; the mesh adds no other xy
// position except the dots' rings.
#pragma once

#include <array>
#include <vector>

#include "gen/model/features/legend.h"
#include "gen/geometry/mesh.h"

namespace tsf {

/// Octagons above the base of a dome, before the apex.
inline constexpr int kDomeRings = 2;
/// Corners of a dome's base and rings.
inline constexpr int kDomeSides = 8;

/// A segment in the plane z = const, mm.
struct PlateSegment {
    double ax = 0, ay = 0, bx = 0, by = 0;
};

struct PlateSpec {
    double x0_mm = 0, y0_mm = 0, x1_mm = 0, y1_mm = 0;  ///< the box's footprint
    double height_mm = 0;                              ///< its top, > 0
    std::vector<LegendDot> dots;                       ///< centres, same frame as the box
    BrailleStandard standard = kNlsSpec800;
    std::vector<PlateSegment> top_edges;               ///< inside the box; they may touch its outline
};

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
