// buildScene: from a HexField and parameters to the model description.
//
// Height rules (the OpenSCAD library mirrors them; keep both in step):
//   h_mm      = mapping.heightMm(value)              (0 for no-data cells)
//   h_units   = snapUnits(h_mm, z_snap)
//   flat:     bottom = 0,        top = snapUnits(base_mm) + h_units
//   mirrored: bottom = h_units - S,  top = bottom + T,
//             S = the least h_units of the kept cells with data (the model
//                 stands on z = 0; no-data cells count as 0 after it),
//                 less a class texture's relief (tilted tops: the
//                 lowest corner once they are resolved),
//             T = max |h_units(a) - h_units(b)| over neighbouring kept cells
//                 + snapUnits(base_mm)
#include "gen/model/build_scene.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <deque>
#include <limits>
#include <sstream>

#include "gen/field/resample.h"
#include "gen/model/concave_hull.h"
#include "gen/model/convex_hull.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/class_textures.h"
#include "gen/model/features/halves.h"
#include "gen/model/features/legend_join.h"
#include "gen/model/features/legend_scene.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/orientation_tab.h"
#include "gen/model/features/tiles.h"
#include "gen/model/features/tilt.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {

namespace {

// Limits that keep every lattice coordinate and height comfortably inside
// int64 arithmetic and the model inside what a printer can make.
constexpr int32_t kMaxGridSide = 100000;
constexpr double kMinPitchMm = 0.05;      // 50 xy snap steps: snapping cannot distort a hexagon
constexpr double kMaxModelMm = 100000.0;  // 100 m: anything larger is a unit mistake
constexpr double kMinSnapMm = 1e-6;
constexpr double kMaxSnapMm = 1.0;

void requireFinitePositive(double v, const char* name, bool allow_zero = false) {
    if (!std::isfinite(v) || v < 0 || (!allow_zero && v == 0)) {
        std::ostringstream s;
        s << name << " must be a finite number " << (allow_zero ? ">= 0" : "> 0") << " (got " << v << ")";
        throw InputError(s.str());
    }
}

void validate(const HexField& field, const SceneParams& p) {
    if (field.grid.cols <= 0 || field.grid.rows <= 0)
        throw InputError(field.source, 0, 0, "the field is empty (no rows or no columns)");
    if (field.grid.cols > kMaxGridSide || field.grid.rows > kMaxGridSide)
        throw InputError(field.source, 0, 0, "the hex grid is larger than " + std::to_string(kMaxGridSide) + " cells per side");
    if (int64_t(field.values.size()) != field.grid.cellCount())
        throw InputError(field.source, 0, 0, "internal: field value count does not match its grid");
    requireFinitePositive(p.pitch_mm, "cell size (pitch, mm)", true);
    if (p.pitch_mm == 0) {
        requireFinitePositive(p.fit_width_mm, "fit width (mm)");
        requireFinitePositive(p.fit_depth_mm, "fit depth (mm)");
    }
    requireFinitePositive(p.max_height_mm, "maximum height (mm)", true);
    requireFinitePositive(p.base_mm, "base thickness (mm)");
    if (!(p.z_snap_mm >= kMinSnapMm && p.z_snap_mm <= kMaxSnapMm)) {
        std::ostringstream s;
        s << "z snap step must be between " << kMinSnapMm << " and " << kMaxSnapMm << " mm (got " << p.z_snap_mm << ")";
        throw InputError(s.str());
    }
    if (p.base_mm < p.z_snap_mm)
        throw InputError("base thickness must be at least one z snap step (" + std::to_string(p.z_snap_mm) + " mm)");
    if (p.max_height_mm + 2 * p.base_mm > kMaxModelMm) throw InputError("model height is larger than 100 m; check the units (mm)");
    if (p.baseline_mode == BaselineMode::Value && !std::isfinite(p.baseline_value))
        throw InputError("baseline value must be finite");
    if (p.value_max && !std::isfinite(*p.value_max)) throw InputError("value at maximum height must be finite");
    if (!std::isfinite(p.steepness) || p.steepness <= 0)
        throw InputError("steepness must be a finite number > 0 (got " + std::to_string(p.steepness) + ")");
    if (!(p.max_slope_deg > 0 && p.max_slope_deg <= kMaxSlopeLimitDeg))
        throw InputError("--max-slope must be more than 0 and at most " + std::to_string(int(kMaxSlopeLimitDeg)) +
                         " degrees (got " + std::to_string(p.max_slope_deg) +
                         "): a steeper top is a wall to a finger and a blade to a nozzle");
    if (p.halves && p.bottom != Bottom::Mirrored)
        throw InputError("--halves cuts a mirrored model at its slab; a flat model already prints without supports. "
                         "Add --mirror, or leave out --halves");
    if (p.halves && p.tilt != TiltSource::None)
        throw InputError("--halves does not combine with --tilt yet (a tilted underside has no flat slab to cut "
                         "at); leave out one of them");
}

ValueMapping resolveMapping(const HexField& field, const SceneParams& p, std::vector<std::string>& notes) {
    double vmin = INFINITY, vmax = -INFINITY;
    for (double v : field.values) {
        if (std::isnan(v)) continue;
        if (!std::isfinite(v))
            throw InputError(field.source, 0, 0, "the field holds an infinite value; values must be finite numbers");
        vmin = std::min(vmin, v);
        vmax = std::max(vmax, v);
    }
    if (!(vmin <= vmax)) throw InputError(field.source, 0, 0, "the field has no data: every cell is empty (NaN / no data)");
    ValueMapping m;
    m.transfer = p.transfer;
    m.max_height_mm = p.max_height_mm;
    switch (p.baseline_mode) {
        case BaselineMode::Zero: m.baseline = 0.0; break;
        case BaselineMode::Min: m.baseline = vmin; break;
        case BaselineMode::Value: m.baseline = p.baseline_value; break;
        default: m.baseline = vmin >= 0 ? 0.0 : vmin; break;
    }
    m.value_max = p.value_max ? *p.value_max : vmax;
    // Options that contradict each other or the data are errors, not a flat
    // block reported as a constant field.
    if (p.value_max && !(*p.value_max > m.baseline)) {
        std::ostringstream s;
        s.precision(17);
        s << "the value at full height (--value-max " << *p.value_max << ") must be above the baseline ("
          << m.baseline << ", from --baseline " << toString(p.baseline_mode) << ")";
        throw InputError(s.str());
    }
    if ((p.baseline_mode == BaselineMode::Value || p.baseline_mode == BaselineMode::Zero) && vmax < m.baseline) {
        std::ostringstream s;
        s.precision(17);
        s << "every value is below the baseline (--baseline " << m.baseline << "; the largest value is " << vmax
          << "): nothing would rise above the floor";
        throw InputError(field.source, 0, 0, s.str());
    }
    if (!(m.value_max > m.baseline)) {
        std::ostringstream s;
        s << "constant field (every value is " << vmin << (vmin == vmax ? "" : " or below the baseline")
          << "): all pillars have the same height";
        notes.push_back(s.str());
    }
    int64_t below = 0, above = 0;
    for (double v : field.values) {
        if (std::isnan(v)) continue;
        below += v < m.baseline;
        above += v > m.value_max;
    }
    if (below) notes.push_back(std::to_string(below) + " cells are below the baseline and sit at the floor");
    if (above) notes.push_back(std::to_string(above) + " cells are above the value at maximum height and are capped");
    return m;
}

double resolvePitch(const HexGrid& grid, const SceneParams& p, double y_scale) {
    double pitch = p.pitch_mm;
    if (pitch == 0) pitch = std::min(p.fit_width_mm / gridWidth(grid, 1.0), p.fit_depth_mm / gridDepth(grid, 1.0, y_scale));
    if (pitch < kMinPitchMm) {
        std::ostringstream s;
        s << "cells would be " << pitch << " mm wide; the smallest supported cell is " << kMinPitchMm
          << " mm (use fewer cells or a larger model)";
        throw InputError(s.str());
    }
    if (gridWidth(grid, pitch) > kMaxModelMm || gridDepth(grid, pitch, y_scale) > kMaxModelMm)
        throw InputError("model would be larger than 100 m; check the cell size (mm)");
    // A cell size and a box that disagree: say so rather than print a model
    // that does not fit the bed the user named.
    const double slack = 1e-9 * std::max(p.fit_width_mm, p.fit_depth_mm);
    if (p.pitch_mm > 0 && p.fit_box_given &&
        (gridWidth(grid, pitch) > p.fit_width_mm + slack || gridDepth(grid, pitch, y_scale) > p.fit_depth_mm + slack)) {
        std::ostringstream s;
        s.precision(4);
        s << "--cell " << pitch << " mm makes the model " << gridWidth(grid, pitch) << " x " << gridDepth(grid, pitch, y_scale)
          << " mm, larger than the " << p.fit_width_mm << " x " << p.fit_depth_mm
          << " mm box (--width/--depth); give one of them, or a smaller cell";
        throw InputError(s.str());
    }
    return pitch;
}

}  // namespace

