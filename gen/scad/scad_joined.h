// An attachment (gen/model/scene_attachments.h) written into a generated
// OpenSCAD file as the data scad_lib/tsf_joined.scad joins into the
// terrain's one polyhedron: its wall contacts and its open body, whose
// vertices on a contact's corner are lattice corners the library computes
// like the pillars' own. No boolean: OpenSCAD keeps every corner as written.
#pragma once

#include <string>

#include "gen/model/scene_attachments.h"

namespace tsf {

struct Scene;

/// True when the library can join `a` into the terrain polyhedron: it
/// stands only against plain cells' walls (no RingContact on a mark's face,
/// no contact corner on a face's ring) and its body's joined vertices are
/// lattice corners. Otherwise the file unions the closed body.
bool scadCanJoin(const Scene& scene, const Attachment& a);

/// `[walls, points, corners, triangles]` (tsf_joined.scad): walls
/// [col, row, edge, bottom, top] (z steps), the body's own points [x, y, z]
/// in mm, its lattice corners [i, j, z steps], triangles counter-clockwise
/// from outside with the corners numbered after the points. Rows of a few
/// entries per line, each line starting with `indent`. Requires
/// scadCanJoin(scene, a).
std::string scadJoinedData(const Scene& scene, const Attachment& a, const std::string& indent = "  ");

/// An assert() line for the file: the body `what` ("the braille legend")
/// shown by `show_switch` stands where tsf placed it for the cell, snap and
/// mirror it wrote (its own points are millimetres, its corners follow the
/// lattice), so another cell, snap or mirror stops the render with what to do.
std::string scadJoinedAssert(const Scene& scene, const std::string& show_switch, const std::string& what);

}  // namespace tsf
