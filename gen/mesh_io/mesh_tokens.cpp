#include "gen/mesh_io/mesh_tokens.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace tsf::mesh_io {

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

std::string quoteForMessage(std::string_view text, size_t max_chars) {
    std::string out = "'";
    for (size_t i = 0; i < text.size() && i < max_chars; ++i) {
        const auto byte = static_cast<unsigned char>(text[i]);
        out += (byte >= 0x20 && byte < 0x7F) ? static_cast<char>(byte) : '?';
    }
    if (text.size() > max_chars) out += "...";
    return out + "'";
}

double anyNumber(const TextScanner& scanner, std::string_view token, const char* what) {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    double value = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty()) scanner.fail(std::string(what) + " expected, found " + quoteForMessage(token));
    if (result.ec == std::errc::result_out_of_range) {
        scanner.fail(std::string(what) + " expected, found " + quoteForMessage(token) +
                     ", which is out of the range of a double");
    }
    if (result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        scanner.fail(std::string(what) + " expected, found " + quoteForMessage(token));
    }
    return value;
}

double finiteNumber(const TextScanner& scanner, std::string_view token, const char* what) {
    const double value = anyNumber(scanner, token, what);
    if (!std::isfinite(value))
        scanner.fail(std::string(what) + " expected, found " + quoteForMessage(token) + " (not a finite number)");
    return value;
}

int64_t integer(const TextScanner& scanner, std::string_view token, const char* what) {
    std::string_view digits = token;
    if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
    int64_t value = 0;
    const auto result = std::from_chars(digits.data(), digits.data() + digits.size(), value);
    if (digits.empty() || result.ec != std::errc() || result.ptr != digits.data() + digits.size()) {
        scanner.fail(std::string(what) + " expected, found " + quoteForMessage(token));
    }
    return value;
}

}  // namespace tsf::mesh_io
