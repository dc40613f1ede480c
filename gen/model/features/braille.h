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

/// Braille dimensions, mm.
struct BrailleStandard {
    const char* name;
    double dot_base_mm;    ///< diameter of a dot where it meets the surface
    double dot_height_mm;  ///< how far a dot stands above the surface
    double dot_pitch_mm;   ///< centre to centre of neighbouring dots in a cell
    double cell_pitch_mm;  ///< centre to centre of the same dot in neighbouring cells
    double line_pitch_mm;  ///< centre to centre of the same dot in neighbouring lines
};

/// NLS Specification 800, "Braille Books and Pamphlets" (Library of Congress,
/// 2008), section 3.2, as quoted by the Braille Authority of North America
/// (nominal values).
inline constexpr BrailleStandard kNlsSpec800{"NLS Specification 800 (2008) 3.2", 1.44, 0.48, 2.34, 6.2, 10.0};

/// The highest dot a reader expects, mm: 0.037 in, the top of the range for
/// tactile signs (2010 ADA Standards for Accessible Design, 703.3.1).
inline constexpr double kMaxBrailleDotHeightMm = 0.94;

/// The dot height (mm) when the printer's layer is not known: whole layers
/// at 0.1, 0.12, 0.15, 0.2 and 0.3 mm, 0.5 mm at 0.25 mm; the standard's
/// 0.48 mm would print 0.4 mm at 0.2 mm layers, under what a reader expects.
inline constexpr double kUnknownLayerDotHeightMm = 0.6;

/// The dot height (mm) printed at `layer_mm` layers: the slicer keeps a
/// layer where the dot reaches past its middle, so the height rounds to
/// whole layers. layer_mm <= 0 gives the height as it is.
double printedDotHeightMm(double dot_height_mm, double layer_mm);

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
