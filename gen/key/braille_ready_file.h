// Braille Ready Format (.brf): formatted braille for an embosser or a
// braille display, as North American Braille ASCII (one printable ASCII
// character per six-dot cell: the 64 cells map to 0x20-0x5F, the mapping
// liblouis' en-us-brf.dis also uses).
//
// Layout: 40 cells to a line and 25 lines to a page (the common US embosser
// page, 11 x 11.5 in), lines ending CR LF, pages ending with a form feed.
// Each paragraph starts on a new line, indented two cells (BANA's
// paragraph form); the first paragraph (the title) is not indented. Lines
// break between words, never at a no-break space (U+00A0: the key puts one
// between a number and its unit); a word longer than a line is split.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace tsf {

inline constexpr int kBrfCellsPerLine = 40;
inline constexpr int kBrfLinesPerPage = 25;

/// The Braille ASCII character of a six-dot cell (bit k-1 = dot k); dots 7
/// and 8 have no character and are dropped.
char brailleAsciiOf(uint8_t cell);

/// The paragraphs translated with the liblouis table (translateToBraille)
/// and laid out as above. Throws as translateToBraille.
std::string brailleReadyFile(const std::vector<std::string>& paragraphs, const std::string& table);

}  // namespace tsf
