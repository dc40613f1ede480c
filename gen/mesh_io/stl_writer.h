// STL writers: binary (default) and ASCII.
//
// Binary layout (all numbers little-endian whatever the host):
//   80 bytes  header: "<title> UNITS=mm", padded with NUL bytes; never starts
//             with "solid" (some readers would take the file for ASCII), a
//             title that does is prefixed with "binary "; cut to fit.
//   4 bytes   uint32 triangle count
//   50 bytes  per triangle: normal (3 x float32), 3 corners (9 x float32),
//             uint16 attribute byte count = 0.
// Coordinates are mm rounded to the nearest float32. The facet normal is the
// unit right-hand normal of the float32 corners (CCW seen from outside points
// outward); a triangle without area gets the normal (0, 0, 0).
//
// ASCII: "solid <title>" ... "endsolid <title>", each number written as the
// shortest decimal that reads back to the same float32 (at most 9 significant
// digits, locale-independent).
//
// STL has no shared vertices: a reader must merge corners back (see
// gen/mesh_io/mesh_reader.h) and float32 rounding can make distinct vertices
// equal. For exact positions use OFF or OBJ.
#pragma once

#include <iosfwd>
#include <string>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_write_options.h"

namespace tsf {

/// Writes mesh to path atomically (gen/util/atomic_file.h), binary unless
/// opts.ascii_stl. Throws tsf::InputError for an unusable path or a mesh that
/// cannot be stored (NaN, beyond float32, more than 2^32-1 triangles),
/// std::invalid_argument for out-of-range indices, std::runtime_error for I/O.
void writeStl(const Mesh& mesh, const std::string& path, const MeshWriteOptions& opts = {});

/// Binary STL bytes of mesh to out. The mesh must have passed the checks of
/// writeStl (finite, in-range indices). Stream errors are left in out's state.
void writeStlBinary(const Mesh& mesh, std::ostream& out, const std::string& title);

/// ASCII STL text of mesh to out (same preconditions as writeStlBinary).
void writeStlAscii(const Mesh& mesh, std::ostream& out, const std::string& title);

}  // namespace tsf
