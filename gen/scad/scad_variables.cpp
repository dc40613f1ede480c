#include "gen/scad/scad_variables.h"

#include <algorithm>
#include <cctype>

namespace tsf {
namespace {

bool identStart(char ch) { return std::isalpha(static_cast<unsigned char>(ch)) || ch == '_' || ch == '$'; }
bool identChar(char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_' || ch == '$'; }

// Skips a comment or string starting at i; returns true if it did.
bool skipCommentOrString(const std::string& s, size_t& i) {
    if (s.compare(i, 2, "//") == 0) {
        const size_t end = s.find('\n', i);
        i = end == std::string::npos ? s.size() : end;
        return true;
    }
    if (s.compare(i, 2, "/*") == 0) {
        const size_t end = s.find("*/", i + 2);
        i = end == std::string::npos ? s.size() : end + 2;
        return true;
    }
    if (s[i] == '"') {
        for (++i; i < s.size() && s[i] != '"'; ++i)
            if (s[i] == '\\') ++i;
        i = std::min(i + 1, s.size());
        return true;
    }
    return false;
}

}  // namespace

std::vector<std::string> scadTopLevelVariables(const std::string& s) {
    std::vector<std::string> names;
    int depth = 0;
    bool statement_start = true;
    size_t i = 0;
    while (i < s.size()) {
        if (skipCommentOrString(s, i)) continue;
        const char ch = s[i];
        if (std::isspace(static_cast<unsigned char>(ch))) { ++i; continue; }
        if (depth == 0 && statement_start && identStart(ch)) {
            const size_t begin = i;
            while (i < s.size() && identChar(s[i])) ++i;
            const std::string name = s.substr(begin, i - begin);
            size_t j = i;
            while (j < s.size() && (s[j] == ' ' || s[j] == '\t')) ++j;
            if ((name == "use" || name == "include") && j < s.size() && s[j] == '<') {
                // use <file> / include <file> end without a semicolon.
                const size_t close = s.find('>', j);
                i = close == std::string::npos ? s.size() : close + 1;
                continue;  // still at a statement start
            }
            if (j < s.size() && s[j] == '=' && (j + 1 >= s.size() || s[j + 1] != '=') &&
                std::find(names.begin(), names.end(), name) == names.end())
                names.push_back(name);
            statement_start = false;
            continue;
        }
        if (ch == '(' || ch == '[' || ch == '{') ++depth;
        else if (ch == ')' || ch == ']' || ch == '}') depth = std::max(0, depth - 1);
        statement_start = depth == 0 && (ch == ';' || ch == '}');
        ++i;
    }
    return names;
}

bool scadHasInclude(const std::string& s) {
    size_t i = 0;
    while (i < s.size()) {
        if (skipCommentOrString(s, i)) continue;
        if (s.compare(i, 7, "include") == 0 && (i == 0 || !identChar(s[i - 1]))) {
            size_t j = i + 7;
            while (j < s.size() && std::isspace(static_cast<unsigned char>(s[j]))) ++j;
            if (j < s.size() && s[j] == '<') return true;
        }
        ++i;
    }
    return false;
}

}  // namespace tsf
