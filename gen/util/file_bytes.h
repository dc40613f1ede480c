// readFileBytes: a whole file in memory, for every reader (fields in gen/readers,
// meshes in gen/mesh_io, the scene sidecar).
#pragma once

#include <cstdint>
#include <string>

namespace tsf {

/// The file's bytes, unchanged (binary, no newline translation). Throws
/// tsf::InputError naming path if it does not exist, is a folder or a device
/// (/dev/zero: endless), cannot be read (with the OS reason) or holds more
/// than max_bytes (0 = no limit; a pipe is read until it passes the limit,
/// so memory stays below twice max_bytes). An empty file is returned
/// as an empty string; the format readers say what they expected. Works for
/// pipes and other files without a size too.
std::string readFileBytes(const std::string& path, int64_t max_bytes = 0);

/// At most the first `head_bytes` bytes of the file, for telling its format
/// from its magic bytes without reading all of it. Same errors as
/// readFileBytes.
std::string readFileHead(const std::string& path, size_t head_bytes);

}  // namespace tsf
