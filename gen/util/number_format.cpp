#include "gen/util/number_format.h"

#include <charconv>
#include <cmath>

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

}  // namespace tsf
