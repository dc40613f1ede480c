// STL reader: binary or ASCII, told apart by content.
//
// Detection: a file whose size is exactly 84 + 50 * (the uint32 count at byte
// 80) is binary, even if its header starts with "solid" (many exporters do
// that). Otherwise a file starting with "solid" whose first kilobyte is text
// is ASCII. Anything else is an error that says which check failed.
//
// Binary: coordinates are little-endian float32 widened to double; facet
// normals and attribute bytes are ignored (nonzero attribute bytes get a
// note). ASCII: keywords in any case, numbers parsed as double, one or more
// "solid ... endsolid" blocks, exactly three vertices per facet.
//
// STL stores each corner on its own, so corners are merged into vertices,
// but only when exactly equal (gen/mesh_io/exact_vertex_index.h).
// Errors (tsf::InputError): empty file, truncated file or count mismatch
// (with byte offsets), NaN or infinite coordinates (binary: byte offset;
// ASCII: line and column), malformed ASCII (line, column, what was expected).
#pragma once

#include <string>
#include <string_view>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf {

/// Reads the STL file at path.
Mesh readStl(const std::string& path, MeshReadReport* report = nullptr);

/// Parses STL bytes already in memory; name is used in error messages.
Mesh parseStl(std::string_view bytes, const std::string& name, MeshReadReport* report = nullptr);

}  // namespace tsf
