#include "gen/util/text_scanner.h"

#include "gen/util/error.h"

namespace tsf {
namespace {
bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }
bool isLineEnd(char c) { return c == '\n' || c == '\r'; }
bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
}  // namespace

TextScanner::TextScanner(std::string_view text, std::string path, char comment)
    : TextScanner(text, std::move(path), comment, 0, 1, 1) {}

TextScanner::TextScanner(std::string_view text, std::string path, char comment, size_t start, int line, int column)
    : text_(text), path_(std::move(path)), comment_(comment), pos_(start), line_start_(start), line_(line),
      column_(column), token_line_(line) {}

void TextScanner::skipBlanks() {
    while (pos_ < text_.size() && isBlank(text_[pos_])) {
        ++pos_;
        ++column_;
    }
}

void TextScanner::endLine() {
    if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_;
    ++line_;
    column_ = 1;
    line_start_ = pos_;
}

bool TextScanner::nextOnLine(std::string_view& token) {
    skipBlanks();
    if (pos_ >= text_.size() || isLineEnd(text_[pos_])) return false;
    if (atComment()) {
        while (pos_ < text_.size() && !isLineEnd(text_[pos_])) ++pos_;  // columns no longer matter on this line
        return false;
    }
    token_line_ = line_;
    token_column_ = column_;
    const size_t start = pos_;
    while (pos_ < text_.size() && !isBlank(text_[pos_]) && !isLineEnd(text_[pos_]) && !atComment()) {
        ++pos_;
        if (pos_ >= text_.size() || !isContinuationByte(text_[pos_])) ++column_;
    }
    token = text_.substr(start, pos_ - start);
    return true;
}

bool TextScanner::skipLine() {
    while (pos_ < text_.size() && !isLineEnd(text_[pos_])) ++pos_;
    if (pos_ >= text_.size()) return false;
    endLine();
    token_line_ = line_;
    token_column_ = 0;
    return true;
}

bool TextScanner::next(std::string_view& token) {
    for (;;) {
        if (nextOnLine(token)) return true;
        if (pos_ >= text_.size()) return false;
        endLine();  // nextOnLine stopped at a line end
    }
}

void TextScanner::fail(const std::string& what) const { throw InputError(path_, token_line_, token_column_, what); }

void TextScanner::failHere(const std::string& what) const {
    const bool after_final_line_end = line_start_ == text_.size() && line_ > 1;
    throw InputError(path_, after_final_line_end ? line_ - 1 : line_, 0, what);
}

}  // namespace tsf
