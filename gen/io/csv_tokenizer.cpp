#include "gen/io/csv_tokenizer.h"

#include "gen/error.h"

namespace tsf {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

char detectCsvDelimiter(std::string_view text) {
    if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
    bool in_quotes = false;
    bool seen_content = false;
    bool has_tab = false, has_semicolon = false, has_comma = false;
    for (char c : text) {
        if (c == '"') in_quotes = !in_quotes;
        if (in_quotes) {
            seen_content = true;
            continue;
        }
        if (c == '\n' || c == '\r') {
            if (seen_content) break;  // end of the first non-blank line
            has_tab = false;          // a blank line made only of tabs says nothing
            continue;
        }
        if (c == '\t') has_tab = true;
        else if (c == ';') { has_semicolon = true; seen_content = true; }
        else if (c == ',') { has_comma = true; seen_content = true; }
        else if (c != ' ') seen_content = true;
    }
    if (has_tab && seen_content) return '\t';
    if (has_semicolon) return ';';
    if (has_comma) return ',';
    return ' ';
}

CsvTokenizer::CsvTokenizer(std::string_view text, char delimiter, std::string path)
    : text_(text), delimiter_(delimiter), path_(std::move(path)) {
    if (text_.substr(0, kUtf8Bom.size()) == kUtf8Bom) pos_ = kUtf8Bom.size();
}

bool CsvTokenizer::atLineBreak() const { return !atEnd() && (text_[pos_] == '\n' || text_[pos_] == '\r'); }

void CsvTokenizer::consumeLineBreak() {
    if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
    column_ = 1;
}

void CsvTokenizer::advance() {
    ++pos_;
    if (pos_ < text_.size() && !isContinuationByte(text_[pos_])) ++column_;
}

void CsvTokenizer::skipBlanks() {
    while (!atEnd()) {
        const char c = text_[pos_];
        if (c == ' ' || (c == '\t' && delimiter_ != '\t')) advance();
        else break;
    }
}

CsvField CsvTokenizer::readField() {
    skipBlanks();
    CsvField field;
    field.line = line_;
    field.column = column_;
    if (!atEnd() && text_[pos_] == '"') {
        field.quoted = true;
        advance();
        for (;;) {
            if (atEnd())
                throw InputError(path_, field.line, field.column, "quote opened here is never closed");
            const char c = text_[pos_];
            if (c == '"') {
                if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '"') {
                    field.text += '"';
                    advance();
                    advance();
                    continue;
                }
                advance();
                break;
            }
            if (c == '\n' || c == '\r') {
                field.text += '\n';
                consumeLineBreak();
                continue;
            }
            field.text += c;
            advance();
        }
        skipBlanks();
        if (!atEnd() && !atLineBreak() && text_[pos_] != delimiter_ &&
            !(delimiter_ == ' ' && text_[pos_] == '\t'))
            throw InputError(path_, line_, column_,
                             "unexpected text after the closing quote of the field that starts at column " +
                                 std::to_string(field.column));
        return field;
    }
    const size_t start = pos_;
    while (!atEnd() && !atLineBreak()) {
        const char c = text_[pos_];
        if (c == delimiter_ || (delimiter_ == ' ' && c == '\t')) break;
        advance();
    }
    size_t end = pos_;
    while (end > start && (text_[end - 1] == ' ' || (text_[end - 1] == '\t' && delimiter_ != '\t'))) --end;
    field.text.assign(text_.substr(start, end - start));
    return field;
}

bool CsvTokenizer::next(std::vector<CsvField>& fields) {
    fields.clear();
    if (atEnd()) return false;
    record_line_ = line_;
    if (delimiter_ == ' ') {
        for (;;) {
            skipBlanks();
            if (atEnd()) return true;
            if (atLineBreak()) {
                consumeLineBreak();
                return true;
            }
            fields.push_back(readField());
        }
    }
    for (;;) {
        fields.push_back(readField());
        if (atEnd()) break;
        if (atLineBreak()) {
            consumeLineBreak();
            break;
        }
        advance();  // the delimiter
    }
    if (fields.size() == 1 && !fields[0].quoted && fields[0].text.empty()) fields.clear();  // blank line
    return true;
}

}  // namespace tsf
