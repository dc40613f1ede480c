#include "gen/io/text_scanner.h"

namespace tsf {
namespace {
bool isSpace(char c) { return c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\v' || c == '\f'; }
bool isContinuationByte(char c) { return (static_cast<unsigned char>(c) & 0xC0) == 0x80; }
}  // namespace

TextScanner::TextScanner(std::string_view text, bool hash_comments, size_t start, int line, int column)
    : text_(text), hash_comments_(hash_comments), pos_(start), line_(line), column_(column) {}

void TextScanner::advance() {
    const char c = text_[pos_];
    ++pos_;
    if (c == '\n' || (c == '\r' && (pos_ >= text_.size() || text_[pos_] != '\n'))) {
        ++line_;
        column_ = 1;
    } else if (c != '\r' && pos_ < text_.size() && !isContinuationByte(text_[pos_])) {
        ++column_;
    }
}

bool TextScanner::next(std::string_view& token) {
    for (;;) {
        while (pos_ < text_.size() && isSpace(text_[pos_])) advance();
        if (pos_ >= text_.size()) return false;
        if (hash_comments_ && text_[pos_] == '#') {
            while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') advance();
            continue;
        }
        break;
    }
    token_line_ = line_;
    token_column_ = column_;
    const size_t start = pos_;
    while (pos_ < text_.size() && !isSpace(text_[pos_]) && !(hash_comments_ && text_[pos_] == '#')) advance();
    token = text_.substr(start, pos_ - start);
    return true;
}

}  // namespace tsf
