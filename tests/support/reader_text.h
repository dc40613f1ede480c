// What the reader's part of a model key (gen/key/model_key.h) must never
// hold: a command-line option, e-notation, digits grouped by spaces, an
// arrow. Part of the shared test support (tests/support/).
#pragma once

#include <regex>
#include <string>
#include <vector>

namespace tsf::test {

/// The reader's part of a key file's text: everything before the
/// paragraph "How this model was made" (the whole text when it has none).
inline std::string readerPart(const std::string& key_text) {
    const size_t at = key_text.find("\nHow this model was made\n");
    return at == std::string::npos ? key_text : key_text.substr(0, at);
}

/// Each thing a screen reader or braille would read wrongly, quoted with
/// what it is; empty when the text reads well.
inline std::vector<std::string> readerTextProblems(const std::string& text) {
    struct Rule {
        const char* what;
        std::regex pattern;
    };
    static const std::vector<Rule> rules = {
        {"a command-line option", std::regex(R"((^|[\s("'])--?[A-Za-z][A-Za-z-]*)")},
        {"e-notation", std::regex(R"(\d[eE][+-]?\d)")},
        {"digits grouped by a space", std::regex(R"(\d \d{3}(\D|$))")},
        {"an arrow", std::regex(R"(->)")},
    };
    std::vector<std::string> problems;
    for (const Rule& r : rules)
        for (auto it = std::sregex_iterator(text.begin(), text.end(), r.pattern); it != std::sregex_iterator(); ++it) {
            const size_t at = size_t(it->position());
            const size_t from = at < 30 ? 0 : at - 30;
            problems.push_back(std::string(r.what) + ": '" + it->str() + "' in '..." + text.substr(from, 80) + "...'");
        }
    return problems;
}

}  // namespace tsf::test
