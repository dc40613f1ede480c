#include "haptics/velocity_filter.h"

#include <cmath>

namespace tsf::haptics {

Vec3 VelocityFilter::update(double t_s, const Vec3& position_m) noexcept {
    if (!std::isfinite(t_s) || !std::isfinite(position_m.x) || !std::isfinite(position_m.y) ||
        !std::isfinite(position_m.z))
        return Vec3(0.0);
    if (count_ > 0) {
        const size_t newest = (head_ + kCapacity - 1) % kCapacity;
        if (!(t_s > t_[newest])) return Vec3(0.0);  // time must advance
    }
    t_[head_] = t_s;
    p_[head_] = position_m;
    head_ = (head_ + 1) % kCapacity;
    if (count_ < kCapacity) ++count_;
    if (count_ < 2) return Vec3(0.0);
    // Walk back from the previous sample until one is at least window_s old.
    size_t pick = (head_ + kCapacity - 2) % kCapacity;
    for (size_t k = 2; k <= count_; ++k) {
        pick = (head_ + kCapacity - k) % kCapacity;
        if (t_s - t_[pick] >= window_s_) break;
    }
    const double dt = t_s - t_[pick];
    if (!(dt > 0.0)) return Vec3(0.0);
    return (position_m - p_[pick]) / dt;
}

}  // namespace tsf::haptics
