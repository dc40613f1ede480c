#include "haptics/force_model.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include <glm/geometric.hpp>

#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf::haptics {
namespace {

/// Below this filtered speed the observer cannot dissipate by damping (the
/// damping force -alpha v would need an unbounded alpha); 0.1 mm/s is under
/// the velocity filter's noise floor, so nothing real is lost.
constexpr double kObserverMinSpeed_m_per_s = 1e-4;
/// Longest time step the mode transitions integrate at once; a stalled loop
/// must not make the level of detail jump when it resumes.
constexpr double kMaxModeStep_s = 0.05;
/// Below a nanometre the direction probe -> proxy is rounding noise; the
/// proxy's surface normal is used instead (the force there is ~0 anyway).
constexpr double kCoincident_m = 1e-9;

bool isFinite(const Vec3& v) noexcept { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

double smoothstep01(double x) noexcept {
    x = std::clamp(x, 0.0, 1.0);
    return x * x * (3.0 - 2.0 * x);
}

double approach(double value, double target, double max_step) noexcept {
    if (value < target) return std::min(target, value + max_step);
    return std::max(target, value - max_step);
}

/// Scales v down to magnitude `limit` if it is longer; keeps its direction.
/// Guarantees glm::length(result) <= limit: v * (limit / m) can come out an
/// ulp or two long after rounding, so it is shrunk by two ulps at a time
/// until it is not (a few steps; 64 would shrink it by 3e-14).
Vec3 clampMagnitude(const Vec3& v, double limit, bool* clamped = nullptr) noexcept {
    const double m = glm::length(v);
    if (m > limit && m > 0.0) {
        if (clamped) *clamped = true;
        Vec3 r = v * (limit / m);
        constexpr double kUlpShrink = 1.0 - 2.0 * std::numeric_limits<double>::epsilon();
        for (int step = 0; step < 64 && glm::length(r) > limit; ++step) r *= kUlpShrink;
        return r;
    }
    return v;
}

/// A number for a message: shortest form that round-trips to 4 digits.

void require(bool ok, const std::string& what) {
    if (!ok) throw InputError(what);
}

/// Largest |grad H| (m/m) of one level, sampled 4 x 4 per texel.
double maxSlope(const ForceModel& model, int level) {
    const ScaleLevel& l = model.space->levels[size_t(level)];
    const double s = l.base_cells_per_texel;
    constexpr int kSub = 4;
    double best = 0.0;
    for (int32_t j = 0; j < l.grid.rows * kSub; ++j)
        for (int32_t i = 0; i < l.grid.cols * kSub; ++i) {
            const double gi = ((i + 0.5) / kSub - 0.5 + 0.5) * s - 0.5;
            const double gj = ((j + 0.5) / kSub - 0.5 + 0.5) * s - 0.5;
            const HeightSample h = sampleLevel(*model.space, level, gi, gj, model.params.sampling);
            const double k = model.mapping.relief_m / model.mapping.cell_m;
            best = std::max(best, k * std::hypot(h.d_di, h.d_dj));
        }
    return best;
}

}  // namespace

double passiveStiffnessBound(const DeviceLimits& limits, double rate_Hz) noexcept {
    if (!(rate_Hz > 0.0) || !(limits.rated_rate_Hz > 0.0)) return 0.0;
    return limits.max_stiffness_N_per_m * std::min(1.0, rate_Hz / limits.rated_rate_Hz);
}

double springForce_N(double depth_m, double stiffness_N_per_m, double entry_depth_m) noexcept {
    if (!(depth_m > 0.0)) return 0.0;
    if (depth_m < entry_depth_m) return stiffness_N_per_m * depth_m * depth_m / (2.0 * entry_depth_m);
    return stiffness_N_per_m * (depth_m - 0.5 * std::max(0.0, entry_depth_m));
}

ForceModel makeForceModel(const ScaleSpace& space, const FieldMapping& mapping, const ForceParams& p,
                          const DeviceLimits& limits, double rate_Hz) {
    require(!space.levels.empty() && !space.levels[0].grid.empty(), "the field has no levels to render");
    require(mapping.cell_m > 0.0 && mapping.relief_m > 0.0, "the field mapping is empty");
    require(rate_Hz > 0.0 && std::isfinite(rate_Hz), "--rate must be a positive number of ticks per second");
    require(p.max_force_N > 0.0 && p.max_force_N <= limits.max_force_N,
            "--max-force must be above 0 and at most the device's limit of " + formatSignificant(limits.max_force_N, 4) +
                " N");
    const double k_bound = passiveStiffnessBound(limits, rate_Hz);
    const double k_guidance = p.guidance_N > 0.0 ? p.guidance_N / p.guidance_ramp_m : 0.0;
    require(p.stiffness_N_per_m > 0.0 && std::isfinite(p.stiffness_N_per_m),
            "--stiffness must be a positive number of N/m");
    require(p.stiffness_N_per_m + k_guidance <= k_bound,
            "--stiffness " + formatSignificant(p.stiffness_N_per_m, 4) + " N/m" +
                (k_guidance > 0.0 ? " plus the guidance spring " + formatSignificant(k_guidance, 4) + " N/m" : "") +
                " is above the passive bound of " + formatSignificant(k_bound, 4) + " N/m for this device at " +
                formatSignificant(rate_Hz, 4) + " Hz (b > K T / 2); lower it or raise --rate");
    require(p.proxy_iterations >= 1 && p.proxy_iterations <= 16, "proxy iterations must be between 1 and 16");
    require(p.entry_depth_m >= 0.0 && p.entry_depth_m <= 0.01, "the entry depth must be between 0 and 10 mm");
    require(p.mu_static >= 0.0 && p.mu_static <= 1.0 && p.mu_kinetic >= 0.0 && p.mu_kinetic <= p.mu_static,
            "friction coefficients must satisfy 0 <= --mu-k <= --mu-s <= 1");
    require(p.stick_speed_m_per_s > 0.0, "the stick speed must be positive");
    require(p.gravity_N >= 0.0 && p.gravity_N <= p.max_force_N, "--gravity must be between 0 and --max-force");
    require(p.guidance_N >= 0.0 && p.guidance_N <= p.max_force_N && p.guidance_ramp_m > 0.0,
            "--guidance must be between 0 and --max-force");
    require(p.volume_force_N >= 0.0 && p.volume_force_N <= p.max_force_N,
            "the volume force must be between 0 and --max-force");
    require(p.volume_edge_fraction > 0.0 && p.volume_edge_fraction <= 0.5,
            "the volume edge fraction must be in (0, 0.5]");
    require(p.lod_rate_levels_per_s > 0.0 && p.volume_fade_s > 0.0, "mode transition rates must be positive");
    require(p.max_damping_Ns_per_m >= 0.0 && p.max_damping_Ns_per_m <= limits.max_damping_Ns_per_m,
            "the observer's damping must be between 0 and the device's limit of " +
                formatSignificant(limits.max_damping_Ns_per_m, 4) + " N s/m");
    require(!p.sampling.central_differences || p.sampling.central_step_texels > 0.0,
            "the central-difference step must be positive");
    ForceModel m;
    m.space = &space;
    m.mapping = mapping;
    m.params = p;
    // Twice the energy the spring stores at the force limit: enough to give
    // back a full press, small enough that a long stretch of absorbed energy
    // (friction) cannot later pay for a burst from the surface.
    m.energy_reserve_J = p.max_force_N * p.max_force_N / p.stiffness_N_per_m;
    m.guidance_slope_bound = p.guidance_N > 0.0 ? maxSlope(m, space.count() - 1) : 0.0;
    return m;
}

SurfacePoint surfaceAt(const ForceModel& model, const Vec3& p_m, double level) noexcept {
    const FieldMapping& map = model.mapping;
    const GridPoint g = deviceToGrid(map, p_m);
    const HeightSample h = sampleScale(*model.space, level, g.gi, g.gj, model.params.sampling);
    const double k = map.relief_m / map.cell_m;
    // grid j runs north = device -z.
    return {map.floor_y_m + map.relief_m * h.height, k * h.d_di, -k * h.d_dj};
}

Contact updateProxy(const ForceModel& model, const Vec3& p_m, double level, int iterations,
                    const Vec3& start_m) noexcept {
    Contact c;
    const SurfacePoint at_probe = surfaceAt(model, p_m, level);
    if (!(p_m.y < at_probe.height_y_m)) {  // in the air: the proxy is the probe
        c.proxy_m = p_m;
        c.normal = glm::normalize(Vec3(-at_probe.slope_x, 1.0, -at_probe.slope_z));
        return c;
    }
    // Descend |q(u) - p|^2 over the surface points q(u) = (u_x, H(u), u_z),
    // from where the proxy was. Gauss-Newton direction
    // -(I + g g^T)^-1 r with r = (u - p) + (H - p_y) g; a step is taken only
    // if it brings the proxy closer to the probe (halving it up to three
    // times otherwise), and is at most half a cell long so the proxy follows
    // the surface instead of jumping across it.
    const double max_step = 0.5 * model.mapping.cell_m;
    double ux = start_m.x, uz = start_m.z;
    SurfacePoint q = surfaceAt(model, Vec3(ux, 0.0, uz), level);
    auto dist2 = [&](double x, double h, double z) {
        return (x - p_m.x) * (x - p_m.x) + (h - p_m.y) * (h - p_m.y) + (z - p_m.z) * (z - p_m.z);
    };
    double j = dist2(ux, q.height_y_m, uz);
    for (int it = 0; it < iterations; ++it) {
        const double gx = q.slope_x, gz = q.slope_z;
        const double dy = q.height_y_m - p_m.y;
        const double rx = (ux - p_m.x) + dy * gx, rz = (uz - p_m.z) + dy * gz;
        const double gr = (gx * rx + gz * rz) / (1.0 + gx * gx + gz * gz);
        double sx = -(rx - gx * gr), sz = -(rz - gz * gr);
        const double len = std::hypot(sx, sz);
        if (!(len > 0.0)) break;
        if (len > max_step) {
            sx *= max_step / len;
            sz *= max_step / len;
        }
        bool moved = false;
        for (int half = 0; half < 4 && !moved; ++half, sx *= 0.5, sz *= 0.5) {
            const SurfacePoint t = surfaceAt(model, Vec3(ux + sx, 0.0, uz + sz), level);
            const double jt = dist2(ux + sx, t.height_y_m, uz + sz);
            if (jt < j) {
                ux += sx;
                uz += sz;
                q = t;
                j = jt;
                moved = true;
            }
        }
        if (!moved) break;
    }
    c.touching = true;
    c.proxy_m = Vec3(ux, q.height_y_m, uz);
    const Vec3 normal = glm::normalize(Vec3(-q.slope_x, 1.0, -q.slope_z));
    const Vec3 to_proxy = c.proxy_m - p_m;
    c.depth_m = glm::length(to_proxy);
    // Direction: from the probe to the proxy (the gradient of the proxy
    // spring's energy); the proxy's normal when they nearly coincide.
    c.normal = c.depth_m > kCoincident_m ? to_proxy / c.depth_m : normal;
    return c;
}

ForceOutput computeForce(const ForceModel& model, const ForceState& state, const ForceInput& in) noexcept {
    ForceOutput out;
    out.state = state;
    const ForceParams& P = model.params;
    const Vec3 p = in.position_m;
    const Vec3 v = isFinite(in.velocity_m_per_s) ? in.velocity_m_per_s : Vec3(0.0);
    if (!std::isfinite(in.t_s) || !isFinite(p) || model.space == nullptr || model.space->levels.empty()) {
        out.flags = kFlagRejected;
        out.state.observed_force_N = Vec3(0.0);  // zero force is what will be applied
        return out;
    }
    ForceState& s = out.state;
    const double dt = s.started ? std::max(0.0, in.t_s - s.t_s) : 0.0;
    const double top_level = double(model.space->count() - 1);

    // Mode transitions: never instantaneous.
    const double mode_dt = std::min(dt, kMaxModeStep_s);
    const double lod_target = std::clamp(double(in.lod), 0.0, top_level);
    if (!s.started) s.lod = lod_target;
    s.lod = std::clamp(approach(s.lod, lod_target, P.lod_rate_levels_per_s * mode_dt), 0.0, top_level);
    s.volume_weight = std::clamp(approach(s.volume_weight, in.volume ? 1.0 : 0.0, mode_dt / P.volume_fade_s), 0.0, 1.0);

    // Normal force (eqs 4.3-4.6), from the probe to its proxy on the surface.
    // The proxy starts where it was if it was on the surface, else where the
    // probe was last tick (the probe has just come through the surface there).
    const Vec3 start = state.started ? (state.touching ? state.proxy_m : state.position_m) : p;
    const Contact contact = updateProxy(model, p, s.lod, P.proxy_iterations, start);
    s.proxy_m = contact.proxy_m;
    s.touching = contact.touching;
    const Vec3 n = contact.normal;
    const double depth = contact.depth_m;
    out.penetration_m = depth;
    // Zero-order-hold compensation: the device holds this force for a whole
    // tick while the probe keeps moving, which makes a sampled spring give
    // back (1/2) K dx^2 more than it took on every step. Evaluating the spring
    // half a step ahead, d + (d - d_prev) / 2, cancels that to first order
    // (it is the damping K T / 2 that the sampling removed).
    double depth_eval = depth;
    if (P.hold_compensation && state.started && depth > 0.0) depth_eval = depth + 0.5 * (depth - state.depth_m);
    s.depth_m = depth;
    const double fn = depth > 0.0 ? springForce_N(depth_eval, P.stiffness_N_per_m, P.entry_depth_m) : 0.0;
    Vec3 f_env = n * fn;

    // Friction (eq. 4.7 with a dimensionally sound switch).
    if (depth > 0.0 && P.friction) {
        const Vec3 p_o = contact.proxy_m;  // the probe's point on the surface
        if (!s.in_contact) {
            s.stick_point_m = p_o;
            s.sliding = false;
        }
        Vec3 disp = s.stick_point_m - p_o;
        disp -= n * glm::dot(disp, n);  // keep it tangential
        const double r = glm::length(disp);
        const double limit_static = P.mu_static * fn;
        const double limit_kinetic = P.mu_kinetic * fn;
        const Vec3 vt = v - n * glm::dot(v, n);
        if (!s.sliding && P.stiffness_N_per_m * r > limit_static) s.sliding = true;
        else if (s.sliding && glm::length(vt) < P.stick_speed_m_per_s) s.sliding = false;
        // Sliding keeps the spring at the kinetic force; sticking keeps it
        // within the static cone (it can only be outside after fn dropped).
        const double radius = (s.sliding ? limit_kinetic : limit_static) / P.stiffness_N_per_m;
        if (r > radius && r > 0.0) disp *= radius / r;
        s.stick_point_m = p_o + disp;
        f_env += disp * P.stiffness_N_per_m;
        s.in_contact = true;
        if (s.sliding) out.flags |= kFlagSliding;
    } else {
        s.in_contact = false;
        s.sliding = false;
    }
    if (depth > 0.0) out.flags |= kFlagContact;

    // Volume (eqs 4.9-4.12).
    const FieldMapping& map = model.mapping;
    const double slab = map.volume_top_y_m - map.volume_bottom_y_m;
    if (s.volume_weight > 0.0 && slab > 0.0 && p.y > map.volume_bottom_y_m && p.y < map.volume_top_y_m) {
        const double frac = (p.y - map.volume_bottom_y_m) / slab;
        const double level = s.lod + frac * (top_level - s.lod);
        const SurfacePoint d = surfaceAt(model, p, level);
        const Vec3 raw = clampMagnitude(P.volume_force_N * Vec3(-d.slope_x, 1.0 - frac, -d.slope_z), P.volume_force_N);
        const double e = P.volume_edge_fraction;
        const double envelope = smoothstep01(frac / e) * smoothstep01((1.0 - frac) / e);
        f_env += raw * (s.volume_weight * envelope);
        out.flags |= kFlagInVolume;
    }

    // Walls at the footprint border.
    if (P.edge == EdgeMode::kWall) {
        const double K = P.stiffness_N_per_m, delta = P.entry_depth_m;
        f_env.x += springForce_N(map.west_x_m - p.x, K, delta) - springForce_N(p.x - map.eastX(), K, delta);
        f_env.z += springForce_N(map.northZ() - p.z, K, delta) - springForce_N(p.z - map.south_z_m, K, delta);
    }

    // Conservative forces: gravity and guidance.
    Vec3 f_cons(0.0, -P.gravity_N, 0.0);
    if (P.guidance_N > 0.0) {
        const SurfacePoint g = surfaceAt(model, p, top_level);
        const double gap = p.y - g.height_y_m;
        if (gap > 0.0) {
            const double pull = P.guidance_N * std::min(gap / P.guidance_ramp_m, 1.0) /
                                std::sqrt(1.0 + model.guidance_slope_bound * model.guidance_slope_bound);
            // -grad of the potential; the clamp only acts where the sampled
            // slope bound fell short of the true maximum, by a hair.
            f_cons += clampMagnitude(pull * Vec3(g.slope_x, -1.0, g.slope_z), P.guidance_N);
        }
    }

    // Passivity observer.
    if (state.started) {
        s.energy_J -= glm::dot(state.observed_force_N, p - state.position_m);
        s.energy_J = std::min(s.energy_J, model.energy_reserve_J);
    }
    // The controller damps along the last step's velocity, not the filtered
    // one: the filter's lag would put part of the damping force in phase with
    // the motion during a fast bounce, feeding energy instead of removing it.
    // Encoder noise in the raw velocity only weakens it (|F_pc| = |E| / (|v| dt)).
    Vec3 f_pc(0.0);
    const Vec3 v_step = dt > 0.0 ? (p - state.position_m) / dt : Vec3(0.0);
    const double v2 = glm::dot(v_step, v_step);
    if (P.passivity_observer && state.started && s.energy_J < 0.0 && dt > 0.0 &&
        v2 > kObserverMinSpeed_m_per_s * kObserverMinSpeed_m_per_s) {
        const double alpha = std::min(-s.energy_J / (v2 * dt), P.max_damping_Ns_per_m);
        f_pc = -alpha * v_step;
        out.damping_Ns_per_m = alpha;
        if (alpha > 0.0) out.flags |= kFlagDamping;
    }

    // Gain, clamp, final check.
    const double gain = std::isfinite(in.output_gain) ? std::clamp(in.output_gain, 0.0, 1.0) : 0.0;
    // The observer's damping has priority: it is clamped first and the rest
    // of the force gets what is left of the limit, so a saturated surface
    // cannot crowd out the dissipation that keeps it passive.
    bool clamped = false;
    const Vec3 damping = clampMagnitude(gain * f_pc, P.max_force_N, &clamped);
    const double room = std::max(0.0, P.max_force_N - glm::length(damping));
    const Vec3 rest = gain * (f_env + f_cons);
    const double rest_mag = glm::length(rest);
    const double scale = rest_mag > room ? room / rest_mag : 1.0;
    if (scale < 1.0 || clamped) out.flags |= kFlagClamped;
    // The sum of two clamped parts can still round an ulp past the limit;
    // the header promises <= max_force_N, so the sum is clamped too.
    out.force_N = clampMagnitude(rest * scale + damping, P.max_force_N);
    s.observed_force_N = gain * f_env * scale + damping;
    if (!isFinite(out.force_N) || !std::isfinite(s.energy_J) || !isFinite(s.stick_point_m)) {
        out.force_N = Vec3(0.0);
        out.flags = kFlagRejected;
        out.state = state;  // do not carry a poisoned state forward
        out.state.observed_force_N = Vec3(0.0);
        out.state.position_m = p;
        out.state.t_s = in.t_s;
        out.state.started = true;
        if (!std::isfinite(out.state.energy_J)) out.state.energy_J = 0.0;
        return out;
    }
    s.started = true;
    s.t_s = in.t_s;
    s.position_m = p;
    return out;
}

}  // namespace tsf::haptics
