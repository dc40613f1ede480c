// readFileBytes: a whole file in memory, for the mesh readers. Internal to
// gen/mesh_io/.
#pragma once

#include <string>
#include <string_view>

namespace tsf::mesh_io {

/// The file's bytes. Throws tsf::InputError naming path if it does not exist,
/// is a folder or cannot be read (with the OS reason). An empty file is
/// returned as an empty string; the format readers say what they expected.
std::string readFileBytes(const std::string& path);

/// text cut to max_chars with control and non-ASCII bytes shown as '?', in
/// single quotes, for quoting file content in error messages.
std::string quoteForMessage(std::string_view text, size_t max_chars = 40);

}  // namespace tsf::mesh_io
