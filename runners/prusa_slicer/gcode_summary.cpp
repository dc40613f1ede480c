#include "runners/prusa_slicer/gcode_summary.h"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace tsf {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

bool startsWith(const std::string& s, const char* prefix) { return s.rfind(prefix, 0) == 0; }

// The number after "<key> = " on a configuration or estimate line; NaN when
// the line is not that key. A list value ("0.4,0.4") gives its first entry.
double valueAfter(const std::string& line, const std::string& key) {
    if (!startsWith(line, key.c_str())) return kNaN;
    const char* p = line.c_str() + key.size();
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    return end == p ? kNaN : v;
}

}  // namespace

GcodeSummary::GcodeSummary()
    : max_z_mm(kNaN), filament_mm(kNaN), filament_cm3(kNaN), filament_g(kNaN), print_time_s(kNaN),
      layer_height_mm(kNaN), first_layer_height_mm(kNaN), nozzle_mm(kNaN) {}

double parseSlicerDuration(const std::string& text) {
    double total = 0;
    bool any = false;
    const char* p = text.c_str();
    while (*p) {
        while (*p == ' ') ++p;
        if (!*p) break;
        char* end = nullptr;
        const long n = std::strtol(p, &end, 10);
        if (end == p || n < 0) return kNaN;
        switch (*end) {
            case 'd': total += n * 86400.0; break;
            case 'h': total += n * 3600.0; break;
            case 'm': total += n * 60.0; break;
            case 's': total += n; break;
            default: return kNaN;
        }
        any = true;
        p = end + 1;
    }
    return any ? total : kNaN;
}

std::string formatDuration(double seconds) {
    if (!std::isfinite(seconds)) return "unknown";
    const long s = std::lround(seconds);
    char buf[64];
    if (s >= 3600) {
        const long minutes = (s + 30) / 60;
        std::snprintf(buf, sizeof buf, "%ld h %02ld min", minutes / 60, minutes % 60);
    } else {
        std::snprintf(buf, sizeof buf, "%ld min %02ld s", s / 60, s % 60);
    }
    return buf;
}

GcodeSummary summarizeGcode(std::istream& in) {
    GcodeSummary g;
    std::string line;
    auto take = [&line](const char* key, double& into) {
        const double v = valueAfter(line, key);
        if (!std::isnan(v)) into = v;
    };
    while (std::getline(in, line)) {
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.empty() || line[0] != ';') continue;
        if (line == ";LAYER_CHANGE") {
            ++g.layers;
        } else if (startsWith(line, ";Z:")) {
            const double z = valueAfter(line, ";Z:");
            if (!std::isnan(z) && !(z <= g.max_z_mm)) g.max_z_mm = z;
        } else if (startsWith(line, ";TYPE:Support material")) {
            g.has_support = true;
        } else if (startsWith(line, "; estimated printing time (normal mode) = ")) {
            g.print_time_s = parseSlicerDuration(line.substr(std::string("; estimated printing time (normal mode) = ").size()));
        } else {
            take("; filament used [mm] = ", g.filament_mm);
            take("; filament used [cm3] = ", g.filament_cm3);
            take("; total filament used [g] = ", g.filament_g);
            take("; layer_height = ", g.layer_height_mm);
            take("; first_layer_height = ", g.first_layer_height_mm);
            take("; nozzle_diameter = ", g.nozzle_mm);
        }
    }
    return g;
}

}  // namespace tsf
