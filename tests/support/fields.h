// Small hand-made fields and model parameters for tests. Part of the shared
// test support (tests/support/).
#pragma once

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/model/scene.h"

namespace tsf::test {

/// A gentle hill with a ridge as a grid CSV, 12 columns by 10 rows of
/// values 0 to 10: room for a tab, a legend and a scale at 6 mm cells.
inline std::string hillCsv() {
    std::string csv;
    for (int r = 0; r < 10; ++r) {
        for (int c = 0; c < 12; ++c) csv += (c ? "," : "") + std::to_string((c * 7 + r * 5) % 11);
        csv += "\n";
    }
    return csv;
}

/// Rows are listed north to south, as in a file; NaN = no data.
inline HexField fieldFromRows(const std::vector<std::vector<double>>& rows) {
    HexField f;
    f.grid.rows = int32_t(rows.size());
    f.grid.cols = rows.empty() ? 0 : int32_t(rows[0].size());
    for (const auto& r : rows) f.values.insert(f.values.end(), r.begin(), r.end());
    f.source = "test";
    return f;
}

inline HexField fieldFromFunction(int cols, int rows, const std::function<double(int, int)>& value) {
    HexField f;
    f.grid = {cols, rows};
    f.values.resize(size_t(cols) * size_t(rows));
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < cols; ++c) f.values[size_t(r) * size_t(cols) + size_t(c)] = value(c, r);
    f.source = "test";
    return f;
}

/// `f` as binned points would give it: one point at the centre of every cell
/// above zero, none in the others (the empty bins a hull keeps are structural).
inline HexField asBinnedPoints(HexField f) {
    f.one_to_one = false;
    f.moments.assign(f.values.size(), BinMoments{});
    for (size_t i = 0; i < f.values.size(); ++i)
        if (f.values[i] != 0.0 && !std::isnan(f.values[i])) f.moments[i].add(0.0, 0.0);
    return f;
}

/// 5 mm cells, 10 mm relief on a 2 mm base, 1 um height snap, no
/// orientation marks (the pillar rules alone; marks have their own tests).
inline SceneParams smallParams(Bottom bottom = Bottom::Flat, Cull cull = Cull::Hull) {
    SceneParams p;
    p.marks = withoutMarks();
    p.pitch_mm = 5.0;
    p.max_height_mm = 10.0;
    p.base_mm = 2.0;
    p.bottom = bottom;
    p.cull = cull;
    return p;
}

inline constexpr double kNaN = NAN;

/// Volume of the union of a Scene's pillars from the Scene alone: each kept
/// cell's footprint (its six corners, snapped to the 1 um grid the way the
/// Scene contract says; shoelace) times its z extent. Shares no code with the
/// direct mesher or the OpenSCAD library.
inline double sceneVolume(const Scene& s) {
    auto snap = [](double v) { return std::round(v / 0.001) * 0.001; };
    double volume = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        double area2 = 0;
        for (int e = 0; e < 6; ++e) {
            const LatticePoint a = hexCorner(s.grid, s.col[k], s.row[k], e);
            const LatticePoint b = hexCorner(s.grid, s.col[k], s.row[k], (e + 1) % 6);
            const double ax = snap(double(a.i) * s.pitch_mm / 2), ay = snap(double(a.j) * s.pitch_mm / (2 * std::sqrt(3.0)) * s.y_scale);
            const double bx = snap(double(b.i) * s.pitch_mm / 2), by = snap(double(b.j) * s.pitch_mm / (2 * std::sqrt(3.0)) * s.y_scale);
            area2 += ax * by - bx * ay;
        }
        volume += area2 / 2 * double(s.top[k] - s.bottom[k]) * s.z_snap_mm;
    }
    return volume;
}

}  // namespace tsf::test