namespace {

// The highest z the mesh reaches, mm: tops with their tilted corners and the
// orientation triangle, and a braille dot's height above a legend's plate.
double highestZMm(const Scene& s) {
    int64_t top = highestPillarTop(s);
    if (s.marks.triangle) top = std::max(top, s.top[size_t(s.marks.triangle->anchor)] + s.marks.triangle->raise_units);
    double z = s.zMm(top);
    if (s.legend) z = std::max(z, s.zMm(s.legend->plate_top_units) + s.legend->layout.standard.dot_height_mm);
    return z;
}

// The finest "nice" z grid (1, 2 or 5 x 10^k mm) whose steps float32 keeps
// apart at the Scene's highest z: four times the largest spacing of float32
// numbers there (2^-23 of the value, relative), so two heights a step apart
// never round to one and a thin triangle keeps its area.
double float32SafeSnapMm(const Scene& s) {
    const double need = 4.0 * std::ldexp(std::max(1.0, highestZMm(s)), -23);
    double decade = std::pow(10.0, std::floor(std::log10(need)));
    for (;; decade *= 10.0)
        for (const double m : {1.0, 2.0, 5.0})
            if (m * decade >= need * (1 - 1e-12)) return std::max(s.z_snap_mm, m * decade);
}

}  // namespace

