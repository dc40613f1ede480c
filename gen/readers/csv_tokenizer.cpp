#include "gen/readers/csv_tokenizer.h"

#include <cctype>
#include <string>

#include "gen/util/error.h"
#include "gen/readers/number_field.h"

namespace tsf {
namespace {

constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }

}  // namespace

namespace {

// The first line with any non-blank character (a quoted line break does not end it).
std::string_view firstNonBlankLine(std::string_view text) {
    size_t start = 0;
    bool in_quotes = false;
    bool content = false;
    for (size_t k = 0; k < text.size(); ++k) {
        const char c = text[k];
        if (c == '"') in_quotes = !in_quotes;
        if (!in_quotes && (c == '\n' || c == '\r')) {
            if (content) return text.substr(start, k - start);
            start = k + 1;
            continue;
        }
        if (c != ' ' && c != '\t') content = true;
    }
    return content ? text.substr(start) : std::string_view();
}

// True if every blank-separated token of `line` is a number or a no-data spelling.
bool allTokensNumeric(std::string_view line) {
    size_t k = 0;
    bool any = false;
    while (k < line.size()) {
        while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
        const size_t start = k;
        while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
        if (k == start) break;
        double v = 0.0;
        if (parseNumberField(line.substr(start, k - start), v) == NumberField::NotNumber) return false;
        any = true;
    }
    return any;
}

// True if every blank-separated token of `line` is a number written with a
// decimal comma or without a mark ("1,5", "-2", "3,25e2"), at least one with
// the comma: a whitespace-separated grid from a decimal-comma locale, not a
// comma-separated one ("1,5 2,5 3,5").
bool allTokensDecimalComma(std::string_view line) {
    size_t k = 0;
    bool any_comma = false, any = false;
    while (k < line.size()) {
        while (k < line.size() && (line[k] == ' ' || line[k] == '\t')) ++k;
        const size_t start = k;
        while (k < line.size() && line[k] != ' ' && line[k] != '\t') ++k;
        if (k == start) break;
        std::string token(line.substr(start, k - start));
        const size_t comma = token.find(',');
        if (comma != std::string::npos) {
            // One comma, between two digits.
            if (token.find(',', comma + 1) != std::string::npos || comma == 0 || comma + 1 >= token.size() ||
                !std::isdigit(static_cast<unsigned char>(token[comma - 1])) ||
                !std::isdigit(static_cast<unsigned char>(token[comma + 1])))
                return false;
            token[comma] = '.';
            any_comma = true;
        } else if (token.find('.') != std::string::npos) {
            return false;  // a decimal point beside decimal commas: not this kind of file
        }
        double v = 0.0;
        if (parseNumberField(token, v) != NumberField::Number) return false;
        any = true;
    }
    return any && any_comma;
}

}  // namespace

char detectCsvDelimiter(std::string_view text) {
    if (text.substr(0, kUtf8Bom.size()) == kUtf8Bom) text.remove_prefix(kUtf8Bom.size());
    const std::string_view line = firstNonBlankLine(text);
    bool in_quotes = false;
    bool has_tab = false, has_semicolon = false, has_comma = false, space_inside_field = false;
    for (size_t k = 0; k < line.size(); ++k) {
        const char c = line[k];
        if (c == '"') in_quotes = !in_quotes;
        if (in_quotes) continue;
        if (c == '\t') has_tab = true;
        else if (c == ';') has_semicolon = true;
        else if (c == ',') has_comma = true;
        else if (c == ' ' && k > 0 && k + 1 < line.size() && line[k - 1] != ' ' && line[k - 1] != '\t' &&
                 line[k + 1] != ' ' && line[k + 1] != '\t')
            space_inside_field = true;  // "1 2": a blank between two non-blanks
    }
    if (has_tab) {
        // Numbers separated by a mix of tabs and spaces ("1  2\t3") are a
        // whitespace-separated grid; otherwise spaces belong to the fields
        // ("mean temp\tmax temp").
        const bool blank_runs = space_inside_field || line.find("  ") != std::string_view::npos;
        if (blank_runs && !has_semicolon && !has_comma && allTokensNumeric(line)) return ' ';
        return '\t';
    }
    if (has_semicolon) return ';';
    if (has_comma && space_inside_field && allTokensDecimalComma(line)) return ' ';  // "1,5 2,5 3,5"
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
