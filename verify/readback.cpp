// readBack: vertical rays at cell centres. See readback.h.
#include "verify/readback.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

#include "verify/detail/format.h"
#include "gen/util/workers.h"
#include "gen/model/attachments.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {
namespace {
// Half the xy grid (kXYSnapMm): far enough to step off an edge onto the
// level beside it, too little to reach another cell.
constexpr double kEdgeNudgeMm = 0.0005;
}  // namespace

namespace {

using detail::fmtMm;
using detail::fmtNum;

// How far outside the mesh's bounding box the rays start (mm). Any positive
// distance works; 1 mm keeps the origin clearly off every surface.
constexpr double kRayStartClearanceMm = 1.0;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

// Orders surfaces worst first: missed rays, then the largest |error|.
bool worse(const CellReadback& a, const CellReadback& b) {
    const bool am = std::isnan(a.measured_mm), bm = std::isnan(b.measured_mm);
    if (am != bm) return am;
    return std::fabs(a.error_mm) > std::fabs(b.error_mm);
}

std::string describe(const CellReadback& c) {
    std::string s = "cell (col " + std::to_string(c.col) + ", row " + std::to_string(c.row) + ") " + c.surface + ": ";
    if (std::isnan(c.measured_mm)) return s + "no surface found (expected at z = " + fmtMm(c.expected_mm) + " mm)";
    s += "z = " + fmtMm(c.measured_mm) + " mm, expected " + fmtMm(c.expected_mm) + " mm (" +
         (c.error_mm >= 0 ? "+" : "") + fmtNum(c.error_mm) + " mm)";
    if (!std::isnan(c.value_error))
        s += "; value " + fmtNum(c.value) + " reads as " + fmtNum(c.value_read);
    return s;
}

}  // namespace

