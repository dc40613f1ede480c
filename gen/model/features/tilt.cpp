// Tilted tops: slopes from the field, resolved to corner heights. See tilt.h.
#include "gen/model/features/tilt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <sstream>
#include <utility>

#include "gen/util/error.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {

namespace {

// d height / d value (mm per value unit) at v: the secant over a millionth of
// the value range either side, so sqrt and log transfers get their local
// steepness and a clamped value (below the baseline, above value_max) gets 0.
double heightPerValue(const ValueMapping& m, double v) {
    const double range = m.value_max - m.baseline;
    if (!(range > 0)) return 0.0;
    const double dv = 1e-6 * range;
    return (m.heightMm(v + dv) - m.heightMm(v - dv)) / (2.0 * dv);
}

PlaneSlope pointsSlope(const HexField& field, const Scene& s, size_t k) {
    const BinMoments& m = field.moments[size_t(s.grid.index(s.col[k], s.row[k]))];
    const double value = s.value[k];
    if (field.statistic == BinStatistic::Density) {
        const auto rel = densityRelativeSlope(m);
        if (!rel) return {};
        const double h_mm = s.mapping.heightMm(value);
        return {h_mm * rel->x / s.pitch_mm, h_mm * rel->y / s.pitch_mm};
    }
    const auto w = weightSlope(m);
    if (!w) return {};
    const double scale = (field.statistic == BinStatistic::WeightSum ? double(m.n) : 1.0) *
                         heightPerValue(s.mapping, value) / s.pitch_mm;
    return {w->x * scale, w->y * scale};
}

PlaneSlope gradientSlope(const HexField& field, const Scene& s, size_t k) {
    const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
    const double hc = s.mapping.heightMm(s.value[k]);
    double mxx = 0, mxy = 0, myy = 0, rx = 0, ry = 0;
    for (int e = 0; e < kHexCorners; ++e) {
        int32_t nc, nr;
        hexNeighbour(s.col[k], s.row[k], e, nc, nr);
        if (!s.grid.contains(nc, nr)) continue;
        const double v = field.at(nc, nr);
        if (std::isnan(v)) continue;
        const LatticePoint o = hexCentre(s.grid, nc, nr);
        const double dx = double(o.i - c.i) * s.pitch_mm * 0.5, dy = latticeY({0, o.j - c.j}, s.pitch_mm, s.y_scale);
        const double dh = s.mapping.heightMm(v) - hc;
        mxx += dx * dx;
        mxy += dx * dy;
        myy += dy * dy;
        rx += dh * dx;
        ry += dh * dy;
    }
    const double det = mxx * myy - mxy * mxy, trace = mxx + myy;
    if (!(trace > 0) || det <= kCollinearRelDet * trace * trace) return {};
    return {(myy * rx - mxy * ry) / det, (mxx * ry - mxy * rx) / det};
}

}  // namespace

std::vector<PlaneSlope> tiltSlopes(const HexField& field, const Scene& s, TiltSource source) {
    std::vector<PlaneSlope> out(s.keptCount());
    if (source == TiltSource::None) return out;
    if (source == TiltSource::Points && int64_t(field.moments.size()) != field.grid.cellCount())
        throw InputError(field.source, 0, 0,
                         "--tilt points needs point input (--points x=COL,y=COL): a grid has no points in its cells; "
                         "use --tilt gradient");
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data) continue;
        out[k] = source == TiltSource::Points ? pointsSlope(field, s, k) : gradientSlope(field, s, k);
    }
    return out;
}

