// Wavefront OBJ reader: the polygon subset (v and f statements).
//
// "v x y z" (a 4th value w or r g b colours are ignored); "f" with corners
// written "v", "v/vt", "v//vn" or "v/vt/vn": 1-based indices, or negative
// ones counting back from the latest vertex (-1 = the last "v" so far).
// Faces with more than 3 corners are fan-triangulated from their first corner
// (noted in the report). Texture coordinates, normals, groups, objects,
// materials and smoothing groups are ignored; point and line elements and
// free-form geometry are ignored with a note. Any other statement is an error,
// so a file that is not OBJ is not silently read as an empty mesh.
//
// Exactly equal positions are merged (gen/mesh_io/exact_vertex_index.h).
// Errors (tsf::InputError with line and column): unknown statements,
// non-numbers, NaN/infinite coordinates, index 0, indices outside the vertex
// list, faces with fewer than 3 corners. Line continuations ('\') are not
// supported.
#pragma once

#include <string>
#include <string_view>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf {

/// Reads the OBJ file at path.
Mesh readObj(const std::string& path, MeshReadReport* report = nullptr);

/// Parses OBJ text already in memory; name is used in error messages.
Mesh parseObj(std::string_view text, const std::string& name, MeshReadReport* report = nullptr);

}  // namespace tsf
