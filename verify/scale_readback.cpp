#include "verify/scale_readback.h"

#include <chrono>
#include <cmath>
#include <sstream>

#include "verify/readback.h"

namespace tsf {
namespace {

std::string mm(double v) {
    std::ostringstream o;
    o.precision(6);
    o << v;
    return o.str();
}

}  // namespace

ScaleReadbackResult readBackScale(const Mesh& mesh, const Scene& scene, const TriangleBvh& caster) {
    ScaleReadbackResult r;
    Check c;
    c.id = "scale_read_back";
    c.title = "every step of the tactile scale at its value's height";
    c.unit = "mm";
    if (!scene.scale) {
        c.status = CheckStatus::Skipped;
        c.note = "no tactile scale";
        r.checks.push_back(std::move(c));
        return r;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const SceneScale& sc = *scene.scale;
    const Bounds b = meshBounds(mesh);
    const double z_above = (std::isfinite(b.max.z) ? b.max.z : 0.0) + 1.0;
    double z_extent = scene.zMm(sc.foot_top_units);
    for (const ScaleStep& st : sc.steps) z_extent = std::max(z_extent, scene.zMm(st.top_units));
    const double tolerance = 0.5 * scene.z_snap_mm + z_extent * kFloat32UnitRoundoff;

    auto probe = [&](double x, double y, int64_t expected, const std::string& what) {
        ++r.surfaces_checked;
        const double want = scene.zMm(expected);
        const auto hit = caster.firstHit({x, y, z_above}, {0, 0, -1});
        if (!hit) {
            ++c.count;
            c.worst.push_back({{x, y, want}, std::nan(""), what + ": the ray met no surface"});
            return;
        }
        const double err = hit->point_mm.z - want;
        r.max_error_mm = std::max(r.max_error_mm, std::fabs(err));
        if (std::fabs(err) > tolerance) {
            ++c.count;
            c.worst.push_back({hit->point_mm, err, what + " at z = " + mm(hit->point_mm.z) + " mm, the Scene says " +
                                                       mm(want) + " mm"});
        }
    };
    probe(0.5 * (sc.x0_mm + sc.xs_mm), 0.5 * (sc.y0_mm + sc.y1_mm), sc.foot_top_units, "the scale's foot (the floor)");
    for (const ScaleStep& st : sc.steps)
        probe(0.5 * (sc.xs_mm + sc.x1_mm), 0.5 * (st.y_south_mm + st.y_north_mm), st.top_units,
              "the step for " + mm(st.value));
    const Stage stage{"scale_readback",
                      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()};
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.stage = stage.name;
    c.time_ms = stage.time_ms;
    c.note = std::to_string(sc.steps.size()) + " steps every " + mm(sc.step) + " and the foot; max error " +
             mm(r.max_error_mm) + " mm, tolerance " + mm(tolerance) + " mm";
    r.checks.push_back(std::move(c));
    r.stages.push_back(stage);
    return r;
}

}  // namespace tsf
