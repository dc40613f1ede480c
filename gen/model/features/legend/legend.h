// The braille legend's layout: lines of text -> braille cells (braille.h)
// -> dot centres in millimetres at a stated braille standard.
//
// Frame: the legend's own, x east from its west edge, y north from its south
// edge, mm; the first line is the northernmost. Inside a cell dots 1-2-3 run
// down the west column and 4-5-6 down the east column (7-8 below them), the
// columns dot_pitch_mm apart, cells cell_pitch_mm apart centre to centre,
// lines line_pitch_mm apart. Every centre is rounded to the model's 1 um
// grid. A margin of margin_mm surrounds the dots' bases on every side.
//
// Lines longer than max_cells are broken at spaces (a word longer than the
// line is an InputError that says how wide the legend would have to be).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/model/features/braille.h"

namespace tsf {

struct LegendParams {
    std::vector<std::string> lines;            ///< text, UTF-8; empty lines are skipped
    std::string table = "en-ueb-g1.ctb";       ///< liblouis table (braille.h)
    BrailleStandard standard = kNlsSpec800;
    double margin_mm = 3.0;                    ///< clear space around the dots
    int max_cells = 0;                         ///< cells per line before a break; 0 = no limit
};

struct LegendDot {
    double x_mm = 0, y_mm = 0;  ///< centre, legend frame
};

struct LegendLayout {
    BrailleStandard standard = kNlsSpec800;
    std::vector<std::string> text;               ///< the lines as laid out (after breaking)
    std::vector<std::vector<uint8_t>> cells;     ///< braille cells of each line
    std::vector<LegendDot> dots;                 ///< every raised dot
    double width_mm = 0, depth_mm = 0;           ///< the area the legend needs, margins included
};

/// The legend as placed on a model (gen/model/features/legend/legend_scene.h): a plate north of
/// the pillars, its top at the floor, the braille on it.
struct SceneLegend {
    LegendLayout layout;          ///< the braille, in the legend's frame
    double x0_mm = 0, y0_mm = 0;  ///< where the legend frame's origin is in the model frame
    int32_t reach_row = 0;        ///< the southmost grid row the plate reaches under (its north tips)
    double plate_south_mm = 0;    ///< y (model frame) of the plate's south edge: the upper side corners of reach_row
    double plate_north_mm = 0;    ///< y of its north edge
    double plate_east_mm = 0;     ///< x of its east edge (its west edge is x = 0)
    int64_t plate_top_units = 0;     ///< z of its top (flat: the floor), z snap units
    /// z of its bottom: flat, the bed (0); mirrored, the bottom of the band
    /// every pillar it stands against holds.
    int64_t plate_bottom_units = 0;
};

struct Scene;

/// The legend the Scene carries (in Scene::features); null without one.
const SceneLegend* sceneLegend(const Scene& scene);
SceneLegend* sceneLegend(Scene& scene);

/// Lays the legend out as described above. Throws InputError for a table
/// liblouis cannot load or a word wider than max_cells.
LegendLayout layoutLegend(const LegendParams& params);

/// "0 to 27 airports" (units "" -> "0 to 27"): the value range a legend states,
/// with up to 4 significant digits as a reader reads them (formatForReader:
/// no e-notation, thousands by commas), the units joined to the number by
/// a no-break space so a line of braille never ends between them
/// (layoutLegend breaks only at spaces and writes the line with a space).
std::string legendRangeText(double low, double high, const std::string& units);

}  // namespace tsf