ReadbackResult readBack(const Mesh& mesh, const Scene& scene, const ColumnGrid& caster, const ReadbackOptions& options) {
    ReadbackResult r;
    ReadbackFigures& f = r.figures;
    const auto t0 = std::chrono::steady_clock::now();

    const Bounds b = meshBounds(mesh);
    const bool have_mesh = std::isfinite(b.min.z) && std::isfinite(b.max.z);
    const double z_above = (have_mesh ? b.max.z : 0.0) + kRayStartClearanceMm;
    const double z_below = (have_mesh ? b.min.z : 0.0) - kRayStartClearanceMm;

    const bool mirrored = scene.params.bottom == Bottom::Mirrored;
    // Height 0 on the top and, mirrored, on the underside (floor_units: at
    // or below the bed, where a mirrored model's lowest cell stands).
    const double top_zero_mm = scene.zMm(mirrored ? scene.mirror_thickness_units + scene.floor_units : scene.floor_units);
    const double bottom_zero_mm = scene.zMm(mirrored ? scene.floor_units : 0);
    const ValueMapping& map = scene.mapping;
    const bool has_range = map.value_max > map.baseline;

    double z_extent = 0;  // largest |z| a surface can have: the float32 rounding scales with it
    for (size_t k = 0; k < scene.keptCount(); ++k)
        z_extent = std::max({z_extent, std::fabs(scene.zMm(scene.top[k])), std::fabs(scene.zMm(scene.bottom[k]))});
    f.height_step_tolerance_mm = options.height_tolerance_mm > 0 ? options.height_tolerance_mm : 0.5 * scene.z_snap_mm;
    // On a tilted or dimpled top the float32 rounding of x and y moves the
    // surface up or down by its slope times the shift (up to sqrt 2 x the
    // largest |x| or |y| times the unit roundoff). The steepest slope a cell
    // has is at most its largest rise from the centre to a corner over half
    // the pitch (a corner is at least that far from the centre along the slope).
    int64_t rise = 0;
    if (!scene.shapes.empty())
        for (size_t k = 0; k < scene.keptCount(); ++k) {
            if (!isShaped(scene.shapes, k)) continue;
            for (int e = 0; e < kHexCorners; ++e) {
                rise = std::max(rise, std::abs(cornerTop(scene, k, e) - centreTop(scene, k)));
                if (mirrored) rise = std::max(rise, std::abs(cornerBottom(scene, k, e) - centreBottom(scene, k)));
            }
        }
    const double xy_extent = have_mesh ? std::max({std::fabs(b.min.x), std::fabs(b.max.x), std::fabs(b.min.y), std::fabs(b.max.y)}) : 0.0;
    const double slope = scene.zMm(rise) / (0.5 * scene.pitch_mm);
    f.float32_rounding_mm = (z_extent + slope * std::sqrt(2.0) * xy_extent) * kFloat32UnitRoundoff;
    f.tolerance_mm = f.height_step_tolerance_mm + f.float32_rounding_mm;

    // A cut into the flat bottom centred on a cell (a half's pin hole): the
    // bottom there is the cut's apex.
    const std::vector<BottomHole> holes = sceneBottomHoles(scene);
    const auto holeApex = [&](size_t k) -> std::optional<int64_t> {
        for (const BottomHole& h : holes)
            if (h.centre == hexCentre(scene.grid, scene.col[k], scene.row[k])) return h.apex_units;
        return std::nullopt;
    };

    const size_t keep = options.max_offenders;
    auto measure = [&](size_t k, bool top) {
        CellReadback c;
        c.col = scene.col[k];
        c.row = scene.row[k];
        // The centre, or where a pillar the notch cuts is read (gen/model/features/marks.h).
        const Vec3 centre = scene.point(readPoint(scene, k), 0);
        c.x_mm = centre.x;
        c.y_mm = centre.y;
        c.surface = top ? "top" : "bottom";
        // Under the orientation triangle the top stands higher by the mark's
        // height and carries no value.
        const int64_t raise = top ? markRaiseAtCentre(scene, k) : 0;
        // A tilted top passes through its value at the centre; a structural
        // cell's dimple is lowest there and carries no value (gen/model/features/top_shapes.h).
        c.expected_mm = scene.zMm(top ? centreTop(scene, k) + raise : holeApex(k).value_or(centreBottom(scene, k)));
        const bool no_value = raise || isStructural(scene.shapes, k);
        c.value = no_value ? std::numeric_limits<double>::quiet_NaN() : scene.value[k];
        const auto hit = top ? caster.firstHit({c.x_mm, c.y_mm, z_above}, {0, 0, -1})
                             : caster.firstHit({c.x_mm, c.y_mm, z_below}, {0, 0, 1});
        const double nan = std::numeric_limits<double>::quiet_NaN();
        c.measured_mm = hit ? hit->point_mm.z : nan;
        c.error_mm = c.measured_mm - c.expected_mm;
        c.value_read = nan;
        c.value_error = nan;
        const bool carries_data = top || mirrored;
        if (hit && carries_data && has_range && !std::isnan(c.value)) {
            const double h = top ? c.measured_mm - top_zero_mm : c.measured_mm - bottom_zero_mm;
            c.value_read = map.valueAt(h);
            c.value_error = c.value_read - std::clamp(c.value, map.baseline, map.value_max);
        }
        return c;
    };

    // The cells in contiguous chunks, one per thread. Each keeps its sums and
    // its `keep` worst surfaces (a bounded heap, ties to the earlier surface),
    // so memory does not grow with the model.
    struct Ranked {
        size_t seq;  // 2 * cell + (bottom ? 1 : 0)
        CellReadback c;
    };
    auto rankedWorse = [](const Ranked& a, const Ranked& b) {
        if (worse(a.c, b.c)) return true;
        if (worse(b.c, a.c)) return false;
        return a.seq < b.seq;
    };
    struct Part {
        size_t surfaces = 0, missed = 0, over = 0, n_err = 0, n_verr = 0;
        double sum_err = 0, sum_verr = 0, max_err = 0, max_verr = 0;
        std::vector<Ranked> worst;  // heap: front = the least bad kept
    };
    const unsigned workers = detail::workerCount(0);
    std::vector<Part> parts(workers);
    const size_t cells = scene.keptCount();
    auto work = [&](unsigned w) {
        Part& p = parts[w];
        for (size_t k = cells * w / workers; k < cells * (w + 1) / workers; ++k)
            for (bool top : {true, false}) {
                Ranked r{2 * k + (top ? 0 : 1), measure(k, top)};
                const CellReadback& c = r.c;
                ++p.surfaces;
                if (std::isnan(c.measured_mm)) {
                    ++p.missed;
                } else {
                    const double e = std::fabs(c.error_mm);
                    p.max_err = std::max(p.max_err, e);
                    p.sum_err += e;
                    ++p.n_err;
                    if (e > f.tolerance_mm) ++p.over;
                    if (!std::isnan(c.value_error)) {
                        p.max_verr = std::max(p.max_verr, std::fabs(c.value_error));
                        p.sum_verr += std::fabs(c.value_error);
                        ++p.n_verr;
                    }
                }
                if (keep == 0) continue;
                if (p.worst.size() < keep) {
                    p.worst.push_back(std::move(r));
                    std::push_heap(p.worst.begin(), p.worst.end(), rankedWorse);
                } else if (rankedWorse(r, p.worst.front())) {
                    std::pop_heap(p.worst.begin(), p.worst.end(), rankedWorse);
                    p.worst.back() = std::move(r);
                    std::push_heap(p.worst.begin(), p.worst.end(), rankedWorse);
                }
            }
    };
    detail::runOnWorkers(workers, [&](unsigned w, const auto&) { work(w); });

    double sum_err = 0, sum_verr = 0;
    size_t n_err = 0, n_verr = 0;
    f.max_error_mm = 0;
    f.max_value_error = 0;
    std::vector<Ranked> all;
    for (Part& p : parts) {
        f.surfaces_checked += p.surfaces;
        f.missed += p.missed;
        f.over_tolerance += p.over;
        sum_err += p.sum_err;
        sum_verr += p.sum_verr;
        n_err += p.n_err;
        n_verr += p.n_verr;
        f.max_error_mm = std::max(f.max_error_mm, p.max_err);
        f.max_value_error = std::max(f.max_value_error, p.max_verr);
        for (Ranked& r : p.worst) all.push_back(std::move(r));
    }
    f.cells_checked = scene.keptCount();
    f.mean_error_mm = n_err ? sum_err / double(n_err) : 0.0;
    f.mean_value_error = n_verr ? sum_verr / double(n_verr) : 0.0;
    if (!n_verr) f.max_value_error = f.mean_value_error = std::numeric_limits<double>::quiet_NaN();

    std::sort(all.begin(), all.end(), rankedWorse);
    if (all.size() > keep) all.resize(keep);
    f.worst.clear();
    for (Ranked& r : all) f.worst.push_back(std::move(r.c));

    const Stage values_stage{"readback", msSince(t0)};
    r.stages.push_back(values_stage);
    {
        Check c;
        c.id = "values_read_back";
        c.title = "every cell at its height";
        c.unit = "mm";
        c.stage = values_stage.name;
        c.time_ms = values_stage.time_ms;
        c.count = int64_t(f.missed + f.over_tolerance);
        c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
        for (const CellReadback& w : f.worst) {
            const bool bad = std::isnan(w.measured_mm) || std::fabs(w.error_mm) > f.tolerance_mm;
            if (!bad) break;
            c.worst.push_back({{w.x_mm, w.y_mm, std::isnan(w.measured_mm) ? w.expected_mm : w.measured_mm}, w.error_mm,
                               describe(w)});
        }
        c.note = std::to_string(f.surfaces_checked) + " surfaces of " + std::to_string(f.cells_checked) +
                 " cells; max error " + fmtNum(f.max_error_mm) + " mm, tolerance " + fmtNum(f.tolerance_mm) + " mm";
        if (f.missed) c.note += "; " + std::to_string(f.missed) + " rays met no surface";
        r.checks.push_back(std::move(c));
    }

    // Grid cells that are not kept must be empty.
    const auto t1 = std::chrono::steady_clock::now();
    Check out;
    out.id = "outside_cells_empty";
    out.title = "no material outside the kept cells";
    out.status = CheckStatus::Pass;
    if (options.check_outside_cells && int64_t(scene.kept_index.size()) == scene.grid.cellCount()) {
        for (int32_t row = 0; row < scene.grid.rows; ++row) {
            for (int32_t col = 0; col < scene.grid.cols; ++col) {
                if (scene.keptAt(col, row) >= 0) continue;
                ++f.outside_cells_checked;
                const Vec3 centre = scene.point(hexCentre(scene.grid, col, row), 0);
                const auto hit = caster.firstHit({centre.x, centre.y, z_above}, {0, 0, -1});
                // On an attachment (gen/model/attachments.h: the legend's plate,
                // the scale, the orientation tab) a culled cell meets its top;
                // on an edge between two of its levels (a riser, the
                // triangle's side) either one's.
                bool on_attachment = false;
                for (const double dx : {0.0, -kEdgeNudgeMm, kEdgeNudgeMm})
                    for (const double dy : {0.0, -kEdgeNudgeMm, kEdgeNudgeMm})
                        for (const int64_t top : attachmentTopsAt(scene, centre.x + dx, centre.y + dy))
                            on_attachment = on_attachment ||
                                            (hit && std::fabs(hit->point_mm.z - scene.zMm(top)) <= scene.z_snap_mm / 2);
                if (on_attachment) continue;
                if (!hit) continue;
                ++f.outside_cells_hit;
                if (out.worst.size() < options.max_offenders)
                    out.worst.push_back({hit->point_mm, hit->point_mm.z,
                                         "cell (col " + std::to_string(col) + ", row " + std::to_string(row) +
                                             ") is not part of the model but has a surface at z = " +
                                             fmtMm(hit->point_mm.z) + " mm"});
            }
        }
        out.count = int64_t(f.outside_cells_hit);
        out.status = out.count ? CheckStatus::Fail : CheckStatus::Pass;
        out.unit = "mm";
        out.note = std::to_string(f.outside_cells_checked) + " cells outside the model checked";
    } else {
        out.status = CheckStatus::Skipped;
        out.note = "skipped";
    }
    const Stage outside_stage{"outside_cells", msSince(t1)};
    r.stages.push_back(outside_stage);
    out.stage = outside_stage.name;
    out.time_ms = outside_stage.time_ms;
    r.checks.push_back(std::move(out));
    return r;
}

}  // namespace tsf
