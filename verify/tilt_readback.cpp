// readBackTilt: rays on the spokes of each tilted top. See tilt_readback.h.
#include "verify/tilt_readback.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <string>

#include "verify/detail/format.h"
#include "verify/readback.h"

namespace tsf {
namespace {

constexpr double kRayStartClearanceMm = 1.0;  // as readback.cpp: any positive distance off the mesh

struct Measured {
    bool ok = false;
    double gx = 0, gy = 0;
};

}  // namespace

TiltReadbackResult readBackTilt(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster) {
    TiltReadbackResult r;
    if (scene.shapes.cells_tilted == 0) return r;
    const auto t0 = std::chrono::steady_clock::now();
    TiltReadbackFigures& f = r.figures;
    const Bounds b = meshBounds(mesh);
    const double z_above = b.max.z + kRayStartClearanceMm, z_below = b.min.z - kRayStartClearanceMm;
    const double float32_mm = std::max(std::fabs(b.max.z), std::fabs(b.min.z)) * kFloat32UnitRoundoff;
    const bool mirrored = scene.params.bottom == Bottom::Mirrored;
    // The shortest spoke, half the distance to the nearest corner: a top
    // or bottom corner of a hexagon squashed north-south, a side corner of
    // one stretched (hex_grid.h); half the circumradius of a regular one.
    const double r_mm = scene.pitch_mm / kSqrt3 * scene.y_scale;
    const double spoke_mm = 0.5 * std::min(r_mm, std::hypot(0.5 * scene.pitch_mm, 0.5 * r_mm));
    std::vector<std::pair<double, std::string>> bad;

    // The slope of the surface met from above (top) or below (bottom).
    auto measure = [&](size_t k, bool top) {
        Measured m;
        const int32_t c = scene.col[k], row = scene.row[k];
        const Vec3 centre = scene.point(hexCentre(scene.grid, c, row), 0);
        auto zAt = [&](double x, double y, double& z) {
            const auto hit = top ? caster.firstHit({x, y, z_above}, {0, 0, -1}) : caster.firstHit({x, y, z_below}, {0, 0, 1});
            if (!hit) return false;
            z = hit->point_mm.z;
            return true;
        };
        double zc = 0;
        if (!zAt(centre.x, centre.y, zc)) return m;
        // The least-squares plane through the centre and the six spokes'
        // ends (a stretched lattice's spokes differ in length: hex_grid.h).
        double sx = 0, sy = 0, mxx = 0, mxy = 0, myy = 0;
        for (int e = 0; e < kHexCorners; ++e) {
            const Vec3 corner = scene.point(hexCorner(scene.grid, c, row, e), 0);
            const double dx = 0.5 * (corner.x - centre.x), dy = 0.5 * (corner.y - centre.y);
            double z = 0;
            if (!zAt(centre.x + dx, centre.y + dy, z)) return m;
            sx += (z - zc) * dx;
            sy += (z - zc) * dy;
            mxx += dx * dx;
            mxy += dx * dy;
            myy += dy * dy;
        }
        const double det = mxx * myy - mxy * mxy;
        m.ok = det > 0;
        m.gx = (myy * sx - mxy * sy) / det;
        m.gy = (mxx * sy - mxy * sx) / det;
        return m;
    };

    for (size_t k = 0; k < scene.keptCount(); ++k) {
        const double gx = scene.shapes.slope_x[k], gy = scene.shapes.slope_y[k];
        if (gx == 0 && gy == 0) continue;
        ++f.cells_checked;
        const double g = std::hypot(gx, gy);
        f.max_slope = std::max(f.max_slope, g);
        const double tol = 4.0 * (0.25 * scene.z_snap_mm + g * kXYSnapMm + 2.0 * float32_mm) / (2.0 * spoke_mm);
        f.max_tolerance = std::max(f.max_tolerance, tol);
        Measured faces[2];
        for (int part = 0; part < (mirrored ? 2 : 1); ++part) {
            const bool top = part == 0;
            const Measured m = measure(k, top);
            faces[part] = m;
            const std::string where = "cell (col " + std::to_string(scene.col[k]) + ", row " +
                                      std::to_string(scene.row[k]) + ") " + (top ? "top" : "bottom");
            if (!m.ok) {
                ++f.missed;
                bad.push_back({1e300, where + ": a ray met no surface"});
                continue;
            }
            const double err = std::hypot(m.gx - gx, m.gy - gy);
            (top ? f.max_error_top : f.max_error_bottom) = std::max(top ? f.max_error_top : f.max_error_bottom, err);
            if (err > tol) {
                ++f.over_tolerance;
                bad.push_back({err, where + ": slope (" + detail::fmtNum(m.gx) + ", " + detail::fmtNum(m.gy) +
                                        ") mm/mm, expected (" + detail::fmtNum(gx) + ", " + detail::fmtNum(gy) +
                                        "), tolerance " + detail::fmtNum(tol)});
            }
        }
        if (mirrored && faces[0].ok && faces[1].ok)
            f.max_top_bottom = std::max(f.max_top_bottom, std::hypot(faces[0].gx - faces[1].gx, faces[0].gy - faces[1].gy));
    }
    std::sort(bad.begin(), bad.end(), [](const auto& a, const auto& b2) { return a.first > b2.first; });
    for (size_t i = 0; i < bad.size() && i < 10; ++i) f.worst.push_back(bad[i].second);

    const Stage stage{"tilt_readback", std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count()};
    r.stages.push_back(stage);
    Check c;
    c.id = "tilts_read_back";
    c.title = "every tilted top (and mirrored bottom) leans as its plane";
    c.unit = "mm/mm";
    c.stage = stage.name;
    c.time_ms = stage.time_ms;
    c.count = int64_t(f.missed + f.over_tolerance);
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.note = std::to_string(f.cells_checked) + " tilted cells; max slope error " + detail::fmtNum(f.max_error_top) +
             " (top)" + (mirrored ? ", " + detail::fmtNum(f.max_error_bottom) + " (bottom)" : std::string()) +
             ", tolerance up to " + detail::fmtNum(f.max_tolerance) + " mm/mm";
    r.checks.push_back(std::move(c));
    return r;
}

}  // namespace tsf
