#include "haptics/feel_renderer.h"

#include <algorithm>

#include <glm/geometric.hpp>

namespace tsf::haptics {

FeelRenderer::FeelRenderer(const ForceModel& model, const RendererOptions& options)
    : model_(model), velocity_(options.velocity_window_s), volume_(options.start_volume) {
    const int top = model.space ? model.space->count() - 1 : 0;
    lod_ = std::clamp(options.start_lod, 0, std::max(0, top));
}

Vec3 FeelRenderer::tick(const DeviceState& ds, double gain, LogRecord& record) noexcept {
    const uint32_t pressed = ds.buttons & ~last_buttons_;
    last_buttons_ = ds.buttons;
    const int top = model_.space->count() - 1;
    if (pressed & kButtonCentre) {
        volume_ = !volume_;
        ++counters_.mode_switches;
    }
    if ((pressed & kButtonPlus) && lod_ < top) {
        ++lod_;
        ++counters_.mode_switches;
    }
    if ((pressed & kButtonMinus) && lod_ > 0) {
        --lod_;
        ++counters_.mode_switches;
    }
    ForceInput in;
    in.t_s = ds.t_s;
    in.position_m = ds.position_m;
    in.velocity_m_per_s = velocity_.update(ds.t_s, ds.position_m);
    in.output_gain = gain;
    in.lod = lod_;
    in.volume = volume_;
    const ForceOutput out = computeForce(model_, state_, in);
    state_ = out.state;

    ++counters_.ticks;
    if (out.flags & kFlagContact) ++counters_.contact_ticks;
    if (out.flags & kFlagClamped) ++counters_.clamped_ticks;
    if (out.flags & kFlagDamping) ++counters_.damping_ticks;
    if (out.flags & kFlagRejected) ++counters_.rejected_ticks;
    counters_.max_force_N = std::max(counters_.max_force_N, glm::length(out.force_N));
    counters_.max_penetration_m = std::max(counters_.max_penetration_m, out.penetration_m);

    record.flags = out.flags;
    record.lod = float(state_.lod);
    record.penetration_m = float(out.penetration_m);
    record.volume = volume_;
    return out.force_N;
}

}  // namespace tsf::haptics
