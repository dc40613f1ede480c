// ForceLog: what each tick felt, recorded into memory that was reserved
// before the loop started (the tick never allocates or does I/O), and written
// as CSV after the loop ends.
//
// CSV columns (one row per tick, header first):
//   t_s                  loop time, seconds since the loop started
//   x_m, y_m, z_m        probe position, device frame (frames.h)
//   fx_N, fy_N, fz_N     force sent to the device
//   force_N              its magnitude
//   buttons              kButton* bits
//   mode                 "surface" or "volume" (the requested mode)
//   lod                  current continuous level of detail (0 = full detail)
//   contact, sliding, clamped, damping   0/1 flags of force_model.h
//   penetration_mm       depth below the surface along its normal (> 0 inside)
// The file replays with `tsf feel FIELD --device replay:FILE`.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "haptics/frames.h"

namespace tsf::haptics {

struct LogRecord {
    double t_s = 0.0;
    Vec3 position_m{0.0};
    Vec3 force_N{0.0};
    uint32_t buttons = 0;
    uint32_t flags = 0;          ///< kFlag* of force_model.h
    float lod = 0.0f;
    float penetration_m = 0.0f;
    bool volume = false;
};

class ForceLog {
public:
    /// Reserves room for `capacity` records up front.
    explicit ForceLog(size_t capacity) : records_(capacity) {}

    /// Appends if there is room (otherwise counts a dropped record). noexcept,
    /// no allocation.
    void push(const LogRecord& r) noexcept {
        if (size_ < records_.size()) records_[size_++] = r;
        else ++dropped_;
    }
    size_t size() const { return size_; }
    size_t capacity() const { return records_.size(); }
    uint64_t dropped() const { return dropped_; }
    const LogRecord& operator[](size_t i) const { return records_[i]; }
    void clear() noexcept { size_ = 0; dropped_ = 0; }

private:
    std::vector<LogRecord> records_;
    size_t size_ = 0;
    uint64_t dropped_ = 0;
};

/// Writes the log as CSV (see the file comment), atomically: a failed write
/// leaves no half file. Throws tsf::InputError for an unusable folder and
/// std::runtime_error for I/O failures.
void writeForceLogCsv(const std::string& path, const ForceLog& log);

}  // namespace tsf::haptics
