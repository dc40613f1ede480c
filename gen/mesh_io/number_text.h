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
/// Appends "[x, y, z]", each coordinate the shortest text of its double
/// (the point lists of the OpenSCAD files).
void appendPoint(std::string& out, double x, double y, double z);

}  // namespace tsf::mesh_io
