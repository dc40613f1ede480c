// Wavefront OBJ writer: exact text form of an indexed mesh.
//
// Layout: "# <title>", "o <title>", one "v x y z" line per vertex, one
// "f a b c" line per triangle (1-based indices, as OBJ requires). Numbers as
// in the OFF writer: shortest exact round-trip decimals, locale-independent.
// Units: mm (OBJ itself has no unit).
#pragma once

#include <iosfwd>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_write_options.h"

namespace tsf {

/// Writes mesh to path atomically. Uses opts.title only. Errors as writeOff.
void writeObj(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts = {});

/// OBJ text of mesh to out (mesh must be finite with in-range indices).
void writeObj(const Mesh& mesh, std::ostream& out, const std::string& title);

}  // namespace tsf
