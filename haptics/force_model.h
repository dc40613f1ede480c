// The force model: one pure, deterministic function from (model, state,
// probe input) to (force, next state). No clock, no device, no allocation, no
// exceptions - it is what the 1 kHz tick calls and what the tests call.
//
// Forces (device frame, newtons; see frames.h and docs/haptics.md):
//   normal    (thesis 4.2-4.3, eqs 4.3-4.6) a spring from the probe to its
//             proxy: a point kept on the surface that follows the probe by
//             descending |proxy - probe| along the surface (updateProxy; a
//             god-object for height fields). Inside means below the surface
//             at the probe's own x, z (eq. 4.3's h < 0). The depth d is
//             |proxy - probe|, the direction probe -> proxy, which is the
//             surface normal (-dH/dx, 1, -dH/dz) at the proxy (eq. 4.5) once
//             the proxy has converged. Force magnitude f(d) = K d^2 / (2 delta)
//             for d < delta (the stiffness ramps in from 0 over the entry depth
//             delta, so touching is smooth) and K (d - delta / 2) beyond:
//             continuous, with a continuous slope, never stiffer than K.
//             The spring is evaluated half a tick ahead (d + (d - d_prev) / 2)
//             to cancel the energy a zero-order hold adds on every step.
//   friction  (eq. 4.7, after Fritz & Barner) a spring of stiffness K from the
//             proxy p_o to a sticktion point p_s, kept tangential. Static
//             while K |p_s - p_o| <= mu_s |F_n|: a force compared with a
//             force. Beyond that it slides: p_s is dragged behind p_o (toward
//             where it was, like a pulled string) so the spring force is
//             mu_k |F_n|. It sticks again when the filtered tangential speed
//             falls below stick_speed (a speed compared with a speed). The
//             thesis compared the speed |v| in m/s with |F_n| mu_s in newtons,
//             so its switch point depended on the units chosen.
//   gravity   (eq. 4.8) optional constant -gravity_N along y.
//   volume    (section 4.5, eqs 4.9-4.12) in the slab above the surface: a
//             soft force F_v (-dD/dx, 1 - s, -dD/dz), magnitude capped at F_v,
//             where s is the height fraction in the slab and D the scale-space
//             height interpolated between levels by s (finest level at the
//             slab bottom, coarsest at its top). It fades in over the outer
//             volume_edge_fraction of the slab at both faces, so crossing a
//             face is continuous (the thesis slab had force jumps there).
//   guidance  (section 7.2.1) optional pull in empty space toward the
//             coarsest level's surface, at most guidance_N; the exact
//             gradient of a potential, so it cannot pump energy.
//   wall      optional (EdgeMode::kWall) spring walls at the footprint edge.
//
// Safety, applied to the sum on every call:
//   - passivity observer (Hannaford & Ryu): E += -F_prev . (p - p_prev) is
//     the energy the environment has absorbed (force held over the tick, as
//     the device does). When E < 0 the surface has produced energy (sampling,
//     the volume field, mode changes); a damping -alpha v, v = the last
//     step's velocity, alpha = min(-E / (|v|^2 dt), max_damping), dissipates
//     it on the next tick. E is capped at twice the spring energy at the
//     force limit so a long run of friction cannot pay for a later burst.
//     Gravity and guidance are conservative and not observed.
//   - the output gain (start/stop ramp, from the loop) multiplies the force.
//   - magnitude clamp to max_force_N, keeping the direction; the observer's
//     damping is clamped first and the rest shares what is left.
//   - any non-finite value gives zero force and the `rejected` flag; a
//     non-finite input leaves the state untouched.
// Mode changes (level of detail, volume on/off) are never instantaneous: the
// continuous level moves at lod_rate_levels_per_s and the volume fades over
// volume_fade_s, so a button press cannot make the surface jump under the
// probe.
#pragma once

#include <cstdint>

#include "haptics/field_mapping.h"
#include "haptics/frames.h"
#include "haptics/haptic_device.h"
#include "haptics/scale_space.h"

