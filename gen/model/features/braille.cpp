#include "gen/model/features/braille.h"

#include <liblouis.h>

#include <cmath>

#include <mutex>

#include "gen/util/error.h"

namespace tsf {
namespace {

// UTF-8 -> code points; false on a malformed sequence.
bool decodeUtf8(const std::string& s, std::vector<widechar>& out) {
    for (size_t i = 0; i < s.size();) {
        const unsigned char c = static_cast<unsigned char>(s[i]);
        int n = c < 0x80 ? 0 : (c >> 5) == 0x6 ? 1 : (c >> 4) == 0xE ? 2 : (c >> 3) == 0x1E ? 3 : -1;
        if (n < 0 || i + size_t(n) > s.size() - 1) return false;  // the sequence runs past the end
        uint32_t cp = n == 0 ? c : n == 1 ? (c & 0x1F) : n == 2 ? (c & 0x0F) : (c & 0x07);
        for (int k = 1; k <= n; ++k) {
            const unsigned char cc = static_cast<unsigned char>(s[i + size_t(k)]);
            if ((cc >> 6) != 0x2) return false;
            cp = (cp << 6) | (cc & 0x3F);
        }
        out.push_back(widechar(cp));
        i += size_t(n) + 1;
    }
    return true;
}

void appendUtf8(uint32_t cp, std::string& out) {
    if (cp < 0x80) {
        out += char(cp);
    } else if (cp < 0x800) {
        out += char(0xC0 | (cp >> 6));
        out += char(0x80 | (cp & 0x3F));
    } else {
        out += char(0xE0 | (cp >> 12));
        out += char(0x80 | ((cp >> 6) & 0x3F));
        out += char(0x80 | (cp & 0x3F));
    }
}

// liblouis keeps loaded tables in global state: one translation at a time.
std::mutex g_louis;

void loadTable(const std::string& table) {
    if (table.empty() || !lou_getTable(table.c_str()))
        throw InputError("--braille-table: liblouis cannot load the table '" + table +
                         "' (a name such as en-ueb-g1.ctb, en-ueb-g2.ctb, en-us-g1.ctb or de-g0.utb; the tables are in "
                         "/usr/share/liblouis/tables)");
}

}  // namespace

std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table,
                                        std::vector<int>& source_of_cell, std::vector<uint32_t>& code_points) {
    static_assert(sizeof(widechar) == 4 || sizeof(widechar) == 2, "liblouis widechar");
    std::vector<widechar> in;
    if (!decodeUtf8(utf8_text, in)) throw InputError("braille: the text is not UTF-8: '" + utf8_text + "'");
    code_points.assign(in.begin(), in.end());
    source_of_cell.clear();
    if (in.empty()) return {};
    // A no-break space is a space to liblouis (not every table defines
    // U+00A0); the caller keeps its words together by its position.
    for (widechar& c : in)
        if (c == 0xA0) c = ' ';
    std::lock_guard<std::mutex> lock(g_louis);
    loadTable(table);
    // A translation is rarely longer than 4 cells per character (number and capital signs).
    std::vector<widechar> out(in.size() * 4 + 16);
    std::vector<int> input_pos(out.size());
    int inlen = int(in.size()), outlen = int(out.size());
    if (!lou_translate(table.c_str(), in.data(), &inlen, out.data(), &outlen, nullptr, nullptr, nullptr,
                       input_pos.data(), nullptr, dotsIO) ||
        inlen != int(in.size()))
        throw InputError("braille: liblouis could not translate '" + utf8_text + "' with " + table);
    std::vector<uint8_t> cells;
    cells.reserve(size_t(outlen));
    for (int k = 0; k < outlen; ++k) {
        cells.push_back(uint8_t(out[size_t(k)] & 0xFF));  // LOU_DOTS bit dropped
        source_of_cell.push_back(input_pos[size_t(k)]);
    }
    return cells;
}

std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table) {
    std::vector<int> source;
    std::vector<uint32_t> code_points;
    return translateToBraille(utf8_text, table, source, code_points);
}

std::string backTranslateBraille(const std::vector<uint8_t>& cells, const std::string& table) {
    if (cells.empty()) return "";
    std::vector<widechar> in;
    for (const uint8_t c : cells) in.push_back(widechar(0x8000 | c));  // LOU_DOTS: a cell, not a character
    std::lock_guard<std::mutex> lock(g_louis);
    loadTable(table);
    std::vector<widechar> out(in.size() * 4 + 16);
    int inlen = int(in.size()), outlen = int(out.size());
    if (!lou_backTranslateString(table.c_str(), in.data(), &inlen, out.data(), &outlen, nullptr, nullptr, dotsIO))
        throw InputError("braille: liblouis could not back-translate " + std::to_string(cells.size()) + " cells with " + table);
    std::string text;
    for (int k = 0; k < outlen; ++k) appendUtf8(uint32_t(out[size_t(k)]), text);
    return text;
}

std::string brailleCodeName(const std::string& table) {
    struct Known {
        const char* table;
        const char* name;
    };
    static constexpr Known kKnown[] = {
        {"en-ueb-g1.ctb", "Unified English Braille, uncontracted"},
        {"en-ueb-g2.ctb", "Unified English Braille, contracted"},
        {"en-us-g1.ctb", "English Braille American Edition, uncontracted"},
        {"en-us-g2.ctb", "English Braille American Edition, contracted"},
        {"en-gb-g1.utb", "British English braille, uncontracted"},
        {"en-GB-g2.ctb", "British English braille, contracted"},
    };
    for (const Known& k : kKnown)
        if (table == k.table) return k.name;
    return "the liblouis table " + table;
}

std::string brailleUnicode(const std::vector<uint8_t>& cells) {
    std::string s;
    for (const uint8_t c : cells) appendUtf8(0x2800u + c, s);
    return s;
}

double printedDotHeightMm(double dot_height_mm, double layer_mm) {
    if (layer_mm <= 0) return dot_height_mm;
    // Half a layer up rounds up: the slicer samples each layer at its middle.
    return std::floor(dot_height_mm / layer_mm + 0.5 + 1e-9) * layer_mm;
}

}  // namespace tsf
