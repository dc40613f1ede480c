#include "pipeline/feel_session.h"

#include <chrono>

#include "haptics/loop_clock.h"

namespace tsf {
namespace {

using namespace tsf::haptics;

// Zero force and close on every way out of the session, exceptions included.
class DeviceSession {
public:
    explicit DeviceSession(HapticDevice& d) : device_(d) { device_.open(); }
    ~DeviceSession() {
        device_.writeForce(haptics::Vec3(0.0));
        device_.close();
    }
    DeviceSession(const DeviceSession&) = delete;
    DeviceSession& operator=(const DeviceSession&) = delete;

private:
    HapticDevice& device_;
};

double secondsSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

FeelSurface buildFeelSurface(const Scene& scene, int levels, ScaleSpaceKind kind, const DeviceLimits& limits,
                             const Mesh* mesh, Proportions proportions) {
    FeelSurface s;
    s.grid = mesh ? meshRelief(scene, *mesh, &s.relief) : printedRelief(scene, &s.relief);
    s.limits = limits;
    const double height_mm = scene.mapping.max_height_mm;
    s.mapping = mapReliefToWorkspace(s.grid.cols, s.grid.rows, s.relief.sample_mm, height_mm, proportions,
                                     limits.workspace);
    s.scale = mappingScale(s.mapping, s.relief.sample_mm, height_mm);
    const auto t0 = std::chrono::steady_clock::now();
    s.space = buildScaleSpace(s.grid, levels, kind, s.relief.samples_per_pitch);
    s.build_s = secondsSince(t0);
    return s;
}

FeelOutcome runFeelSession(const Scene& scene, const FeelSurface& surface, HapticDevice& device,
                           const FeelRequest& rq, const std::atomic<bool>& stop, const std::function<void()>& on_open) {
    const ForceModel model = makeForceModel(surface.space, surface.mapping, rq.force, surface.limits, rq.loop.rate_Hz);
    FeelRenderer renderer(model, rq.renderer);
    SteadyLoopClock steady(rq.spin_us * 1e-6);
    FakeLoopClock fake;
    LoopClock& clock = rq.realtime ? static_cast<LoopClock&>(steady) : static_cast<LoopClock&>(fake);

    FeelOutcome out;
    out.log = ForceLog(rq.log_records);
    const auto t0 = std::chrono::steady_clock::now();
    {
        DeviceSession session(device);
        if (on_open) on_open();
        runHapticLoopThread(device, renderer, clock, rq.loop, stop, &out.log, out.stats, rq.realtime, &out.priority);
    }
    out.wall_s = secondsSince(t0);
    out.counters = renderer.counters();
    out.coverage = touchedCells(scene, surface.relief, surface.mapping, out.log);
    return out;
}

}  // namespace tsf
