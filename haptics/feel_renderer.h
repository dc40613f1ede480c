// FeelRenderer: the per-tick work of `tsf feel` between reading the device
// and writing the force - button handling, the velocity filter and the force
// model - as a TickHandler for the haptic loop.
//
// Buttons (rising edges, as in the thesis user study):
//   centre  volume mode on/off
//   plus    one level coarser (up to the last scale-space level)
//   minus   one level finer (down to level 0, full detail)
// The force model fades between modes and levels (force_model.h), so a press
// never makes the surface jump.
#pragma once

#include <cstdint>

#include "haptics/force_model.h"
#include "haptics/haptic_loop.h"
#include "haptics/velocity_filter.h"

namespace tsf::haptics {

struct RendererOptions {
    double velocity_window_s = kDefaultVelocityWindow_s;
    int start_lod = 0;
    bool start_volume = false;
};

/// Counters gathered over a session (written by the haptic thread, read
/// after it has been joined).
struct RendererCounters {
    uint64_t ticks = 0;
    uint64_t contact_ticks = 0;
    uint64_t clamped_ticks = 0;
    uint64_t damping_ticks = 0;
    uint64_t rejected_ticks = 0;
    uint64_t mode_switches = 0;
    double max_force_N = 0.0;
    double max_penetration_m = 0.0;
};

class FeelRenderer final : public TickHandler {
public:
    /// The model (and its ScaleSpace) must outlive the renderer.
    FeelRenderer(const ForceModel& model, const RendererOptions& options = {});

    Vec3 tick(const DeviceState& state, double gain, LogRecord& record) noexcept override;

    const ForceState& forceState() const { return state_; }
    const RendererCounters& counters() const { return counters_; }
    int requestedLod() const { return lod_; }
    bool requestedVolume() const { return volume_; }

private:
    const ForceModel& model_;
    ForceState state_;
    VelocityFilter velocity_;
    RendererCounters counters_;
    int lod_ = 0;
    bool volume_ = false;
    uint32_t last_buttons_ = 0;
};

}  // namespace tsf::haptics
