// ReplayDevice: plays back recorded probe positions (a `tsf feel --log` file
// or any CSV with the same columns) as if a device were being moved.
//
// File format: comma-separated, a header row naming the columns, then one
// row per sample. Required columns: t_s (seconds, strictly increasing),
// x_m, y_m, z_m (device frame, metres). Optional: buttons (integer of
// kButton* bits). Other columns are ignored, so a force log replays as is.
// Blank lines and lines starting with '#' are skipped.
//
// Playback: loop time 0 is the first sample; positions are interpolated
// linearly in time, buttons hold the last sample's value; after the last
// sample read() returns kEnded. Forces written are kept (forceWritten()) but
// move nothing: the recording is kinematic.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "haptics/haptic_device.h"

namespace tsf::haptics {

struct ReplaySample {
    double t_s = 0.0;
    Vec3 position_m{0.0};
    uint32_t buttons = 0;
};

/// Largest replay file read (bytes): a one-hour log at 1 kHz is about
/// 250 MB; the cap keeps an endless stream from filling memory.
inline constexpr int64_t kMaxReplayFileBytes = int64_t(1) << 30;  // 1 GiB

/// Parses a replay file (at most kMaxReplayFileBytes). Throws
/// tsf::InputError with file, line and column for a missing column, a bad
/// number, time not increasing, a position outside +-1 m, or a file with no
/// samples; naming the file for one that is too large or a device.
std::vector<ReplaySample> readReplayFile(const std::string& path);

/// The same from text already in memory (source names it in errors).
std::vector<ReplaySample> parseReplayCsv(const std::string& text, const std::string& source);

class ReplayDevice final : public HapticDevice {
public:
    ReplayDevice(std::vector<ReplaySample> samples, std::string source, DeviceLimits limits = {});

    std::string name() const override { return "replay:" + source_; }
    DeviceLimits limits() const override { return limits_; }
    bool needsRealtime() const override { return false; }
    void open() override {}
    void close() noexcept override { force_ = Vec3(0.0); }
    ReadStatus read(double loop_time_s, DeviceState& out) noexcept override;
    bool writeForce(const Vec3& force_N) noexcept override;

    Vec3 forceWritten() const { return force_; }
    double duration_s() const { return samples_.back().t_s - samples_.front().t_s; }

private:
    std::vector<ReplaySample> samples_;
    std::string source_;
    DeviceLimits limits_;
    size_t cursor_ = 0;
    Vec3 force_{0.0};
};

}  // namespace tsf::haptics