namespace tsf::haptics {

enum class EdgeMode {
    kClamp,  ///< the surface continues flat beyond the field's border
    kWall,   ///< plus spring walls at the footprint's border
};

struct ForceParams {
    // Surface
    double stiffness_N_per_m = 1000.0;  ///< K; at most passiveStiffnessBound()
    double entry_depth_m = 0.001;       ///< delta: depth over which the stiffness ramps in
    SamplingParams sampling;            ///< interpolation and gradient method
    int proxy_iterations = 4;           ///< proxy descent steps per tick (each at most half a cell)
    EdgeMode edge = EdgeMode::kClamp;
    // Friction
    bool friction = true;
    double mu_static = 0.3;              ///< 0 <= mu_kinetic <= mu_static <= 1
    double mu_kinetic = 0.2;
    double stick_speed_m_per_s = 0.005;  ///< sliding stops below this filtered tangential speed
    // Other forces
    double gravity_N = 0.0;              ///< 0 = off
    double guidance_N = 0.0;             ///< 0 = off
    double guidance_ramp_m = 0.005;      ///< the pull grows from 0 to guidance_N over this gap
    double volume_force_N = 1.0;         ///< F_v = k s_f of eq. 4.12
    double volume_edge_fraction = 0.1;   ///< of the slab thickness, fade at each face
    // Mode changes
    double lod_rate_levels_per_s = 4.0;
    double volume_fade_s = 0.25;
    // Safety
    double max_force_N = 6.0;            ///< <= DeviceLimits::max_force_N
    bool passivity_observer = true;
    bool hold_compensation = true;       ///< evaluate the surface spring half a tick ahead
    double max_damping_Ns_per_m = 20.0;  ///< cap of the observer's damping, <= DeviceLimits
};

/// Everything computeForce reads besides state and input. Built and checked
/// by makeForceModel; the ScaleSpace must outlive it.
struct ForceModel {
    const ScaleSpace* space = nullptr;
    FieldMapping mapping;
    ForceParams params;
    double energy_reserve_J = 0.0;       ///< cap on the observer's stored energy
    double guidance_slope_bound = 0.0;   ///< max |grad H| of the guidance level, m/m
};

/// Largest stiffness that keeps a sampled spring passive on this device at
/// rate_Hz: from Colgate's bound b > K T / 2 + |B| with the device damping b
/// implied by its rated stiffness at its rated rate (b = K_r T_r / 2), so
/// K_max = K_r T_r / T, and never above K_r. 0 for a non-positive rate.
double passiveStiffnessBound(const DeviceLimits& limits, double rate_Hz) noexcept;

/// Checks params against the device and the rate and builds the model.
/// Throws tsf::InputError with a message naming the option at fault (for
/// example a stiffness above the passive bound, mu_kinetic > mu_static, a
/// max force above the device's). The space must hold at least one level.
ForceModel makeForceModel(const ScaleSpace& space, const FieldMapping& mapping, const ForceParams& params,
                          const DeviceLimits& limits, double rate_Hz);

/// Per-tick input.
struct ForceInput {
    double t_s = 0.0;
    Vec3 position_m{0.0};
    Vec3 velocity_m_per_s{0.0};  ///< filtered (velocity_filter.h)
    double output_gain = 1.0;    ///< 0..1, start/stop ramp; clamped
    int lod = 0;                 ///< requested level of detail (0 = full detail)
    bool volume = false;         ///< requested volume mode
};

/// What the model remembers between ticks. Default-constructed = session start.
struct ForceState {
    bool started = false;
    double t_s = 0.0;
    Vec3 position_m{0.0};
    double lod = 0.0;              ///< current continuous level of detail
    double volume_weight = 0.0;    ///< 0 = surface mode, 1 = volume mode, between = fading
    double depth_m = 0.0;          ///< penetration along the normal last tick
    bool touching = false;         ///< the probe was below the surface last tick
    Vec3 proxy_m{0.0};             ///< the proxy (god-object) last tick
    bool in_contact = false;
    bool sliding = false;
    Vec3 stick_point_m{0.0};
    double energy_J = 0.0;         ///< passivity observer: energy absorbed by the environment
    Vec3 observed_force_N{0.0};    ///< observed part of the force applied last tick
};

/// Bits of ForceOutput::flags.
inline constexpr uint32_t kFlagContact = 0x01;
inline constexpr uint32_t kFlagSliding = 0x02;
inline constexpr uint32_t kFlagInVolume = 0x04;
inline constexpr uint32_t kFlagClamped = 0x08;
inline constexpr uint32_t kFlagDamping = 0x10;   ///< the passivity observer added damping
inline constexpr uint32_t kFlagRejected = 0x20;  ///< non-finite input or result; force zeroed

struct ForceOutput {
    Vec3 force_N{0.0};        ///< finite, |force_N| <= max_force_N
    ForceState state;
    uint32_t flags = 0;
    double penetration_m = 0.0;   ///< distance from the probe to its proxy, > 0 inside the surface, 0 in the air
    double damping_Ns_per_m = 0.0;
};

/// The force model (see the file comment). noexcept, deterministic: the same
/// (model, state, input) always gives the same output.
ForceOutput computeForce(const ForceModel& model, const ForceState& state, const ForceInput& input) noexcept;

/// The spring law f(d) of the normal force, newtons; 0 for d <= 0 or NaN.
double springForce_N(double depth_m, double stiffness_N_per_m, double entry_depth_m) noexcept;

/// Surface height (device y, metres) and slope (dH/dx, dH/dz) at a device
/// point for a continuous level; what the normal force uses.
struct SurfacePoint {
    double height_y_m = 0.0;
    double slope_x = 0.0;  ///< dH/dx, m/m
    double slope_z = 0.0;  ///< dH/dz, m/m
};
SurfacePoint surfaceAt(const ForceModel& model, const Vec3& p_m, double level) noexcept;

/// The proxy (god-object) of the probe: a point kept on the surface that
/// moves from start_m toward the probe, by `iterations` descent steps on
/// |proxy - probe| along the surface, never jumping (steps of at most half a
/// cell, each accepted only if it brings the proxy closer). In the air the
/// proxy is the probe. Because the proxy only moves to shorten the spring
/// between it and the probe, the spring can only lose energy through proxy
/// motion: contact with any surface shape, even cliffs and narrow valleys, is
/// passive in continuous time, and the proxy stays on the face it touched
/// instead of flipping between the walls of a valley.
struct Contact {
    bool touching = false;       ///< the probe is below the surface
    Vec3 proxy_m{0.0};
    Vec3 normal{0.0, 1.0, 0.0};  ///< unit, from the probe toward the proxy
    double depth_m = 0.0;        ///< |proxy - probe| when touching, else 0
};
Contact updateProxy(const ForceModel& model, const Vec3& p_m, double level, int iterations,
                    const Vec3& start_m) noexcept;

}  // namespace tsf::haptics
