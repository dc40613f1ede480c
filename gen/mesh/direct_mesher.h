// DirectMesher: the boundary of a Scene's solid as an exact triangle mesh.
//
// meshScene returns the boundary of the union of the Scene's prisms:
//   - a top face per kept cell (hexagon, 4 triangles), except that
//     edge-connected plain level cells of one height share one top polygon
//     whose interior lattice vertices are left out but for a sparse
//     sublattice (every 4th row and column), so its triangles are a few
//     cells across;
//   - a bottom face per kept cell when mirrored; a flat bottom is ONE polygon
//     (the outline of the kept region) with the same sparse interior vertices;
//   - a vertical wall wherever a neighbour's z interval does not cover this
//     cell's (only where heights differ; outer walls on the kept region's rim);
//   - the Scene's attachments (gen/model/attachments.h: bodies that stand
//     against the outer walls, whichever feature made them): each covers the
//     walls it touches over its z span as a neighbour would, and shares their
//     lattice corners, so no boolean operation joins them; and its cuts
//     (holes into the flat bottom).
// Every corner line is split at every height that meets it, so there are no
// T-junctions; vertices are identified by lattice id and snapped height, never
// by comparing floats. The result is closed, 2-manifold, outward-oriented
// (CCW from outside) and has no zero-area triangles.
#pragma once

#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Mesh the Scene. An empty Scene (no kept cells) gives an empty Mesh. A
/// Scene that breaks the invariants the mesher builds on (gen/model/scene_check.h;
/// buildScene never makes one) is a tsf::InputError.
/// With Assembly::Parts only what stays with the pillars is joined to them
/// (gen/mesh/scene_parts.h draws the rest as parts of their own).
Mesh meshScene(const Scene& scene, Assembly assembly = Assembly::OnePiece);

/// The same with the Scene's attachments as sceneAttachments gave them
/// (gen/model/attachments.h), for a caller that uses them too.
Mesh meshScene(const Scene& scene, const std::vector<Attachment>& attachments);

}  // namespace tsf
