#include "runners/openscad/openscad_messages.h"

#include <sstream>

namespace tsf {
namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }

// "... in file NAME, line N" (NAME may be quoted), at the end or followed by ":".
void findLocation(ScadMessage& m) {
    const std::string key = " in file ";
    const size_t at = m.text.rfind(key);
    if (at == std::string::npos) return;
    const size_t comma = m.text.find(", line ", at + key.size());
    if (comma == std::string::npos) return;
    std::string file = m.text.substr(at + key.size(), comma - at - key.size());
    if (file.size() >= 2 && file.front() == '"' && file.back() == '"') file = file.substr(1, file.size() - 2);
    size_t pos = comma + 7;
    int line = 0;
    bool digits = false;
    while (pos < m.text.size() && m.text[pos] >= '0' && m.text[pos] <= '9') {
        line = line * 10 + (m.text[pos++] - '0');
        digits = true;
        if (line > 100000000) return;
    }
    if (!digits) return;
    m.file = file;
    m.line = line;
}

// Assertion '(cond)' failed: "message" in file ...
void findAssert(ScadMessage& m) {
    if (!startsWith(m.text, "Assertion '")) return;
    const size_t open = m.text.find("failed: \"");
    if (open == std::string::npos) {
        m.assert_message = "assertion failed";
        return;
    }
    const size_t begin = open + 9;
    size_t end = m.text.rfind("\" in file ");
    if (end == std::string::npos || end < begin) end = m.text.rfind('"');
    m.assert_message = end != std::string::npos && end >= begin ? m.text.substr(begin, end - begin) : m.text.substr(begin);
}

}  // namespace

std::vector<ScadMessage> parseOpenScadOutput(const std::string& output) {
    static const struct {
        const char* prefix;
        ScadMessage::Kind kind;
    } kPrefixes[] = {{"ERROR: ", ScadMessage::Kind::Error},     {"WARNING: ", ScadMessage::Kind::Warning},
                     {"TRACE: ", ScadMessage::Kind::Trace},     {"ECHO: ", ScadMessage::Kind::Echo},
                     {"DEPRECATED: ", ScadMessage::Kind::Deprecated}};
    std::vector<ScadMessage> messages;
    std::istringstream in(output);
    std::string line;
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        ScadMessage m;
        bool found = false;
        for (const auto& p : kPrefixes) {
            if (startsWith(line, p.prefix)) {
                m.kind = p.kind;
                m.text = line.substr(std::string(p.prefix).size());
                found = true;
                break;
            }
        }
        if (!found && (startsWith(line, "Can't ") || startsWith(line, "Either add a valid suffix"))) {
            m.kind = ScadMessage::Kind::Error;
            m.text = line;
            found = true;
        }
        if (!found) continue;
        if (m.kind != ScadMessage::Kind::Echo) findLocation(m);
        if (m.kind == ScadMessage::Kind::Error) findAssert(m);
        messages.push_back(std::move(m));
    }
    return messages;
}

const char* toString(ScadMessage::Kind kind) {
    switch (kind) {
        case ScadMessage::Kind::Warning: return "WARNING";
        case ScadMessage::Kind::Trace: return "TRACE";
        case ScadMessage::Kind::Echo: return "ECHO";
        case ScadMessage::Kind::Deprecated: return "DEPRECATED";
        default: return "ERROR";
    }
}

std::string formatScadMessage(const ScadMessage& m) {
    if (startsWith(m.text, "Can't ") || startsWith(m.text, "Either add")) return m.text;
    return std::string(toString(m.kind)) + ": " + m.text;
}

}  // namespace tsf
