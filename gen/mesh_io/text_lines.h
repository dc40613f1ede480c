// Line builders shared by the OFF and OBJ writers. Internal to gen/mesh_io/.
#pragma once

#include <array>
#include <cstdint>
#include <iosfwd>
#include <string>

#include "gen/geometry/mesh.h"

namespace tsf::mesh_io {

/// Appends "<prefix>x y z\n" with shortest exact round-trip doubles.
void appendPositionLine(std::string& text, const char* prefix, const Vec3& p);
/// Appends "<prefix>a b c\n" with each index plus base (0 for OFF, 1 for OBJ).
void appendTriangleLine(std::string& text, const char* prefix, const std::array<uint32_t, 3>& tri, uint32_t base);
/// Writes text to out and clears it once it holds a chunk's worth (or always
/// when force is set), so large meshes stream with bounded memory.
void flushText(std::string& text, std::ostream& out, bool force = false);

}  // namespace tsf::mesh_io
