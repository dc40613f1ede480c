#include "gen/key/braille_ready_file.h"

#include <array>

#include "gen/model/features/braille.h"

namespace tsf {
namespace {

/// North American Braille ASCII: the character of each six-dot cell, by
/// dots (bit 0 = dot 1 ... bit 5 = dot 6).
constexpr std::array<char, 64> brailleAsciiTable() {
    // The characters 0x20-0x5F with their dots, as the standard lists them.
    constexpr const char* kChars = " A1B'K2L@CIF/MSP\"E3H9O6R^DJG>NTQ,*5<-U8V.%[$+X!&;:4\\0Z7(_?W]#Y)=";
    std::array<char, 64> t{};
    for (int cell = 0; cell < 64; ++cell) t[size_t(cell)] = kChars[cell];
    return t;
}

constexpr std::array<char, 64> kBrailleAscii = brailleAsciiTable();

using Cells = std::vector<uint8_t>;

void endLine(std::string& out, int& line) {
    out += "\r\n";
    if (++line == kBrfLinesPerPage) {
        out += '\f';
        line = 0;
    }
}

}  // namespace

char brailleAsciiOf(uint8_t cell) { return kBrailleAscii[cell & 0x3F]; }

std::string brailleReadyFile(const std::vector<std::string>& paragraphs, const std::string& table) {
    std::string out;
    int line = 0;  // lines written on the current page
    for (size_t p = 0; p < paragraphs.size(); ++p) {
        std::vector<int> source;
        std::vector<uint32_t> code_points;
        const Cells cells = translateToBraille(paragraphs[p], table, source, code_points);
        // Words: runs of cells between blank cells; a blank from a no-break
        // space (a number and its unit) stays inside its word.
        std::vector<Cells> words(1);
        for (size_t k = 0; k < cells.size(); ++k) {
            const uint8_t c = cells[k];
            const int from = source[k];
            const bool glued = from >= 0 && size_t(from) < code_points.size() && code_points[size_t(from)] == 0xA0;
            if ((c & 0x3F) == 0 && !glued) {
                if (!words.back().empty()) words.emplace_back();
            } else {
                words.back().push_back(c);
            }
        }
        if (words.back().empty()) words.pop_back();
        std::string text(p == 0 ? 0 : 2, ' ');  // the current line
        bool line_has_word = false;
        for (Cells word : words) {
            for (;;) {
                const size_t used = text.size() + (line_has_word ? 1 : 0);  // a space before the word
                const size_t room = used >= size_t(kBrfCellsPerLine) ? 0 : size_t(kBrfCellsPerLine) - used;
                if (word.size() <= room) {
                    if (line_has_word) text += ' ';
                    for (uint8_t c : word) text += brailleAsciiOf(c);
                    line_has_word = true;
                    break;
                }
                if (line_has_word) {  // the word goes to the next line
                    out += text;
                    endLine(out, line);
                    text.clear();
                    line_has_word = false;
                    continue;
                }
                // A word longer than a whole line: as much as fits, then the rest.
                for (size_t k = 0; k < room; ++k) text += brailleAsciiOf(word[k]);
                word.erase(word.begin(), word.begin() + long(room));
                out += text;
                endLine(out, line);
                text.clear();
            }
        }
        out += text;
        endLine(out, line);
    }
    if (line != 0) out += '\f';
    return out;
}

}  // namespace tsf
