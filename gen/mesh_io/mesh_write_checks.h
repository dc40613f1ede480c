// Checks every writer runs before touching the disk, so a bad mesh never
// produces a file. Internal to gen/mesh_io/.
#pragma once

#include <string>

#include "gen/geometry/mesh.h"

namespace tsf::mesh_io {

/// Throws std::invalid_argument if a triangle refers to a vertex that does not
/// exist (a bug in whoever built the mesh), and tsf::InputError naming path if
/// a coordinate is NaN or infinite or, when float32_format is set, too large
/// for a 32-bit float (STL and 3MF store float32).
void checkMeshForWriting(const Mesh& mesh, const std::string& path, bool float32_format);

/// title with control characters (bytes < 0x20 and 0x7F) replaced by spaces,
/// so it cannot break a line-based format.
std::string printableTitle(const std::string& title);

}  // namespace tsf::mesh_io
