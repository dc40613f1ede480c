// OFF reader (Object File Format, as written by CGAL, Geomview, MeshLab).
//
// Accepts the header "OFF" and the colour/normal variants "COFF", "NOFF",
// "CNOFF" (the extra per-vertex values are ignored), counts on the header
// line or the next one ("<vertices> <faces> [<edges>]"), '#' comments, and
// faces with any number of corners >= 3, fan-triangulated from their first
// corner (right for the convex faces OFF writers produce; noted in the
// report). Values after a face's indices (colours) are ignored. Binary OFF
// and the 4D/nD/texture variants are refused.
//
// Exactly equal positions are merged (gen/mesh_io/exact_vertex_index.h).
// Errors (tsf::InputError with line and column): missing header, bad counts,
// non-numbers, NaN/infinite coordinates, an index outside 0..vertices-1, a
// face with fewer than 3 corners, fewer or more entries than the counts say.
#pragma once

#include <string>
#include <string_view>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf {

/// Reads the OFF file at path.
Mesh readOff(const std::string& path, MeshReadReport* report = nullptr);

/// Parses OFF text already in memory; name is used in error messages.
Mesh parseOff(std::string_view text, const std::string& name, MeshReadReport* report = nullptr);

}  // namespace tsf
