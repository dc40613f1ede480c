#include "haptics/replay_device.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>

#include "gen/util/error.h"
#include "gen/util/file_bytes.h"

namespace tsf::haptics {
namespace {

/// Positions further than this from the workspace centre cannot come from a
/// desktop device; such a file is not a recording in metres.
constexpr double kMaxReplayCoordinate_m = 1.0;

struct Field {
    std::string text;
    int column = 1;  ///< 1-based character column where the field starts
};

std::vector<Field> splitRow(const std::string& line) {
    std::vector<Field> out;
    size_t start = 0;
    while (true) {
        const size_t comma = line.find(',', start);
        const size_t end = comma == std::string::npos ? line.size() : comma;
        size_t a = start, b = end;
        while (a < b && (line[a] == ' ' || line[a] == '\t')) ++a;
        while (b > a && (line[b - 1] == ' ' || line[b - 1] == '\t')) --b;
        out.push_back({line.substr(a, b - a), int(a) + 1});
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return out;
}

double parseNumber(const Field& f, const std::string& source, int line, const char* what) {
    double v = 0.0;
    const char* first = f.text.data();
    const char* last = first + f.text.size();
    if (!f.text.empty() && *first == '+') ++first;
    const auto r = std::from_chars(first, last, v);
    if (f.text.empty() || r.ec != std::errc() || r.ptr != last || !std::isfinite(v))
        throw InputError(source, line, f.column,
                         std::string("expected a finite number for ") + what + ", found '" + f.text + "'");
    return v;
}

}  // namespace

std::vector<ReplaySample> parseReplayCsv(const std::string& text, const std::string& source) {
    std::istringstream in(text);
    std::string line;
    int line_no = 0;
    int idx_t = -1, idx_x = -1, idx_y = -1, idx_z = -1, idx_b = -1;
    bool have_header = false;
    std::vector<ReplaySample> out;
    while (std::getline(in, line)) {
        ++line_no;
        if (!line.empty() && line.back() == '\r') line.pop_back();
        if (line.find_first_not_of(" \t") == std::string::npos || line[line.find_first_not_of(" \t")] == '#') continue;
        const std::vector<Field> fields = splitRow(line);
        if (!have_header) {
            for (size_t k = 0; k < fields.size(); ++k) {
                const std::string& n = fields[k].text;
                if (n == "t_s") idx_t = int(k);
                else if (n == "x_m") idx_x = int(k);
                else if (n == "y_m") idx_y = int(k);
                else if (n == "z_m") idx_z = int(k);
                else if (n == "buttons") idx_b = int(k);
            }
            if (idx_t < 0 || idx_x < 0 || idx_y < 0 || idx_z < 0)
                throw InputError(source, line_no, 1,
                                 "expected a header row with the columns t_s, x_m, y_m, z_m (and optionally "
                                 "buttons), as written by 'tsf feel --log'");
            have_header = true;
            continue;
        }
        const int need = std::max({idx_t, idx_x, idx_y, idx_z, idx_b});
        if (int(fields.size()) <= need)
            throw InputError(source, line_no, int(line.size()) + 1,
                             "expected " + std::to_string(need + 1) + " columns, found " +
                                 std::to_string(fields.size()));
        ReplaySample s;
        s.t_s = parseNumber(fields[size_t(idx_t)], source, line_no, "t_s");
        const int axes[3] = {idx_x, idx_y, idx_z};
        const char* names[3] = {"x_m", "y_m", "z_m"};
        for (int a = 0; a < 3; ++a) {
            const int k = axes[a];
            const double c = parseNumber(fields[size_t(k)], source, line_no, names[a]);
            s.position_m[a] = c;
            if (std::abs(c) > kMaxReplayCoordinate_m)
                throw InputError(source, line_no, fields[size_t(k)].column,
                                 "position " + fields[size_t(k)].text +
                                     " m is outside +-1 m; expected device coordinates in metres");
        }
        if (idx_b >= 0) {
            const double b = parseNumber(fields[size_t(idx_b)], source, line_no, "buttons");
            if (b < 0.0 || b > 255.0 || b != std::floor(b))
                throw InputError(source, line_no, fields[size_t(idx_b)].column,
                                 "expected buttons as an integer 0..255, found '" + fields[size_t(idx_b)].text + "'");
            s.buttons = uint32_t(b);
        }
        if (!out.empty() && !(s.t_s > out.back().t_s))
            throw InputError(source, line_no, fields[size_t(idx_t)].column,
                             "time " + fields[size_t(idx_t)].text + " s does not increase (previous sample at " +
                                 std::to_string(out.back().t_s) + " s)");
        out.push_back(s);
    }
    if (!have_header)
        throw InputError(source, line_no, 0, "the replay file is empty; expected a header row t_s,x_m,y_m,z_m");
    if (out.empty()) throw InputError(source, line_no, 0, "the replay file has a header but no samples");
    return out;
}

std::vector<ReplaySample> readReplayFile(const std::string& path) {
    return parseReplayCsv(readFileBytes(path, kMaxReplayFileBytes), path);
}

ReplayDevice::ReplayDevice(std::vector<ReplaySample> samples, std::string source, DeviceLimits limits)
    : samples_(std::move(samples)), source_(std::move(source)), limits_(limits) {
    if (samples_.empty()) throw InputError(source_, 0, 0, "the replay file has no samples");
}

ReadStatus ReplayDevice::read(double loop_time_s, DeviceState& out) noexcept {
    const double t = samples_.front().t_s + loop_time_s;
    if (t > samples_.back().t_s) return ReadStatus::kEnded;
    if (samples_[cursor_].t_s > t) cursor_ = 0;
    while (cursor_ + 1 < samples_.size() && samples_[cursor_ + 1].t_s <= t) ++cursor_;
    const ReplaySample& a = samples_[cursor_];
    out.t_s = loop_time_s;
    out.buttons = a.buttons;
    out.homed = true;
    if (cursor_ + 1 >= samples_.size()) {
        out.position_m = a.position_m;
    } else {
        const ReplaySample& b = samples_[cursor_ + 1];
        const double f = (t - a.t_s) / (b.t_s - a.t_s);
        out.position_m = a.position_m + (b.position_m - a.position_m) * f;
    }
    return ReadStatus::kOk;
}

bool ReplayDevice::writeForce(const Vec3& force_N) noexcept {
    force_ = force_N;
    return true;
}

}  // namespace tsf::haptics
