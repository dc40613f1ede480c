// The braille legend's plate as it stands beside the pillars: its footprint
// and which of its edges are pillar walls.
//
// placeLegend (legend_scene.h) decides the plate's box: x from 0 to its east
// edge, y from the line through the upper side corners of reach_row to its
// north edge. The plate is that box LESS every kept hexagon in it, so it
// never overlaps a pillar: it fills the culled corners and the notches of
// the outline between the hexagons' tips and stands against their walls.
// Every edge where it meets a pillar is a whole hexagon edge between two
// lattice corners, and every other corner of its outline is a lattice point
// on the box or one of the box's two north corners, so the pillars and the
// plate join exactly (shared lattice edges at 0 and the floor, no boolean
// operation), as the tactile scale and the orientation tab do.
//
// Derived from the Scene, never stored: the box, reach_row and the kept
// cells decide it.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gen/model/scene_attachments.h"

namespace tsf {

struct Scene;

/// The plate's footprint as directed edges with the plate on their left
/// (counter-clockwise seen from +z): its outline and the outlines of the
/// pillars standing inside it. Outlines may touch at a corner (a hexagon's
/// tip on the south edge), never cross.
struct PlateOutline {
    std::vector<OutlinePoint> points;  ///< mm; lattice: the lattice vertex id of a kept cell's corner, -1 otherwise
    struct Edge {
        uint32_t a = 0, b = 0;  ///< into points
        int32_t cell = -1;      ///< the kept cell whose wall this is, -1: the plate's own side
        int side = -1;          ///< that cell's edge (0..5, hex_grid.h)
    };
    std::vector<Edge> edges;
    /// A wall it would stand against is cut by a mark in the data (the
    /// notch): the outline is not a plate that can be made (placeLegend
    /// keeps the plate north of such rows).
    bool meets_cut = false;
};

/// The outline of the Scene's legend plate (empty without a legend).
PlateOutline legendPlateOutline(const Scene& scene);

/// Whether the plate's east edge is the grid box's east edge (a lattice
/// line), rather than further east under a legend wider than the grid.
bool legendEastOnLattice(const Scene& scene);

}  // namespace tsf
