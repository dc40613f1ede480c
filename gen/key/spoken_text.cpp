// Text for a screen reader. See spoken_text.h.
#include "gen/key/spoken_text.h"

#include <cctype>
#include <sstream>
#include <vector>

namespace tsf {
namespace {

bool digit(char c) { return std::isdigit(static_cast<unsigned char>(c)) != 0; }

void replaceAll(std::string& s, const std::string& from, const std::string& to) {
    for (size_t at = 0; (at = s.find(from, at)) != std::string::npos; at += to.size()) s.replace(at, from.size(), to);
}

}  // namespace

std::string spokenText(const std::string& text) {
    std::string s = text;
    replaceAll(s, " -> ", " to ");
    // "<digit> x <digit>" -> "<digit> by <digit>"
    for (size_t at = 1; at + 3 < s.size(); ++at)
        if (s.compare(at, 3, " x ") == 0 && digit(s[at - 1]) && digit(s[at + 3])) s.replace(at, 3, " by ");
    replaceAll(s, "mm^3", "cubic mm");
    replaceAll(s, "mm^2", "square mm");
    return s;
}

namespace {

/// Brackets this long or shorter stay on one line: a place "(76.0, 38.5)",
/// a cell "(col 17, row 1)"; longer ones are clauses like any other.
constexpr size_t kWholeBracketChars = 24;

/// Splits after each `sep` ("; " or ", "), keeping the separator's mark on
/// the piece before it: "a; b" -> {"a;", "b"}; never inside a short
/// bracketed group (kWholeBracketChars).
std::vector<std::string> splitAfter(const std::string& text, const std::string& sep) {
    std::vector<bool> whole(text.size(), false);
    std::vector<size_t> open;
    for (size_t k = 0; k < text.size(); ++k) {
        if (text[k] == '(') open.push_back(k);
        else if (text[k] == ')' && !open.empty()) {
            const size_t o = open.back();
            open.pop_back();
            if (k - o + 1 <= kWholeBracketChars)
                for (size_t j = o; j <= k; ++j) whole[j] = true;
        }
    }
    std::vector<std::string> out;
    size_t from = 0;
    for (size_t at = 0; (at = text.find(sep, at)) != std::string::npos;) {
        if (whole[at]) {
            at += sep.size();
            continue;
        }
        out.push_back(text.substr(from, at + sep.size() - 1 - from));
        from = at += sep.size();
    }
    out.push_back(text.substr(from));
    return out;
}

}  // namespace

std::string shortLines(const std::string& text, size_t width, size_t indent) {
    std::string out;
    std::istringstream in(text);
    std::string line;
    bool first = true;
    const std::string pad(indent, ' ');
    while (std::getline(in, line)) {
        if (!first) out += "\n";
        first = false;
        if (line.size() <= width) {
            out += line;
            continue;
        }
        // Clauses (after "; "), and a clause too long alone by its items
        // (after ", "); never inside an item, so a phrase stays whole.
        std::vector<std::string> pieces;
        for (const std::string& clause : splitAfter(line, "; ")) {
            if (clause.size() + indent <= width) pieces.push_back(clause);
            else
                for (const std::string& item : splitAfter(clause, ", ")) pieces.push_back(item);
        }
        std::string current;
        for (const std::string& piece : pieces) {
            if (current.empty()) current = piece;
            else if (current.size() + 1 + piece.size() <= width) current += " " + piece;
            else {
                out += current + "\n";
                current = pad + piece;
            }
        }
        out += current;
    }
    if (!text.empty() && text.back() == '\n') out += "\n";
    return out;
}

}  // namespace tsf
