#include "verify/attachment_readback.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "gen/model/attachments.h"
#include "verify/readback.h"
#include "gen/util/number_format.h"

namespace tsf {
AttachmentReadbackResult readBackAttachments(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster,
                                             size_t max_offenders) {
    AttachmentReadbackResult r;
    const std::vector<ProbeSet> sets = sceneProbes(scene);
    if (sets.empty()) return r;
    const auto t0 = std::chrono::steady_clock::now();
    const Bounds b = meshBounds(mesh);
    const double z_above = (std::isfinite(b.max.z) ? b.max.z : 0.0) + 1.0;
    double z_extent = 0;
    for (const ProbeSet& set : sets)
        for (const SurfaceProbe& p : set.probes) z_extent = std::max(z_extent, std::fabs(p.z_mm));
    const double tolerance = 0.5 * scene.z_snap_mm + z_extent * kFloat32UnitRoundoff;

    for (const ProbeSet& set : sets) {
        Check c;
        c.id = set.name + "_read_back";
        c.title = set.title;
        c.unit = "mm";
        size_t n = 0, surfaces = 0;
        double max_error = 0;
        for (const SurfaceProbe& p : set.probes) {
            ++n;
            const auto hit = caster.firstHit({p.x_mm, p.y_mm, z_above}, {0, 0, -1});
            if (p.empty) {
                if (hit) {
                    ++c.count;
                    if (c.worst.size() < max_offenders)
                        c.worst.push_back({hit->point_mm, hit->point_mm.z,
                                           p.what + ": material at z = " + formatSignificant(hit->point_mm.z) +
                                               " mm where the Scene cuts through the model"});
                }
                continue;
            }
            ++surfaces;
            if (!hit) {
                ++c.count;
                if (c.worst.size() < max_offenders)
                    c.worst.push_back({{p.x_mm, p.y_mm, p.z_mm}, std::nan(""), p.what + ": the ray met no surface"});
                continue;
            }
            const double err = hit->point_mm.z - p.z_mm;
            max_error = std::max(max_error, std::fabs(err));
            // On a slope, the float32 rounding of the surface's x and y.
            const double shift = std::sqrt(2.0) * std::max(std::fabs(p.x_mm), std::fabs(p.y_mm)) * kFloat32UnitRoundoff;
            if (std::fabs(err) > tolerance + p.slope * shift) {
                ++c.count;
                if (c.worst.size() < max_offenders)
                    c.worst.push_back({hit->point_mm, err, p.what + " at z = " + formatSignificant(hit->point_mm.z) +
                                                               " mm, the Scene says " + formatSignificant(p.z_mm) + " mm"});
            }
        }
        if (n == 0) continue;
        r.probes_checked += n;
        r.max_error_mm = std::max(r.max_error_mm, max_error);
        c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
        c.stage = "attachment_readback";
        c.note = std::to_string(n) + " places (" + std::to_string(surfaces) + " surfaces, " +
                 std::to_string(n - surfaces) + " cuts); max error " + formatSignificant(max_error) + " mm, tolerance " +
                 formatSignificant(tolerance) + " mm";
        r.checks.push_back(std::move(c));
    }
    const Stage stage{"attachment_readback",
                      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()};
    for (Check& c : r.checks) c.time_ms = stage.time_ms;
    r.stages.push_back(stage);
    return r;
}

}  // namespace tsf
