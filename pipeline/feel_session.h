// A feel session from a Scene, with no command line: the relief tsf gen
// would print (haptics/printed_relief.h), fitted to the device's workspace,
// its scale space and force model, then the 1 kHz loop on a device opened
// for the session and left at zero force on every way out, exceptions
// included. `tsf feel` is one front end; it only parses, makes the device
// and prints.
#pragma once

#include <atomic>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "gen/model/scene.h"
#include "haptics/coverage.h"
#include "haptics/feel_renderer.h"
#include "haptics/field_mapping.h"
#include "haptics/force_log.h"
#include "haptics/force_model.h"
#include "haptics/haptic_device.h"
#include "haptics/haptic_loop.h"
#include "haptics/height_grid.h"
#include "haptics/printed_relief.h"
#include "haptics/scale_space.h"

namespace tsf {

/// What is felt: the printed relief, where it lies in the workspace and
/// its levels of detail. Built before any device is opened (a Falcon must be
/// served without pause once it is open).
struct FeelSurface {
    haptics::ReliefInfo relief;
    haptics::HeightGrid grid;
    haptics::FieldMapping mapping;
    haptics::ScaleSpace space;
    haptics::DeviceLimits limits;  ///< the workspace and force limit the surface is fitted to
    haptics::MappingScale scale;   ///< device mm per printed mm, across and up
    double build_s = 0;            ///< building the scale space, s
};

/// `levels` (1..kMaxScaleLevels) of `kind`; the Falcon's workspace and limits;
/// `proportions`: the footprint and relief fitted apart (today's default) or
/// one scale for x, y and z (field_mapping.h).
/// `mesh` (nullable): feel that mesh (a model file as written, or as
/// OpenSCAD rendered an edited .scad) on the Scene's grid instead of the
/// Scene's own mesh.
FeelSurface buildFeelSurface(const Scene& scene, int levels, haptics::ScaleSpaceKind kind,
                             const haptics::DeviceLimits& limits = {}, const Mesh* mesh = nullptr,
                             haptics::Proportions proportions = haptics::Proportions::kFitted);

struct FeelRequest {
    haptics::ForceParams force;
    haptics::RendererOptions renderer;
    haptics::LoopOptions loop;
    bool realtime = false;      ///< real-time clock and priority (a real device); else virtual time
    double spin_us = 0;         ///< the real-time clock's final busy wait, us
    size_t log_records = 0;     ///< room in the force log (0: no log kept)
};

struct FeelOutcome {
    haptics::LoopStats stats;
    haptics::RendererCounters counters;
    haptics::ForceLog log{0};
    haptics::Coverage coverage;  ///< cells the probe touched (from the log)
    std::string priority;        ///< what the scheduler granted the loop's thread
    double wall_s = 0;
};

/// Opens `device`, calls `on_open` (e.g. to tell a person to home the
/// Falcon), runs the loop until its duration, the device's end or `stop`,
/// and closes the device after a zero force, whatever happens. A device
/// that cannot be opened throws its haptics::DeviceError before any loop.
FeelOutcome runFeelSession(const Scene& scene, const FeelSurface& surface, haptics::HapticDevice& device,
                           const FeelRequest& request, const std::atomic<bool>& stop,
                           const std::function<void()>& on_open = {});

}  // namespace tsf
