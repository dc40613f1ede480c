// OFF writer: exact text form of an indexed mesh.
//
// Layout: "OFF", a "# <title>" comment, "<vertices> <faces> 0", one
// "x y z" line per vertex, one "3 a b c" line per triangle (0-based indices).
// Every coordinate is the shortest decimal that reads back to exactly the same
// double (at most 17 significant digits, locale-independent), so write -> read
// reproduces positions bit for bit. Units: mm, as in the mesh.
#pragma once

#include <iosfwd>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_write_options.h"

namespace tsf {

/// Writes mesh to path atomically. Uses opts.title only. Errors as writeStl
/// (gen/mesh_io/stl_writer.h), without the float32 limit.
void writeOff(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts = {});

/// OFF text of mesh to out (mesh must be finite with in-range indices).
void writeOff(const Mesh& mesh, std::ostream& out, const std::string& title);

}  // namespace tsf
