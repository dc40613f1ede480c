// TopShapes: pillar tops that are not flat hexagons - tilted tops (gen/model/features/tilt.h)
// and the conical dimple of structural cells - as data in the Scene, so the
// direct mesher, the OpenSCAD file and the verifier draw and read the same
// numbers.
//
// A shaped cell's top is a fan of triangles from its centre vertex over its
// six corners (and the crossing points on its edges, below): every corner has
// its own height on the z grid, the centre the height its value asks for
// (tilt) or the floor lowered by the dimple's depth (structural cells). A
// mirrored model's shaped cell has a bottom fan too: a tilted bottom is the
// top moved down by the slab thickness (the same plane, so from below it tilts
// the same way as the value's heights do: docs/model.md), a dimple's bottom is
// raised at the centre (felt from below the same way).
//
// Crossings. Where two neighbouring tops (or mirrored bottoms) cross along
// their shared edge - one higher at one end, the other at the other end - the
// wall between them is two triangles that meet at a crossing point on the
// edge. That point is a vertex of both tops and of both walls (no
// T-junction). It lies on the edge at the crossing of the two top lines, but
// never nearer than kMinCrossingMm to an end (the crossing moves along the
// edge to that distance), so no wall or top triangle has a side shorter than
// that; its height is the mean of the two top lines there, on the z grid.
//
// Planar ids. Fan centres and crossing points get planar ids after the
// lattice's and the marks' (Scene::planarPoint): first_id + n is extra[n] at
// height extra_z[n]. Each such vertex has exactly one height.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "gen/model/features/marks.h"

namespace tsf {

struct Scene;

/// Nearest a crossing point comes to either end of its edge, mm: half a
/// 0.4 mm nozzle's width, far above the 1 um xy grid, well below an edge.
inline constexpr double kMinCrossingMm = 0.2;

struct TopShapes {
    // Per kept cell (all empty when no cell is shaped).
    std::vector<std::array<int32_t, 6>> top_dz;     ///< z of corner e minus Scene::top[k], z units
    std::vector<std::array<int32_t, 6>> bottom_dz;  ///< mirrored: z of corner e minus Scene::bottom[k]
    std::vector<int32_t> top_centre_dz;             ///< z of the top's centre minus top[k] (< 0: a dimple)
    std::vector<int32_t> bottom_centre_dz;          ///< mirrored: z of the bottom's centre minus bottom[k]
    std::vector<double> slope_x, slope_y;           ///< the tilt drawn, mm per mm (x east, y north); 0 = level
    std::vector<uint8_t> structural;                ///< 1: kept only to hold the model together (dimpled)
    // Geometry made from the above by buildTopShapeGeometry.
    std::vector<uint8_t> shaped;          ///< 1: top (and mirrored bottom) drawn as a fan from the centre
    std::vector<int64_t> centre_top_id;   ///< planar id of the top fan's centre, -1 if not shaped
    std::vector<int64_t> centre_bottom_id;  ///< mirrored: planar id of the bottom fan's centre
    std::vector<int64_t> crossing_top;      ///< 6 per kept cell (edge e): planar id of the tops' crossing, -1
    std::vector<int64_t> crossing_bottom;   ///< 6 per kept cell: the mirrored bottoms' crossing, -1
    int64_t first_id = 0;                   ///< planar id of extra[0]
    std::vector<PlanarPoint> extra;         ///< fan centres and crossing points, lattice coordinates
    std::vector<int64_t> extra_z;           ///< the one height of each extra vertex, z units
    // Facts for the summary.
    int64_t cells_tilted = 0;    ///< cells whose top is not level
    int64_t cells_clamped = 0;   ///< cells whose tilt was made shallower to stay above the floor / clear of a mark
    int64_t cells_flat_clamped = 0;  ///< of those, cells that had to stay level
    int64_t cells_textured = 0;  ///< structural cells with a dimple
    int64_t dimple_units = 0;    ///< depth of the dimple at the centre, z units

    bool empty() const { return top_dz.empty(); }
};

/// Shapes for `cells` kept cells, every top (and, `mirrored`, every bottom)
/// level and no cell structural: what the tilt and the sidecar fill in.
TopShapes levelTopShapes(size_t cells, bool mirrored);

/// z (units) of corner e (0..5, hex_grid.h) of kept cell k's top / bottom.
int64_t cornerTop(const Scene& s, size_t k, int e);
int64_t cornerBottom(const Scene& s, size_t k, int e);
/// The same at lattice vertex `id`, which must be a corner of cell k.
int64_t cornerTopAt(const Scene& s, size_t k, int64_t id);
int64_t cornerBottomAt(const Scene& s, size_t k, int64_t id);
/// z (units) of the top's / bottom's centre of kept cell k (a dimple lowers it).
int64_t centreTop(const Scene& s, size_t k);
int64_t centreBottom(const Scene& s, size_t k);
/// True when kept cell k is drawn as a fan.
inline bool isShaped(const TopShapes& t, size_t k) { return !t.shaped.empty() && t.shaped[k]; }
/// True when kept cell k is structural (kept only to connect the model).
inline bool isStructural(const TopShapes& t, size_t k) { return !t.structural.empty() && t.structural[k]; }

/// Which face lies across each directed edge (v, w) of a face ring (planar ids).
std::map<std::pair<int64_t, int64_t>, int32_t> facesOnEdges(const Scene& scene);

/// Throws InputError (scene_check.h) when scene.shapes is not what the
/// mesher builds on: lists of the wrong length, a corner or centre whose
/// bottom is not below its top, neighbours whose spans do not overlap at a
/// shared corner, tops (or bottoms) that cross without their crossing point,
/// or a shaped top that crosses a mark's face. Empty shapes pass.
void checkTopShapes(const Scene& scene);

/// From the per-cell corner and centre offsets of scene.shapes, makes the
/// crossings, the fan centres and their planar ids (shaped, centre_*_id,
/// crossing_*, first_id, extra, extra_z). Call after the marks' faces are
/// built (the ids follow theirs). Does nothing when scene.shapes is empty.
void buildTopShapeGeometry(Scene& scene);

}  // namespace tsf
