// VelocityFilter: probe velocity as a finite difference over a time window.
//
// Why: a one-tick difference of encoder positions is mostly quantisation
// noise (a Falcon count is about 38 um; over 1 ms that is 38 mm/s of noise).
// Differencing over window_s instead divides the noise by the window length
// at the cost of window_s / 2 of delay; CHAI3D uses 15 ms. The default here,
// 10 ms, gives under 4 mm/s of quantisation noise with 5 ms of delay.
//
// Behaviour: keeps the last kCapacity samples in a fixed ring (no
// allocation). The velocity is (p_now - p_then) / (t_now - t_then) where
// "then" is the newest stored sample at least window_s old, or the oldest one
// while the history is shorter. The first sample, a sample that does not
// advance time, or a non-finite sample gives zero velocity (and non-finite
// samples are not stored).
#pragma once

#include <array>
#include <cstddef>

#include "haptics/frames.h"

namespace tsf::haptics {

inline constexpr double kDefaultVelocityWindow_s = 0.010;

class VelocityFilter {
public:
    static constexpr size_t kCapacity = 64;

    explicit VelocityFilter(double window_s = kDefaultVelocityWindow_s) noexcept : window_s_(window_s) {}

    /// Adds a sample and returns the filtered velocity in m/s.
    Vec3 update(double t_s, const Vec3& position_m) noexcept;
    void reset() noexcept { count_ = 0; head_ = 0; }
    double window() const noexcept { return window_s_; }

private:
    double window_s_;
    std::array<double, kCapacity> t_{};
    std::array<Vec3, kCapacity> p_{};
    size_t head_ = 0;   ///< index of the next write
    size_t count_ = 0;  ///< stored samples
};

}  // namespace tsf::haptics
