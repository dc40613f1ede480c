// Tokens of the text mesh formats (ASCII STL, OFF, OBJ): numbers parsed with
// an error at the token's position on failure, keywords compared ignoring
// case, file content quoted for messages. Internal to gen/mesh_io/; the
// tokens and their positions come from tsf::TextScanner (gen/util/text_scanner.h).
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

#include "gen/util/text_scanner.h"

namespace tsf::mesh_io {

/// token (the last one scanner returned) as a finite double (an optional
/// leading '+' is accepted), or scanner.fail() saying that `what` was expected.
double finiteNumber(const TextScanner& scanner, std::string_view token, const char* what);
/// token as a double, NaN and infinities allowed (for values that are read
/// and ignored, like STL facet normals).
double anyNumber(const TextScanner& scanner, std::string_view token, const char* what);
/// token as a whole number, or fail.
int64_t integer(const TextScanner& scanner, std::string_view token, const char* what);

/// True if token equals keyword ignoring ASCII case.
bool equalsIgnoringCase(std::string_view token, std::string_view keyword);

/// text cut to max_chars with control and non-ASCII bytes shown as '?', in
/// single quotes, for quoting file content in error messages.
std::string quoteForMessage(std::string_view text, size_t max_chars = 40);

}  // namespace tsf::mesh_io
