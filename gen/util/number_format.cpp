#include "gen/util/number_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <string>

namespace tsf {
namespace {

// Room for any double in any of the formats below (fixed with 17 decimals of
// 1e308 needs 327 characters).
constexpr size_t kBufferChars = 400;

std::string special(double v) { return std::isnan(v) ? "nan" : v < 0 ? "-inf" : "inf"; }

}  // namespace

std::string formatSignificant(double v, int digits) {
    if (!std::isfinite(v)) return special(v);
    char buf[kBufferChars];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, digits < 1 ? 1 : digits);
    return std::string(buf, r.ptr);
}

std::string formatFixed(double v, int decimals) {
    if (!std::isfinite(v)) return special(v);
    char buf[kBufferChars];
    const auto r = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, decimals < 0 ? 0 : decimals);
    return std::string(buf, r.ptr);
}

std::string formatShortest(double v) {
    if (!std::isfinite(v)) return special(v);
    char buf[kBufferChars];
    const auto r = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, r.ptr);
}

std::string formatForReader(double v, int digits) {
    if (!std::isfinite(v)) return special(v);
    if (digits < 1) digits = 1;
    if (v == 0) return "0";
    const double a = std::fabs(v);
    int exponent = int(std::floor(std::log10(a)));
    if (a >= 1e15 || a < 1e-6) {
        // Mantissa and power in words: the mantissa rounded may reach 10.
        double mantissa = v / std::pow(10.0, exponent);
        if (std::fabs(std::stod(formatSignificant(mantissa, digits))) >= 10) mantissa /= 10, ++exponent;
        return formatSignificant(mantissa, digits) + " times ten to the power of " +
               (exponent < 0 ? "minus " + std::to_string(-exponent) : std::to_string(exponent));
    }
    std::string text;
    const int decimals = digits - 1 - exponent;
    if (decimals > 0) {
        text = formatFixed(v, decimals);
        while (text.back() == '0') text.pop_back();
        if (text.back() == '.') text.pop_back();
    } else {
        const double unit = std::pow(10.0, -decimals);
        text = formatFixed(std::round(v / unit) * unit, 0);
    }
    if (text == "-0") text = "0";
    // Group the whole part in threes from 10,000 up.
    const size_t start = text[0] == '-' ? 1 : 0;
    const size_t point = std::min(text.find('.'), text.size());
    if (point - start > 4)
        for (size_t at = point; at > start + 3; at -= 3) text.insert(at - 3, ",");
    return text;
}

}  // namespace tsf
