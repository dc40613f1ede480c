// Braille through liblouis: text -> braille cells (dot patterns).
//
// liblouis (Debian liblouis-dev) holds the braille codes of most languages
// as tables; tsf asks it for dot patterns (its dotsIO mode), never for ASCII
// braille, so any table works the same way. The default is Unified English
// Braille, uncontracted (en-ueb-g1.ctb; docs/printing.md argues the choice).
//
// A cell is 8 bits: bit k-1 set = dot k raised (dots 1-2-3 down the left
// column, 4-5-6 down the right, 7-8 below them in 8-dot tables). A space is
// the empty cell 0.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tsf {

/// Unified English Braille, uncontracted (docs/printing.md says why).
inline constexpr const char* kDefaultBrailleTable = "en-ueb-g1.ctb";

/// Translates UTF-8 text to braille cells with the liblouis table (a name
/// such as "en-us-g1.ctb" or "de-g0.utb", or a comma-separated list).
/// Throws InputError for a table liblouis cannot load, text that is not
/// UTF-8, or text liblouis cannot translate.
std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table);

/// The same, and for each cell the index of the code point of the text it
/// came from (liblouis' inputPos): a layout can tell which blank cells
/// came from a no-break space (U+00A0, translated as a space) and keep
/// the words around them on one line.
std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table,
                                        std::vector<int>& source_of_cell, std::vector<uint32_t>& code_points);

/// Braille cells back to text with the liblouis table (lou_backTranslate):
/// to check that what is embossed says what the text says. Throws
/// InputError as translateToBraille.
std::string backTranslateBraille(const std::vector<uint8_t>& cells, const std::string& table);

/// The braille code a liblouis table writes, in words, for a reader:
/// "Unified English Braille, uncontracted" (en-ueb-g1.ctb), "English Braille
/// American Edition, contracted" (en-us-g2.ctb), ...; for any other table
/// "the liblouis table NAME".
std::string brailleCodeName(const std::string& table);

/// The cells as Unicode braille patterns (U+2800 + cell), UTF-8: for reports and tests.
std::string brailleUnicode(const std::vector<uint8_t>& cells);

}  // namespace tsf
