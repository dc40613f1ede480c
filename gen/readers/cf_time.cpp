// CF time coordinates as dates. See cf_time.h.
#include "gen/readers/cf_time.h"

#include <cmath>
#include <cstdint>
#include <cstdio>

namespace tsf {
namespace {

/// Reads up to `most` digits at `at` into n; false when there are none.
bool digits(const std::string& t, size_t& at, size_t most, int64_t& n) {
    size_t k = 0;
    n = 0;
    while (at < t.size() && k < most && t[at] >= '0' && t[at] <= '9') n = n * 10 + (t[at++] - '0'), ++k;
    return k > 0;
}

/// "1850-01-01", "2000-1-1 06:00", "1970-01-01T00:00:00.5", "-0100-03-01"
/// (a year of up to six digits, optionally signed): false for anything else
/// or a month, day or time out of range.
bool parseReference(const std::string& t, int64_t& y, int64_t& mo, int64_t& d, int64_t& hh, int64_t& mi, double& ss) {
    size_t at = 0;
    const bool negative = at < t.size() && t[at] == '-';
    if (at < t.size() && (t[at] == '-' || t[at] == '+')) ++at;
    if (!digits(t, at, 6, y)) return false;
    if (negative) y = -y;
    if (at >= t.size() || t[at++] != '-' || !digits(t, at, 2, mo)) return false;
    if (at >= t.size() || t[at++] != '-' || !digits(t, at, 2, d)) return false;
    hh = mi = 0;
    ss = 0;
    if (at < t.size() && (t[at] == ' ' || t[at] == 'T')) {
        ++at;
        if (!digits(t, at, 2, hh) || at >= t.size() || t[at++] != ':' || !digits(t, at, 2, mi)) return false;
        if (at < t.size() && t[at] == ':') {
            ++at;
            int64_t whole = 0;
            if (!digits(t, at, 2, whole)) return false;
            ss = double(whole);
            if (at < t.size() && t[at] == '.') {
                ++at;
                double scale = 0.1;
                while (at < t.size() && t[at] >= '0' && t[at] <= '9' && scale > 1e-9) ss += (t[at++] - '0') * scale, scale /= 10;
            }
        }
    }
    return mo >= 1 && mo <= 12 && d >= 1 && d <= 31 && hh < 24 && mi < 60 && ss < 61;
}

}  // namespace

std::string cfDate(const std::string& units, const std::string& calendar, double value) {
    const std::string cal = calendar.empty() ? "standard" : calendar;
    if (cal != "standard" && cal != "gregorian" && cal != "proleptic_gregorian") return "";
    const size_t since = units.find(" since ");
    if (since == std::string::npos) return "";
    const std::string unit = units.substr(0, since);
    double seconds = 0;
    if (unit == "days" || unit == "day" || unit == "d") seconds = value * 86400;
    else if (unit == "hours" || unit == "hour" || unit == "h") seconds = value * 3600;
    else if (unit == "minutes" || unit == "minute") seconds = value * 60;
    else if (unit == "seconds" || unit == "second" || unit == "s") seconds = value;
    else return "";
    int64_t y = 0, mo = 0, d = 0, hh = 0, mi = 0;
    double ss = 0;
    if (!parseReference(units.substr(since + 7), y, mo, d, hh, mi, ss)) return "";
    // Days from the civil date (proleptic Gregorian; H. Hinnant's algorithm).
    auto daysFromCivil = [](int64_t yy, int64_t mm, int64_t dd) {
        yy -= mm <= 2;
        const int64_t era = (yy >= 0 ? yy : yy - 399) / 400;
        const int64_t yoe = yy - era * 400;
        const int64_t doy = (153 * (mm + (mm > 2 ? -3 : 9)) + 2) / 5 + dd - 1;
        const int64_t doe = yoe * 365 + yoe / 4 - yoe / 100 + doy;
        return era * 146097 + doe - 719468;
    };
    const double total = double(daysFromCivil(y, mo, d)) * 86400 + hh * 3600 + mi * 60 + ss + seconds;
    if (!std::isfinite(total) || std::abs(total) > 1e14) return "";
    int64_t days = int64_t(std::floor(total / 86400));
    const double rest = total - double(days) * 86400;
    // Civil date from days.
    days += 719468;
    const int64_t era = (days >= 0 ? days : days - 146096) / 146097;
    const int64_t doe = days - era * 146097;
    const int64_t yoe = (doe - doe / 1460 + doe / 36524 - doe / 146096) / 365;
    const int64_t doy = doe - (365 * yoe + yoe / 4 - yoe / 100);
    const int64_t mp = (5 * doy + 2) / 153;
    const int64_t dd = doy - (153 * mp + 2) / 5 + 1;
    const int64_t mm = mp < 10 ? mp + 3 : mp - 9;
    const int64_t yy = yoe + era * 400 + (mm <= 2);
    char buf[96];  // room for any int64 fields, whatever the date
    if (rest < 1) std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lld", (long long)yy, (long long)mm, (long long)dd);
    else
        std::snprintf(buf, sizeof buf, "%04lld-%02lld-%02lld %02d:%02d", (long long)yy, (long long)mm, (long long)dd,
                      int(rest / 3600), int(std::fmod(rest, 3600) / 60));
    return buf;
}

std::string stepLabel(const std::string& description) {
    const size_t open = description.rfind('('), close = description.rfind(')');
    if (open != std::string::npos && close != std::string::npos && close > open + 1 &&
        description[open + 1] >= '0' && description[open + 1] <= '9')
        return description.substr(open + 1, close - open - 1);
    return description;
}

}  // namespace tsf
