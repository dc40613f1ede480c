#include "gen/readers/number_field.h"

#include <charconv>
#include <cmath>
#include <cstdlib>
#include <string>

namespace tsf {
namespace {

std::string_view trim(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t')) s.remove_suffix(1);
    return s;
}

bool equalsNoCase(std::string_view a, std::string_view b) {
    if (a.size() != b.size()) return false;
    for (size_t k = 0; k < a.size(); ++k) {
        char c = a[k];
        if (c >= 'A' && c <= 'Z') c = char(c - 'A' + 'a');
        if (c != b[k]) return false;
    }
    return true;
}

bool isNoDataSpelling(std::string_view s) {
    return s.empty() || s == "-" || equalsNoCase(s, "nan") || equalsNoCase(s, "na") || equalsNoCase(s, "n/a");
}

// Number grammar only: from_chars would also accept "inf"/"nan" words, which
// we classify ourselves; this keeps "infinity" and "nan(0x1)" out of kNumber.
NumberField parseNumber(std::string_view s, double& value) {
    if (!s.empty() && s.front() == '+') {
        s.remove_prefix(1);
        if (!s.empty() && (s.front() == '-' || s.front() == '+')) return NumberField::NotNumber;
    }
    if (s.empty()) return NumberField::NotNumber;
    const char* first = s.data();
    const char* last = s.data() + s.size();
    const char* digits = first + (*first == '-' ? 1 : 0);
    if (digits == last) return NumberField::NotNumber;
    if (*digits != '.' && (*digits < '0' || *digits > '9')) {
        // A word: the only valid ones are infinities and NaN spellings.
        std::string_view word(digits, size_t(last - digits));
        if (equalsNoCase(word, "inf") || equalsNoCase(word, "infinity")) return NumberField::Infinite;
        if (equalsNoCase(word, "nan") || (word.size() > 4 && equalsNoCase(word.substr(0, 4), "nan(") &&
                                          word.back() == ')')) {
            value = NAN;
            return NumberField::NoData;
        }
        return NumberField::NotNumber;
    }
    double v = 0.0;
    const auto res = std::from_chars(first, last, v, std::chars_format::general);
    if (res.ptr != last) return NumberField::NotNumber;
    if (res.ec == std::errc::result_out_of_range) {
        // from_chars reports both overflow and underflow; strtod tells them apart.
        const std::string copy(s);
        v = std::strtod(copy.c_str(), nullptr);
        if (!std::isfinite(v)) return NumberField::Infinite;
    } else if (res.ec != std::errc()) {
        return NumberField::NotNumber;
    }
    if (!std::isfinite(v)) return NumberField::Infinite;
    value = v;
    return NumberField::Number;
}

}  // namespace

NumberField parseNumberField(std::string_view text, double& value) {
    const std::string_view s = trim(text);
    if (isNoDataSpelling(s)) {
        value = NAN;
        return NumberField::NoData;
    }
    return parseNumber(s, value);
}

NumberField parseStrictNumber(std::string_view text, double& value) {
    const std::string_view s = trim(text);
    double v = 0.0;
    const NumberField kind = parseNumber(s, v);
    if (kind == NumberField::NoData) return NumberField::NotNumber;
    if (kind == NumberField::Number) value = v;
    return kind;
}

bool parseWholeNumber(std::string_view s, int64_t max_value, int64_t& out) {
    if (s.empty() || s.size() > 18) return false;  // 18 digits always fit in int64
    int64_t v = 0;
    for (char c : s) {
        if (c < '0' || c > '9') return false;
        v = v * 10 + (c - '0');
    }
    if (v > max_value) return false;
    out = v;
    return true;
}

std::string badNumberMessage(NumberField kind, std::string_view text, char delimiter) {
    const std::string shown = quoteForMessage(trim(text));
    if (kind == NumberField::Infinite)
        return "infinite or too large value " + shown + " (largest allowed magnitude is about 1.8e308)";
    std::string msg = "expected a number, found " + shown;
    const std::string_view t = trim(text);
    const size_t comma = t.find(',');
    if (delimiter != ',' && comma != std::string_view::npos && t.find(',', comma + 1) == std::string_view::npos) {
        std::string fixed(t);
        fixed[comma] = '.';
        double v = 0.0;
        if (parseStrictNumber(fixed, v) == NumberField::Number)
            msg += " (decimal comma? write " + fixed + ")";
    }
    return msg;
}

std::string quoteForMessage(std::string_view text, size_t max_chars) {
    std::string out = "\"";
    const size_t n = text.size() < max_chars ? text.size() : max_chars;
    for (size_t k = 0; k < n; ++k) {
        const unsigned char c = static_cast<unsigned char>(text[k]);
        out += (c < 0x20 || c == 0x7f) ? '?' : char(c);
    }
    if (text.size() > max_chars) out += "...";
    out += "\"";
    return out;
}

}  // namespace tsf