Scene buildScene(const HexField& field, const SceneParams& params) {
    validate(field, params);
    Scene s;
    s.grid = field.grid;
    s.params = params;
    if (field.input.categorical && s.params.legend.wanted() && s.params.legend.range_line.empty()) {
        // A class map's legend says how many classes it shows, not the
        // range of their codes (the key names them).
        std::vector<double> classes;
        for (const double v : field.values)
            if (!std::isnan(v)) classes.push_back(v);
        std::sort(classes.begin(), classes.end());
        classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
        s.params.legend.range_line = std::to_string(classes.size()) + (classes.size() == 1 ? " class" : " classes");
    }
    s.z_snap_mm = params.z_snap_mm;
    s.mapping = resolveMapping(field, params, s.notes);
    // A raster's rows, one pillar per value, stand a pitch apart as on the
    // ground (true aspect); a lattice laid over the ground keeps its own.
    s.y_scale = params.true_aspect && field.rows_a_pitch_apart ? kRowsAPitchApart * field.row_aspect : 1.0;
    s.pitch_mm = resolvePitch(field.grid, params, s.y_scale);
    s.one_to_one = field.one_to_one;
    if (s.pitch_mm < kMinTactileCellMm) {
        std::ostringstream w;
        w.precision(3);
        w << "cells are " << s.pitch_mm << " mm across, below the " << kMinTactileCellMm
          << " mm a fingertip tells apart: neighbouring values will feel like texture (fewer --bins, or a larger --cell)";
        s.notes.push_back(w.str());
    }
    const HexGrid& g = s.grid;
    const size_t n = size_t(g.cellCount());
    // A class map's classes stand at one height, told apart by texture.
    if (classTexturesApply(field, params)) {
        s.textures = decideClassTextures(field, params, s.pitch_mm, s.y_scale);
        s.mapping = classTextureMapping(field, s.zMm(s.textures->height_units));
        // The braille legend names the classes by texture where they fit.
        if (s.params.legend.wanted() && s.params.legend.key_lines.empty())
            s.params.legend.key_lines = classTextureLegendLines(*s.textures, field.input.classes);
    }

    // Heights above the floor, snapped once; everything below compares integers.
    std::vector<int64_t> h_units(n, 0);
    std::vector<uint8_t> nonempty(n, 0);
    for (size_t idx = 0; idx < n; ++idx) {
        const double v = field.values[idx];
        if (std::isnan(v)) continue;
        ++s.cells_with_data;
        h_units[idx] = snapUnits(s.mapping.heightMm(v), s.z_snap_mm);
        nonempty[idx] = h_units[idx] > 0;
        s.cells_nonempty += nonempty[idx];
    }

    std::vector<uint8_t> keep(n, 0);
    std::vector<uint8_t> dropped_by_concave;  // kept by the convex hull, not by the concave one
    if (params.cull == Cull::None) {
        std::fill(keep.begin(), keep.end(), 1);
    } else if (s.cells_nonempty == 0) {
        // Nothing rises above the floor: there is no hull to cull with. Keep
        // the whole grid as a flat slab rather than print nothing.
        std::fill(keep.begin(), keep.end(), 1);
        s.notes.push_back("no cell rises above the floor: the whole grid is kept as a flat slab");
    } else {
        // The hull spans the non-empty cells; when every cell is one input
        // value, it spans every cell with data: a typed 0 is a value, and
        // only cells without data are left out.
        std::vector<LatticePoint> centres;
        centres.reserve(size_t(s.cells_nonempty));
        for (int32_t r = 0; r < g.rows; ++r)
            for (int32_t c = 0; c < g.cols; ++c) {
                const size_t idx = size_t(g.index(c, r));
                if (nonempty[idx] || (field.one_to_one && !std::isnan(field.values[idx]))) centres.push_back(hexCentre(g, c, r));
            }
        s.hull = convexHull(centres);
        for (int32_t r = 0; r < g.rows; ++r)
            for (int32_t c = 0; c < g.cols; ++c)
                keep[size_t(g.index(c, r))] = hullContains(s.hull, hexCentre(g, c, r));
        if (componentCount(g, keep) > 1) {
            // A thin hull (one cell, or cells on a line) can miss the cells
            // between its corners. Every cell within one circumradius of the
            // hull touches it, and such cells form one piece (docs/model.md).
            const double reach = 1.0 / kSqrt3 + 1e-9;  // circumradius in pitches, plus rounding slack
            for (int32_t r = 0; r < g.rows; ++r)
                for (int32_t c = 0; c < g.cols; ++c)
                    keep[size_t(g.index(c, r))] = hullDistancePitch(s.hull, hexCentre(g, c, r)) <= reach;
            s.notes.push_back("the hull of the non-empty cells is too thin to hold the model together; "
                              "cells touching it were added so the model is one piece");
        }
        if (params.cull == Cull::Concave) {
            std::vector<uint8_t> anchor(n, 0);
            for (size_t idx = 0; idx < n; ++idx)
                anchor[idx] = nonempty[idx] || (field.one_to_one && !std::isnan(field.values[idx]));
            std::vector<uint8_t> concave = concaveKeep(g, anchor, keep, std::max(0, params.concave_radius));
            for (size_t idx = 0; idx < n; ++idx) {
                s.cells_convex += keep[idx];
                dropped_by_concave.push_back(keep[idx] && !concave[idx] ? uint8_t(1) : uint8_t(0));
            }
            keep.swap(concave);
        }
    }
    // A mirrored model stands on z = 0: its lowest data cell's underside is
    // the bed, not the height of its value above a floor it does not have
    // (a mirrored band of values 7000 to 25000 would float 2 mm up). The
    // shift is taken over every cell the culling keeps, before a tile takes
    // its share, so the tiles of one model share it; floor_units records
    // it (the z of height 0, at or below the bed).
    // Tops shaped below their level (class textures' dimples and ridges)
    // mirror into the underside: their relief is kept below the lowest
    // cell. Tilted tops keep the whole height below them until their
    // corners are resolved, and come down to their lowest corner then.
    int64_t mirror_shift = 0;
    if (params.bottom == Bottom::Mirrored) {
        mirror_shift = std::numeric_limits<int64_t>::max();
        for (size_t idx = 0; idx < n; ++idx)
            if (keep[idx] && !std::isnan(field.values[idx])) mirror_shift = std::min(mirror_shift, h_units[idx]);
        if (mirror_shift == std::numeric_limits<int64_t>::max() || params.tilt != TiltSource::None) mirror_shift = 0;
        if (s.textures) mirror_shift = std::max<int64_t>(0, mirror_shift - s.textures->relief_units);
        for (size_t idx = 0; idx < n; ++idx)
            if (!std::isnan(field.values[idx])) h_units[idx] = std::max<int64_t>(0, h_units[idx] - mirror_shift);
    }
    if (!params.tile_cells.empty()) {
        // One tile of a tiled model: its share of the cells the whole keeps
        // (gen/model/features/tiles.h made it one piece).
        if (params.tile_cells.size() != n) throw InputError("a tile's cell list does not match the grid");
        for (size_t idx = 0; idx < n; ++idx) keep[idx] = keep[idx] && params.tile_cells[idx];
        if (componentCount(g, keep) != 1) throw InputError("a tile of the model is not one piece");
    }
    assert(componentCount(g, keep) == 1);

    const int64_t base_units = snapUnits(params.base_mm, s.z_snap_mm);
    s.kept_index.assign(n, -1);
    for (int32_t r = 0; r < g.rows; ++r) {
        for (int32_t c = 0; c < g.cols; ++c) {
            const size_t idx = size_t(g.index(c, r));
            if (!keep[idx]) continue;
            s.kept_index[idx] = int32_t(s.col.size());
            s.col.push_back(c);
            s.row.push_back(r);
            s.value.push_back(field.values[idx]);
            s.kind.push_back(std::isnan(field.values[idx]) ? CellKind::NoData : CellKind::Data);
            s.cells_nodata_kept += std::isnan(field.values[idx]);
        }
    }
    const size_t kept = s.col.size();
    // A cell without data is a pit below the floor (half the base, at most
    // 1 mm): a finger finds a hole, never the lowest value.
    s.nodata_pit_units = std::min<int64_t>(base_units / 2, std::max<int64_t>(1, snapUnits(1.0, s.z_snap_mm)));
    s.top.resize(kept);
    s.bottom.resize(kept);
    if (params.bottom == Bottom::Flat) {
        s.floor_units = base_units;
        for (size_t k = 0; k < kept; ++k) {
            s.bottom[k] = 0;
            s.top[k] = base_units + h_units[size_t(g.index(s.col[k], s.row[k]))];
            if (s.kind[k] == CellKind::NoData) s.top[k] -= s.nodata_pit_units;
        }
    } else {
        int64_t max_step = 0;
        for (size_t k = 0; k < kept; ++k) {
            const int64_t h = h_units[size_t(g.index(s.col[k], s.row[k]))];
            for (int e = 0; e < kHexCorners; ++e) {
                int32_t nc, nr;
                hexNeighbour(s.col[k], s.row[k], e, nc, nr);
                const int32_t other = s.keptAt(nc, nr);
                if (other >= 0) max_step = std::max<int64_t>(max_step, std::llabs(h - h_units[size_t(g.index(nc, nr))]));
            }
        }
        s.floor_units = -mirror_shift;
        s.mirror_thickness_units = max_step + base_units;
        const int64_t flat_pit = s.nodata_pit_units;
        // A pit is cut from both faces of the slab: leave the cell at least
        // one step thick (a flat field's slab is only the base thick).
        s.nodata_pit_units = std::min(s.nodata_pit_units, (s.mirror_thickness_units - 1) / 2);
        if (params.halves) {
            // Halves: every pillar must cross one slab thick enough for the
            // pin holes on both sides of the cut (gen/model/features/halves.h).
            // The grown slab is far thicker than two pits, so a pit is the
            // flat model's (as the OpenSCAD library computes it from the
            // grown thickness).
            int64_t highest_bottom = 0, lowest_top = INT64_MAX;
            for (size_t k = 0; k < kept; ++k) {
                const int64_t h = h_units[size_t(g.index(s.col[k], s.row[k]))];
                const int64_t pit = s.kind[k] == CellKind::NoData ? flat_pit : 0;
                highest_bottom = std::max(highest_bottom, h + pit);
                lowest_top = std::min(lowest_top, h - pit + s.mirror_thickness_units);
            }
            // The pins go where the pillars have room for them on both sides
            // of the cut (material there anyway: placeHalves); only when no
            // three pillars have, the slab grows to hold them everywhere.
            // At least the orientation tab's room: it lies across the cut, as
            // thick as the base (at least kTabMinThicknessMm) on each side,
            // in every pillar it may stand against (orientation_tab.h); and
            // no pillar ends at the cut (it would vanish from one half).
            const int64_t tab_room =
                2 * std::max({base_units, snapUnits(kTabMinThicknessMm, s.z_snap_mm), int64_t(1)});
            const int64_t want = std::max(params.halves_slab_units.value_or(0), tab_room);
            const int64_t grow = std::max<int64_t>(0, want - (lowest_top - highest_bottom));
            s.mirror_thickness_units += grow;
            s.nodata_pit_units = std::min(flat_pit, (s.mirror_thickness_units - 1) / 2);
            SceneHalves halves;
            halves.thickness_grown_units = grow;
            halves.slab_bottom_units = highest_bottom;
            halves.slab_top_units = lowest_top + grow;
            halves.split_units = (halves.slab_bottom_units + halves.slab_top_units) / 2;
            s.halves = halves;
        }
        for (size_t k = 0; k < kept; ++k) {
            s.bottom[k] = h_units[size_t(g.index(s.col[k], s.row[k]))];
            s.top[k] = s.bottom[k] + s.mirror_thickness_units;
            if (s.kind[k] == CellKind::NoData) {
                s.bottom[k] += s.nodata_pit_units;
                s.top[k] -= s.nodata_pit_units;
            }
        }
    }
    if (s.cells_nodata_kept > 0 && s.nodata_pit_units == 0)
        s.notes.push_back("the base is one z step thick: cells without data sit at the floor, like the lowest value");
    if (!dropped_by_concave.empty()) {
        // What the convex hull would have printed there: empty pillars (floor
        // height, or a pit without data) of the full slab.
        const int64_t slab = params.bottom == Bottom::Flat ? base_units : s.mirror_thickness_units;
        int64_t dropped = 0, units = 0;
        for (size_t idx = 0; idx < n; ++idx) {
            if (!dropped_by_concave[idx]) continue;
            ++dropped;
            const bool nodata = std::isnan(field.values[idx]);
            units += slab - (nodata ? (params.bottom == Bottom::Flat ? 1 : 2) * s.nodata_pit_units : 0);
        }
        s.volume_saved_mm3 = double(units) * s.z_snap_mm * hexArea(s.pitch_mm, s.y_scale);
        std::ostringstream note;
        note.precision(3);
        note << "concave hull: " << s.keptCount() << " cells kept, " << dropped << " fewer than the convex hull ("
             << (s.cells_convex > 0 ? 100.0 * double(dropped) / double(s.cells_convex) : 0.0) << "%), saving about "
             << s.volume_saved_mm3 / 1000.0 << " cm^3 of material";
        s.notes.push_back(note.str());
    }
    if (params.tile_marks) {
        // A tile draws the model's marks where the model has them.
        s.marks = {};
        s.marks.notch = params.tile_marks->notch;
        s.marks.triangle = params.tile_marks->triangle;
        if (s.marks.triangle) {
            const int32_t anchor = s.marks.triangle->anchor;
            if (anchor < 0 || size_t(anchor) >= n || s.kept_index[size_t(anchor)] < 0)
                throw InputError("a tile does not hold the cell its orientation triangle stands on");
            s.marks.triangle->anchor = s.kept_index[size_t(anchor)];
        }
        buildMarkFaces(s);
    } else {
        placeMarks(s);
    }
    if (s.halves) {
        const int64_t full = halvesSlabUnits(s.z_snap_mm);
        const bool last_try = params.halves_slab_units && *params.halves_slab_units >= full;
        if (!placeHalves(s, /*or_throw=*/last_try)) {
            // A try of the search below: the caller sees no halves.
            if (params.halves_slab_units) {
                s.halves.reset();
                return s;
            }
            // No three pillars have room for the pins in the model's own
            // slab: the thinnest slab that gives them room, between it
            // (fails) and one that holds the pins everywhere (never fails
            // for want of room), to kHalvesSlabSearchMm.
            int64_t lo = s.halves->slab_top_units - s.halves->slab_bottom_units, hi = full;
            const int64_t step = std::max<int64_t>(1, snapUnits(kHalvesSlabSearchMm, s.z_snap_mm));
            SceneParams trial = params;
            while (hi - lo > step) {
                trial.halves_slab_units = (lo + hi) / 2;
                if (buildScene(field, trial).halves) hi = *trial.halves_slab_units;
                else lo = *trial.halves_slab_units;
            }
            trial.halves_slab_units = hi;
            return buildScene(field, trial);
        }
    }
    // A tile's code pits go under level tops, so before the dimples.
    if (params.tile_place) placeTileCode(s);
    if (params.structural_texture && params.halves)
        s.notes.push_back("structural cells are left level on a model cut into halves (the cut and the pin "
                          "holes are drawn on level cells): give --no-texture-structural to silence this");
    if (params.tilt != TiltSource::None || (params.structural_texture && !params.halves) || s.textures) {
        // Structural: a kept cell at the floor that no input value fell in (a
        // bin without points): kept only because the hull holds the model
        // together there. A raster cell always holds pixels, so at the floor
        // it is a value (0 rain is data) and is never dimpled. Not when
        // nothing rises above the floor (the whole model is then such cells).
        std::vector<uint8_t> structural(kept, 0);
        const bool dimples = params.structural_texture && s.cells_nonempty > 0 && !field.moments.empty();
        if (dimples)
            for (size_t k = 0; k < kept; ++k) {
                const size_t idx = size_t(g.index(s.col[k], s.row[k]));
                structural[k] = s.kind[k] == CellKind::Data && h_units[idx] == 0 && field.moments[idx].n == 0 &&
                                (s.drawn_by_face.empty() || !s.drawn_by_face[k]) &&
                                (params.level_cells.empty() || !params.level_cells[idx]) && !isTileCodeCell(s, k);
            }
        std::vector<PlaneSlope> slopes = tiltSlopes(field, s, params.tilt);
        std::vector<int32_t> centre_dz;
        if (s.textures) classTextureShapes(s, slopes, centre_dz);  // no --tilt with textures (decideClassTextures)
        // Nothing to shape (a raster's cells are never structural, and no
        // tilt or texture was asked for): every top stays a level hexagon,
        // with no per-cell shape lists to build, check and carry.
        const bool any = params.tilt != TiltSource::None || s.textures ||
                         std::any_of(structural.begin(), structural.end(), [](uint8_t b) { return b != 0; });
        if (any) resolveTopShapes(s, slopes, s.textures ? 1.0 : params.steepness, structural, centre_dz);
        if (any && params.bottom == Bottom::Mirrored && params.tilt != TiltSource::None) {
            // Tilted mirrored tops kept the whole height below them (above);
            // now that their corners are known, the model comes down to
            // stand on its lowest corner. Before the legend and the tab,
            // which take their z from the cells; tilt has no halves or tiles.
            int64_t lowest = std::numeric_limits<int64_t>::max();
            for (size_t k = 0; k < kept; ++k) {
                lowest = std::min(lowest, centreBottom(s, k));
                for (int e = 0; e < kHexCorners; ++e) lowest = std::min(lowest, cornerBottom(s, k, e));
            }
            if (lowest > 0 && lowest != std::numeric_limits<int64_t>::max()) {
                for (size_t k = 0; k < kept; ++k) {
                    s.top[k] -= lowest;
                    s.bottom[k] -= lowest;
                }
                for (int64_t& z : s.shapes.extra_z) z -= lowest;
                s.floor_units -= lowest;
            }
        }
    }
    if (s.textures) {
        if (s.textures->relief_units * s.z_snap_mm < kMinFeltTextureReliefMm - 1e-9)
            s.notes.push_back("the class textures rise only " + formatSignificant(s.zMm(s.textures->relief_units), 2) +
                              " mm on cells " + formatSignificant(s.pitch_mm, 3) + " mm across, below the " +
                              formatSignificant(kMinFeltTextureReliefMm) +
                              " mm a finger finds without searching: larger cells (fewer --bins, a larger --cell)");
    }
    // The legend, the tab and the features of the registry last: they stand
    // against cells whose tops (tilted or not) rise to the floor, or on a
    // mirrored model hold their band; the tab keeps clear of the legend's
    // plate, the registry's features of every footprint claimed before them.
    placeLegend(s);
    if (std::optional<FootprintClaim> plate = legendClaim(s)) s.claims.push_back(std::move(*plate));
    if (params.tile_marks && params.tile_marks->tab) {
        // A tile carries the model's own tab (touched cells given as grid cell indices).
        OrientationTab tab = *params.tile_marks->tab;
        for (auto& [k, e] : tab.touched) {
            if (k < 0 || size_t(k) >= n || s.kept_index[size_t(k)] < 0)
                throw InputError("a tile does not hold the pillars its orientation tab stands against");
            k = s.kept_index[size_t(k)];
        }
        s.marks.tab = std::move(tab);
    } else {
        placeTab(s);
    }
    if (wantsTab(params) && !s.marks.tab && s.keptCount() > 0) {
        // No pillar on the west side to stand a tab against (placeTab's note
        // says why): the marks go in the data where they fit, as the thesis
        // places them, rather than nowhere.
        SceneParams in_data = params;
        in_data.marks.place = MarkPlace::Data;
        Scene again = buildScene(field, in_data);
        again.notes.insert(again.notes.begin(), s.notes.back() + "; they are placed in the data instead, where they fit");
        return again;
    }
    if (std::optional<FootprintClaim> tab = tabClaim(s)) s.claims.push_back(std::move(*tab));
    placeFeatures(s, FeaturePhase::Beside);
    if (params.stored_as_float32) {
        const double snap = float32SafeSnapMm(s);
        if (snap > s.z_snap_mm) {
            if (snap > kMaxSnapMm)
                throw InputError("the model is " + formatSignificant(highestZMm(s), 4) +
                                 " mm tall: a float32 STL or 3MF cannot hold its heights to " +
                                 formatSignificant(kMaxSnapMm) + " mm; make it lower (--height) or write OFF or OBJ");
            SceneParams coarser = params;
            coarser.z_snap_mm = snap;
            coarser.stored_as_float32 = false;
            Scene again = buildScene(field, coarser);
            again.params.stored_as_float32 = true;
            again.notes.push_back("heights snapped to " + formatSignificant(snap) + " mm instead of " +
                                  formatSignificant(params.z_snap_mm) + " mm: at " +
                                  formatSignificant(highestZMm(again), 4) +
                                  " mm the float32 coordinates of STL and 3MF resolve no finer (OFF and OBJ keep the "
                                  "finer grid)");
            return again;
        }
    }
    return s;
}

}  // namespace tsf
