#include "gen/model/features/legend/legend_scene.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_plate.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/number_format.h"
#include "gen/model/scene.h"
#include "gen/util/error.h"

namespace tsf {
namespace {

double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

// Share of the grid's columns the kept cells of the plate's southmost row must span.
constexpr double kPlateHoldFraction = 0.6;

// The share of the plate's width (x, from 0 to its east edge) along which
// it stands against pillars that rise to its top: where it holds on.
double heldShare(const Scene& s) {
    const SceneLegend& l = *sceneLegend(s);
    const PlateOutline outline = legendPlateOutline(s);
    std::vector<std::pair<double, double>> spans;
    for (const PlateOutline::Edge& e : outline.edges) {
        if (e.cell < 0) continue;
        const size_t k = size_t(e.cell);
        if (!s.drawn_by_face.empty() && s.drawn_by_face[k]) continue;
        if (cornerTop(s, k, e.side) < l.plate_top_units || cornerTop(s, k, (e.side + 1) % kHexCorners) < l.plate_top_units)
            continue;  // a pit holds it only up to its top
        const double a = outline.points[e.a].x_mm, b = outline.points[e.b].x_mm;
        spans.push_back({std::min(a, b), std::max(a, b)});
    }
    std::sort(spans.begin(), spans.end());
    double held = 0, reached = -std::numeric_limits<double>::infinity();
    for (const auto& [a, b] : spans) {
        if (b <= reached) continue;
        held += b - std::max(a, reached);
        reached = b;
    }
    const double width = l.plate_east_mm - l.x0_mm;
    return width > 0 ? held / width : 0.0;
}

// Of the rows 0..limit, the northmost the plate may reach to and hold on
// along kPlateHoldFraction of its width, else the one it holds on along
// most of it: an irregular outline (a projected map's rotated corners, a
// coast) leaves the first rows short, or pits where data ends.
int32_t firmestReach(Scene& s, SceneLegend l, int32_t limit) {
    int32_t best = limit;
    double best_share = -1;
    for (int32_t r = 0; r <= limit; ++r) {
        l.reach_row = r;
        l.plate_south_mm = s.point(LatticePoint{hexCentre(s.grid, 0, r).i, hexCentre(s.grid, 0, r).j + 1}, 0).y;
        s.features.set(l);
        const double share = heldShare(s);
        if (share > best_share + 1e-9) {
            best = r;
            best_share = share;
        }
        if (share >= kPlateHoldFraction) break;
    }
    s.features.reset<SceneLegend>();
    return best;
}

}  // namespace

const SceneLegend* sceneLegend(const Scene& s) { return s.features.get<SceneLegend>(); }
SceneLegend* sceneLegend(Scene& s) { return s.features.get<SceneLegend>(); }

void placeLegend(Scene& s) {
    const ModelWords& rq = s.params.words;
    const double layer_mm = s.params.printer_layer_mm;
    if (!rq.inBraille() || s.keptCount() == 0) return;
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    if (s.params.halves)
        throw InputError("--title/--units with --halves: a legend on a model cut into halves is not made yet. Leave out "
                         "--halves (the mirrored model prints whole, with supports), or leave out --title and --units");
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const double v : s.value)
        if (!std::isnan(v)) {
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
    LegendParams p;
    if (!rq.title.empty()) p.lines.push_back(rq.title);
    if (!rq.range_line.empty()) p.lines.push_back(rq.range_line);
    else if (std::isfinite(lo)) p.lines.push_back(legendRangeText(lo, hi, rq.units));
    p.table = rq.braille_table;
    if (layer_mm > 0) {
        // Whole layers: the fewest that reach the standard's height, unless
        // that is higher than a reader expects (a layer thicker than the range).
        const double layers = std::ceil(p.standard.dot_height_mm / layer_mm - 1e-9);
        if (layers * layer_mm <= kMaxBrailleDotHeightMm) p.standard.dot_height_mm = std::max(1.0, layers) * layer_mm;
    } else {
        // The layer is not known: a height that is whole layers at the
        // common ones, so the printed dot stays in the standards' range.
        p.standard.dot_height_mm = kUnknownLayerDotHeightMm;
    }
    const double width = gridWidth(s.grid, s.pitch_mm);
    const BrailleStandard& st = p.standard;
    p.max_cells = std::max(1, int(std::floor((width - 2 * p.margin_mm - st.dot_base_mm - st.dot_pitch_mm) /
                                              st.cell_pitch_mm)) + 1);
    SceneLegend l;
    if (!rq.key_lines.empty()) {
        // The key's lines only when each one stays one braille line.
        LegendParams with = p;
        size_t lines = 0;
        for (const std::string& line : with.lines) lines += !line.empty();
        for (const std::string& line : rq.key_lines) {
            with.lines.push_back(line);
            lines += !line.empty();
        }
        bool one_line_each = true;
        try {
            l.layout = layoutLegend(with);
            one_line_each = l.layout.text.size() == lines;
        } catch (const InputError&) {
            one_line_each = false;  // a word of theirs is wider than the plate
        }
        if (!one_line_each) {
            l.layout = layoutLegend(p);
            s.notes.push_back("the legend names the classes only in the key files: a class's line is wider than "
                              "the plate (" + std::to_string(p.max_cells) + " braille cells)");
        }
    } else {
        l.layout = layoutLegend(p);
    }
    if (l.layout.dots.empty()) return;
    // The plate reaches south over the culled corners to row `reach`, at most
    // to the first row (from the north) whose kept cells span
    // kPlateHoldFraction of the grid's columns. A mirrored model's plate
    // never reaches over a whole row that holds a no-data pit (it lies in
    // the band of the pillars it stands against, which a pit does not hold);
    // a flat model's plate stands around such a pit, whose walls above its
    // top are then the plate's sides (a pit stays a pit).
    int32_t reach = 0;
    for (int32_t r = 0; r < s.grid.rows; ++r) {
        int32_t lo_col = s.grid.cols, hi_col = -1;
        bool pit = false;
        for (int32_t c = 0; c < s.grid.cols; ++c) {
            const int32_t k = s.keptAt(c, r);
            if (k < 0) continue;
            lo_col = std::min(lo_col, c);
            hi_col = std::max(hi_col, c);
            pit = pit || s.kind[size_t(k)] == CellKind::NoData;
        }
        reach = r;
        if (hi_col >= lo_col && double(hi_col - lo_col + 1) >= kPlateHoldFraction * s.grid.cols) break;
        if (pit && mirrored) break;  // this row's tips are covered, the row itself is not
    }
    // The south edge: the line through the upper side corners of row `reach`
    // (it meets hexagon walls only at their corners); the braille begins north
    // of the tips of row 0.
    const LatticePoint north = hexCentre(s.grid, 0, 0);
    const double tips_mm = s.point(LatticePoint{north.i, north.j + 2}, 0).y;
    l.x0_mm = 0;
    l.y0_mm = tips_mm;
    l.plate_north_mm = snapUm(tips_mm + l.layout.depth_mm);
    // On the grid box's east edge (a lattice line, so the plate meets the
    // eastmost walls at their corners) unless the braille is wider.
    l.plate_east_mm = l.layout.width_mm <= width + 1e-3 ? width : snapUm(l.layout.width_mm);
    l.plate_top_units = s.floor_units;
    // A mirrored model has no floor: the plate lies in the z band every
    // pillar it stands against holds, as thick as the base (at least
    // kMinMirroredPlateMm, at most the band), in the band's middle.
    const int64_t min_thick = std::max<int64_t>(1, snapUnits(kMinMirroredPlateMm, s.z_snap_mm));
    const int64_t want_thick = std::max(min_thick, snapUnits(s.params.base_mm, s.z_snap_mm));
    bool band_too_thin = false;
    if (!mirrored) reach = firmestReach(s, l, reach);
    // The south edge, pulled north while a wall the plate would stand
    // against is cut by the notch in the data (a model of few rows), or
    // (mirrored) while the pillars it stands against share no band thick enough.
    for (;; --reach) {
        l.reach_row = reach;
        l.plate_south_mm = s.point(LatticePoint{hexCentre(s.grid, 0, reach).i, hexCentre(s.grid, 0, reach).j + 1}, 0).y;
        s.features.set(l);
        const PlateOutline outline = legendPlateOutline(s);
        bool fits = !outline.meets_cut;
        if (fits && mirrored) {
            int64_t bottom = INT64_MIN, top = INT64_MAX;
            for (const PlateOutline::Edge& e : outline.edges) {
                if (e.cell < 0) continue;
                for (const int c : {e.side, (e.side + 1) % kHexCorners}) {
                    bottom = std::max(bottom, cornerBottom(s, size_t(e.cell), c));
                    top = std::min(top, cornerTop(s, size_t(e.cell), c));
                }
            }
            fits = top - bottom >= min_thick;
            band_too_thin = band_too_thin || !fits;
            if (fits) {
                const int64_t thick = std::min(top - bottom, want_thick);
                sceneLegend(s)->plate_bottom_units = bottom + (top - bottom - thick) / 2;
                sceneLegend(s)->plate_top_units = sceneLegend(s)->plate_bottom_units + thick;
            }
        }
        if (fits) return;
        if (reach == 0) break;
    }
    s.features.reset<SceneLegend>();
    if (band_too_thin)
        throw InputError("--title/--units: the braille legend's plate on a mirrored model lies in the band every "
                         "northern pillar it stands against holds, and these share less than " +
                         formatSignificant(kMinMirroredPlateMm, 3) +
                         " mm; give a thicker --base, or leave out --mirror, or --title and --units");
    throw InputError("--title/--units: the braille legend's plate would stand against the orientation notch on a model "
                     "this small (" + std::to_string(s.keptCount()) + (s.keptCount() == 1 ? " cell" : " cells") +
                     "): give it more cells, or --no-notch, or leave out --title and --units");
}

}  // namespace tsf
