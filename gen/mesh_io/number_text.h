// Locale-independent shortest round-trip number text for the text writers.
// Internal to gen/mesh_io/.
//
// std::to_chars writes the shortest decimal that reads back to exactly the
// same value (at most 9 significant digits for a float, 17 for a double), and,
// unlike printf("%.9g"), never writes a decimal comma under a foreign locale.
#pragma once

#include <string>

namespace tsf::mesh_io {

/// Appends the shortest text that parses back to exactly value (float32).
void appendShortest(std::string& out, float value);
/// Appends the shortest text that parses back to exactly value (double).
void appendShortest(std::string& out, double value);

}  // namespace tsf::mesh_io
