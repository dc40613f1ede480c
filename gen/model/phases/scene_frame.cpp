#include "gen/model/phases/scene_frame.h"

#include <algorithm>
#include <sstream>

#include "gen/field/resample.h"
#include "gen/model/phases/scene_limits.h"
#include "gen/model/phases/value_mapping.h"
#include "gen/model/feature_registry.h"
#include "gen/util/error.h"

namespace tsf {

namespace {

// The cell size, mm: as given, or the largest that fits the grid into the
// fit box.
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

Scene sceneFrame(const HexField& field, const SceneParams& params) {
    Scene s;
    s.grid = field.grid;
    s.params = params;
    s.place = field.place;
    if (field.input.categorical && s.params.words.inBraille() && s.params.words.range_line.empty()) {
        // A class map's legend says how many classes it shows, not the
        // range of their codes (the key names them).
        std::vector<double> classes;
        for (const double v : field.values)
            if (!std::isnan(v)) classes.push_back(v);
        std::sort(classes.begin(), classes.end());
        classes.erase(std::unique(classes.begin(), classes.end()), classes.end());
        s.params.words.range_line = std::to_string(classes.size()) + (classes.size() == 1 ? " class" : " classes");
    }
    s.z_snap_mm = params.z_snap_mm;
    s.mapping = resolveValueMapping(field, params, s.notes);
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
    // The features of the pillars themselves (a class map's classes at one
    // height, told apart by texture) may stand the values at their own.
    frameFeatures(s, field);
    return s;
}

}  // namespace tsf
