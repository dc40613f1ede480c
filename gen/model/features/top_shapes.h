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

#include "gen/model/scene.h"

namespace tsf {

/// Nearest a crossing point comes to either end of its edge, mm: half a
/// 0.4 mm nozzle's width, far above the 1 um xy grid, well below an edge.
inline constexpr double kMinCrossingMm = 0.2;


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

/// The highest z (units) any pillar's top reaches: its level top, or its
/// shaped top's highest corner or centre (marks and attachments not counted).
int64_t highestPillarTop(const Scene& s);

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