void resolveTopShapes(Scene& s, const std::vector<PlaneSlope>& slopes, double steepness,
                      const std::vector<uint8_t>& structural, const std::vector<int32_t>& centre_dz) {
    TopShapes& t = s.shapes;
    const size_t n = s.keptCount();
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    t = levelTopShapes(n, mirrored);
    if (!structural.empty()) t.structural = structural;

    const auto face_on_edge = facesOnEdges(s);  // which face lies across a directed ring edge

    const double unit_per_mm = 1.0 / s.z_snap_mm;
    // The corners are rounded to the z grid, which can steepen a fan's
    // triangle by up to a z step over the hexagon's inradius: the limit is
    // kept with that to spare, so no drawn triangle leans more than asked.
    const double max_gradient =
        std::max(0.0, std::tan(s.params.max_slope_deg * std::numbers::pi / 180.0) - s.z_snap_mm / (0.5 * s.pitch_mm));
    // No corner more than a mark's height above the height range: a tilt
    // says how the value changes across the cell, never a value far beyond
    // the data's, and the highest pillars can still lean (by as much as the
    // orientation triangle stands above its region).
    const int64_t ceiling_units =
        snapUnits(s.mapping.max_height_mm, s.z_snap_mm) + snapUnits(s.params.marks.triangle_height_mm, s.z_snap_mm);
    for (size_t k = 0; k < n; ++k) {
        if (s.kind[k] != CellKind::Data || t.structural[k]) continue;
        if (!s.drawn_by_face.empty() && s.drawn_by_face[k]) continue;
        double gx = slopes[k].x * steepness, gy = slopes[k].y * steepness;
        if (!std::isfinite(gx) || !std::isfinite(gy) || (gx == 0 && gy == 0)) continue;
        const double gradient = std::hypot(gx, gy);
        if (gradient > max_gradient) {
            gx *= max_gradient / gradient;
            gy *= max_gradient / gradient;
            ++t.cells_slope_limited;
        }
        const int64_t h = mirrored ? s.bottom[k] - s.floor_units : s.top[k] - s.floor_units;  // height above the floor, units
        // Mirrored, the floor lies at or below the bed: no corner below the bed either.
        const int64_t above_bed = mirrored ? s.bottom[k] : h;
        const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
        double want[kHexCorners];
        int64_t lo[kHexCorners], hi[kHexCorners];
        for (int e = 0; e < kHexCorners; ++e) {
            const LatticePoint p = hexCorner(s.grid, s.col[k], s.row[k], e);
            const double dx = double(p.i - c.i) * s.pitch_mm * 0.5, dy = latticeY({0, p.j - c.j}, s.pitch_mm, s.y_scale);
            want[e] = (gx * dx + gy * dy) * unit_per_mm;
            lo[e] = -above_bed;          // no corner below the floor (the bed)
            hi[e] = ceiling_units - h;   // nor above the height range
        }
        // An edge against a mark's face: both its ends stay on the side of the
        // face's top (and mirrored bottom) that the centre is on, so the two
        // never cross (a face's ring has no crossing points).
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t j = s.keptNeighbour(k, e);
            if (j < 0 || s.drawn_by_face.empty() || !s.drawn_by_face[size_t(j)]) continue;
            const int64_t v = hexCornerId(s.grid, s.col[k], s.row[k], e);
            const int64_t w = hexCornerId(s.grid, s.col[k], s.row[k], (e + 1) % kHexCorners);
            const auto across = face_on_edge.find({w, v});
            for (int end : {e, (e + 1) % kHexCorners}) {
                auto keepSide = [&](int64_t mine, int64_t theirs) {
                    if (mine > theirs) lo[end] = std::max(lo[end], theirs - mine);
                    else if (mine < theirs) hi[end] = std::min(hi[end], theirs - mine);
                    else lo[end] = hi[end] = 0;
                };
                if (across == face_on_edge.end()) {
                    lo[end] = hi[end] = 0;
                    continue;
                }
                const PlanarFace& f = s.faces.faces[size_t(across->second)];
                keepSide(s.top[k], s.faceTop(f));
                if (mirrored) keepSide(s.bottom[k], s.faceBottom(f));
            }
        }
        double lambda = 1.0;
        for (int e = 0; e < kHexCorners; ++e) {
            if (want[e] < 0) lambda = std::min(lambda, double(lo[e]) / want[e]);
            if (want[e] > 0) lambda = std::min(lambda, double(hi[e]) / want[e]);
        }
        lambda = std::max(0.0, lambda);
        bool any = false;
        for (int e = 0; e < kHexCorners; ++e) {
            const int64_t dz = std::clamp<int64_t>(std::llround(lambda * want[e]), lo[e], hi[e]);
            t.top_dz[k][size_t(e)] = int32_t(dz);
            if (mirrored) t.bottom_dz[k][size_t(e)] = int32_t(dz);
            any = any || dz != 0;
        }
        if (lambda < 1.0) {
            ++t.cells_clamped;
            t.cells_flat_clamped += !any;
        }
        if (any) {
            ++t.cells_tilted;
            t.slope_x[k] = lambda * gx;
            t.slope_y[k] = lambda * gy;
        }
    }

    // Class textures' dimples and bumps: the centre moves, the corners stay.
    if (!centre_dz.empty())
        for (size_t k = 0; k < n; ++k) {
            if (centre_dz[k] == 0 || s.kind[k] != CellKind::Data || t.structural[k]) continue;
            if (!s.drawn_by_face.empty() && s.drawn_by_face[k]) continue;
            t.top_centre_dz[k] = centre_dz[k];
            if (mirrored) t.bottom_centre_dz[k] = centre_dz[k];
        }

    // Structural cells: a cone into the top (and, mirrored, into the bottom).
    const int64_t base_units = snapUnits(s.params.base_mm, s.z_snap_mm);
    t.dimple_units = mirrored ? std::min<int64_t>(s.nodata_pit_units, base_units / 4) : s.nodata_pit_units;
    if (t.dimple_units > 0)
        for (size_t k = 0; k < n; ++k) {
            if (!t.structural[k]) continue;
            t.top_centre_dz[k] = int32_t(-t.dimple_units);
            if (mirrored) t.bottom_centre_dz[k] = int32_t(t.dimple_units);
            ++t.cells_textured;
        }

    // Mirrored: every pillar keeps the same thickness, which must now cover
    // the steps between neighbouring corners, not only between centres.
    if (mirrored && t.cells_tilted > 0) {
        int64_t max_step = s.mirror_thickness_units - base_units;
        auto heightAt = [&s](size_t k, int64_t id) {
            return s.kind[k] == CellKind::NoData ? 0 : cornerBottomAt(s, k, id);
        };
        for (size_t k = 0; k < n; ++k)
            for (int e = 0; e < kHexCorners; ++e) {
                const int32_t j = s.keptNeighbour(k, e);
                if (j < 0 || size_t(j) < k) continue;
                for (int end : {e, (e + 1) % kHexCorners}) {
                    const int64_t id = hexCornerId(s.grid, s.col[k], s.row[k], end);
                    max_step = std::max<int64_t>(max_step, std::llabs(heightAt(k, id) - heightAt(size_t(j), id)));
                }
            }
        const int64_t grow = max_step + base_units - s.mirror_thickness_units;
        if (grow > 0) {
            for (int64_t& top : s.top) top += grow;
            s.mirror_thickness_units += grow;
        }
    }
    if (t.cells_slope_limited > 0) {
        std::ostringstream note;
        note.precision(3);
        note << "tilt: " << t.cells_slope_limited << " tops would lean more than " << s.params.max_slope_deg
             << " degrees and lean that much (--max-slope)";
        s.notes.push_back(note.str());
    }
    if (t.cells_clamped > 0) {
        std::ostringstream note;
        note << "tilt: " << t.cells_clamped << " cells tilt less than their plane asks so no corner goes below the floor "
             << "or above the height range, or crosses an orientation mark (" << t.cells_flat_clamped
             << " of them stay level)";
        s.notes.push_back(note.str());
    }
    buildTopShapeGeometry(s);
}

}  // namespace tsf
