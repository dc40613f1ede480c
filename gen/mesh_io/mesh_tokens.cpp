#include "gen/mesh_io/text_scanner.h"

#include <charconv>
#include <cmath>
#include <system_error>

#include "gen/error.h"
#include "gen/mesh_io/file_bytes.h"

namespace tsf::mesh_io {
namespace {

bool isBlank(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v'; }

bool isTokenEnd(char c) { return isBlank(c) || c == '\n'; }

}  // namespace

bool equalsIgnoringCase(std::string_view token, std::string_view keyword) {
    if (token.size() != keyword.size()) return false;
    for (size_t i = 0; i < token.size(); ++i) {
        char a = token[i], b = keyword[i];
        if (a >= 'A' && a <= 'Z') a = static_cast<char>(a - 'A' + 'a');
        if (b >= 'A' && b <= 'Z') b = static_cast<char>(b - 'A' + 'a');
        if (a != b) return false;
    }
    return true;
}

TextScanner::TextScanner(std::string_view text, std::string path, char comment)
    : text_(text), path_(std::move(path)), comment_(comment) {}

bool TextScanner::tokenOnLine(std::string_view& token) {
    while (pos_ < text_.size() && isBlank(text_[pos_])) ++pos_;
    if (pos_ >= text_.size() || text_[pos_] == '\n') return false;
    if (comment_ != '\0' && text_[pos_] == comment_) {
        while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
        return false;
    }
    const size_t start = pos_;
    while (pos_ < text_.size() && !isTokenEnd(text_[pos_]) && !(comment_ != '\0' && text_[pos_] == comment_)) ++pos_;
    token = text_.substr(start, pos_ - start);
    token_line_ = line_;
    token_column_ = static_cast<int>(start - line_start_) + 1;
    return true;
}

bool TextScanner::nextLine() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if (pos_ >= text_.size()) return false;
    ++pos_;
    line_start_ = pos_;
    ++line_;
    token_line_ = line_;
    token_column_ = 0;
    return true;
}

bool TextScanner::token(std::string_view& token) {
    for (;;) {
        if (tokenOnLine(token)) return true;
        if (!nextLine()) return false;
    }
}

void TextScanner::fail(const std::string& what) const { throw InputError(path_, token_line_, token_column_, what); }

void TextScanner::failHere(const std::string& what) const {
    // At the end of a file that ends with a newline, the "current line" is
    // the empty one after it; name the last line a person sees instead.
    const bool after_final_newline = line_start_ == text_.size() && line_ > 1;
    throw InputError(path_, after_final_newline ? line_ - 1 : line_, 0, what);
}

double TextScanner::anyNumber(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty()) fail(std::string(what) + " expected, found " + quoteForMessage(token));
    if (result.ec == std::errc::result_out_of_range) {
        fail(std::string(what) + " expected, found " + quoteForMessage(token) + ", which is out of the range of a double");
    }
    if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        fail(std::string(what) + " expected, found " + quoteForMessage(token));
    }
    return value;
}

double TextScanner::finiteNumber(std::string_view token, const char* what) const {
    const double value = anyNumber(token, what);
    if (!std::isfinite(value)) fail(std::string(what) + " expected, found " + quoteForMessage(token) + " (not a finite number)");
    return value;
}

int64_t TextScanner::integer(std::string_view token, const char* what) const {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    int64_t value = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        fail(std::string(what) + " expected, found " + quoteForMessage(token));
    }
    return value;
}

}  // namespace tsf::mesh_io
