#include "gen/model/features/braille.h"

#include <liblouis.h>

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

}  // namespace

std::vector<uint8_t> translateToBraille(const std::string& utf8_text, const std::string& table) {
    static_assert(sizeof(widechar) == 4 || sizeof(widechar) == 2, "liblouis widechar");
    std::vector<widechar> in;
    if (!decodeUtf8(utf8_text, in)) throw InputError("braille: the text is not UTF-8: '" + utf8_text + "'");
    if (in.empty()) return {};
    std::lock_guard<std::mutex> lock(g_louis);
    if (table.empty() || !lou_getTable(table.c_str()))
        throw InputError("--braille-table: liblouis cannot load the table '" + table +
                         "' (a name such as en-us-g1.ctb, en-ueb-g1.ctb or de-g0.utb; the tables are in "
                         "/usr/share/liblouis/tables)");
    // A translation is rarely longer than 4 cells per character (number and capital signs).
    std::vector<widechar> out(in.size() * 4 + 16);
    int inlen = int(in.size()), outlen = int(out.size());
    if (!lou_translateString(table.c_str(), in.data(), &inlen, out.data(), &outlen, nullptr, nullptr, dotsIO) ||
        inlen != int(in.size()))
        throw InputError("braille: liblouis could not translate '" + utf8_text + "' with " + table);
    std::vector<uint8_t> cells;
    cells.reserve(size_t(outlen));
    for (int k = 0; k < outlen; ++k) cells.push_back(uint8_t(out[size_t(k)] & 0xFF));  // LOU_DOTS bit dropped
    return cells;
}

std::string brailleUnicode(const std::vector<uint8_t>& cells) {
    std::string s;
    for (const uint8_t c : cells) appendUtf8(0x2800u + c, s);
    return s;
}

}  // namespace tsf
