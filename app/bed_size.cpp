#include "app/bed_size.h"

#include <cmath>
#include <cstdlib>

#include "gen/util/error.h"

namespace tsf::cli {

BedSize parseBedSize(const std::string& text, const std::string& option, bool need_height) {
    double v[3] = {0, 0, 0};
    int n = 0;
    const char* p = text.c_str();
    bool ok = !text.empty();
    while (ok && *p) {
        char* end = nullptr;
        const double x = std::strtod(p, &end);
        ok = end != p && std::isfinite(x) && x > 0 && n < 3;
        if (!ok) break;
        v[n++] = x;
        p = end;
        if (*p == 'x' || *p == 'X') {
            ++p;
            ok = *p != '\0';
        } else {
            ok = *p == '\0';
        }
    }
    ok = ok && (need_height ? n == 3 : n >= 2);
    if (!ok)
        throw InputError(option + ": expected " + (need_height ? "WIDTHxDEPTHxHEIGHT in mm, e.g. 220x220x250"
                                                               : "WIDTHxDEPTH in mm, e.g. 220x220") +
                         ", got '" + text + "'");
    return {v[0], v[1], v[2]};
}

}  // namespace tsf::cli
