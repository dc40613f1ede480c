// Braille through liblouis: text -> braille cells (dot patterns).
//
// liblouis (Debian liblouis-dev) holds the braille codes of most languages
// as tables; tsf asks it for dot patterns (its dotsIO mode), never for ASCII
// braille, so any table works the same way. The default is uncontracted
// (grade 1) US English, as signage guidance asks for (docs/printing.md).
//
// A cell is 8 bits: bit k-1 set = dot k raised (dots 1-2-3 down the left
// column, 4-5-6 down the right, 7-8 below them in 8-dot tables). A space is
// the empty cell 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tsf {

/// Uncontracted (grade 1) US English braille.
inline constexpr const char* kDefaultBrailleTable = "en-us-g1.ctb";

/// Translates UTF-8 text to braille cells with the liblouis table (a name
/// such as "en-us-g1.ctb" or "de-g0.utb", or a comma-separated list).
/// Throws InputError for a table liblouis cannot load, text that is not
/// UTF-8, or text liblouis cannot translate.
std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table);

/// The cells as Unicode braille patterns (U+2800 + cell), UTF-8: for reports and tests.
std::string brailleUnicode(const std::vector<uint8_t>& cells);

}  // namespace tsf
