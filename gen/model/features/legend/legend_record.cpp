// The braille legend's record in the scene sidecar. See legend_record.h.
#include "gen/model/features/legend/legend_record.h"

#include <algorithm>
#include <sstream>
#include <tuple>

#include "gen/model/features/legend/legend.h"
#include "gen/model/features/legend/legend_scene.h"
#include "gen/model/sidecar_fields.h"
#include "gen/model/features/braille.h"
#include "gen/util/number_format.h"

namespace tsf {

using namespace sidecar;

namespace {

// The standards tsf lays braille out at, by the name a sidecar records.
const BrailleStandard* knownStandard(const std::string& name) {
    for (const BrailleStandard* st : {&kNlsSpec800})
        if (name == st->name) return st;
    return nullptr;
}

void readLegend(const json& l, const std::string& lp, const Scene& s, SceneLegend& out, ModelWords& request) {
    if (!l.is_object()) fail(lp, std::string("expected an object or null, found ") + typeName(l));
    request.title = getString(l, lp, "title");
    request.units = getString(l, lp, "units");
    request.braille_table = getString(l, lp, "table");
    const json& st = member(l, lp, "standard");
    const std::string sp = join(lp, "standard");
    const BrailleStandard* known = knownStandard(getString(st, sp, "name"));
    if (!known) fail(join(sp, "name"), "not a braille standard this tsf knows (" + std::string(kNlsSpec800.name) + ")");
    BrailleStandard standard = *known;
    standard.dot_base_mm = getPositive(st, sp, "dot_base_mm");
    standard.dot_height_mm = getPositive(st, sp, "dot_height_mm");
    standard.dot_pitch_mm = getPositive(st, sp, "dot_pitch_mm");
    standard.cell_pitch_mm = getPositive(st, sp, "cell_pitch_mm");
    standard.line_pitch_mm = getPositive(st, sp, "line_pitch_mm");
    LegendLayout& layout = out.layout;
    layout.standard = standard;
    const json& text = getArray(l, lp, "text");
    for (size_t i = 0; i < text.size(); ++i) {
        if (!text[i].is_string()) fail(lp + ".text[" + std::to_string(i) + "]", "expected a string");
        layout.text.push_back(text[i].get<std::string>());
    }
    const json& cells = getArray(l, lp, "cells");
    for (size_t i = 0; i < cells.size(); ++i) {
        const std::string cp = lp + ".cells[" + std::to_string(i) + "]";
        if (!cells[i].is_array()) fail(cp, "expected an array of braille cells");
        std::vector<uint8_t> line;
        for (size_t k = 0; k < cells[i].size(); ++k) {
            const int64_t v = toInt(cells[i][k], cp + "[" + std::to_string(k) + "]");
            if (v < 0 || v > 255) fail(cp + "[" + std::to_string(k) + "]", "expected a braille cell 0..255");
            line.push_back(uint8_t(v));
        }
        layout.cells.push_back(std::move(line));
    }
    std::tie(layout.width_mm, layout.depth_mm) = getFinitePair(l, lp, "size_mm");
    std::tie(out.x0_mm, out.y0_mm) = getFinitePair(l, lp, "origin_mm");
    out.reach_row = getInt32(l, lp, "reach_row", 0, std::max<int64_t>(0, int64_t(s.grid.rows) - 1));
    const json& plate = member(l, lp, "plate_mm");
    const std::string pp = join(lp, "plate_mm");
    out.plate_south_mm = getFinite(plate, pp, "south");
    out.plate_north_mm = getFinite(plate, pp, "north");
    out.plate_east_mm = getFinite(plate, pp, "east");
    if (!(out.plate_north_mm > out.plate_south_mm)) fail(join(pp, "north"), "must be north of the plate's south edge");
    if (!(out.plate_east_mm > 0)) fail(join(pp, "east"), "must be east of the plate's west edge (x = 0)");
    out.plate_top_units = getInt(l, lp, "plate_top_units");
    // Version 7: a mirrored model's plate lies in a band; before, on the bed.
    out.plate_bottom_units = l.contains("plate_bottom_units") ? getInt(l, lp, "plate_bottom_units") : 0;
    if (out.plate_bottom_units >= out.plate_top_units) fail(join(lp, "plate_bottom_units"), "must be below the plate's top");
    const double r = 0.5 * standard.dot_base_mm;
    const json& dots = getArray(l, lp, "dots");
    for (size_t i = 0; i < dots.size(); ++i) {
        const std::string dp = lp + ".dots[" + std::to_string(i) + "]";
        if (!dots[i].is_array() || dots[i].size() != 2) fail(dp, "expected [x, y]");
        const LegendDot d{toNumber(dots[i][0], dp + "[0]"), toNumber(dots[i][1], dp + "[1]")};
        const double x = d.x_mm + out.x0_mm, y = d.y_mm + out.y0_mm;
        if (!(x - r >= 0 && x + r <= out.plate_east_mm && y - r >= out.plate_south_mm && y + r <= out.plate_north_mm))
            fail(dp, "the dot does not lie on the legend's plate");
        layout.dots.push_back(d);
    }
    if (layout.dots.empty()) fail(join(lp, "dots"), "a legend has at least one dot");
}


}  // namespace

// The braille legend as placed: its request (for reports), the standard its
// dots were laid out at, the text and braille cells, every dot and the plate.
// Read back as is: verifying a model needs no braille table and no placement.
json legendRecord(const Scene& s) {
    if (!sceneLegend(s)) return nullptr;
    const SceneLegend& l = *sceneLegend(s);
    const BrailleStandard& st = l.layout.standard;
    json dots = json::array();
    for (const LegendDot& d : l.layout.dots) dots.push_back({d.x_mm, d.y_mm});
    return {{"title", s.params.words.title},
            {"units", s.params.words.units},
            {"table", s.params.words.braille_table},
            {"standard",
             {{"name", st.name},
              {"dot_base_mm", st.dot_base_mm},
              {"dot_height_mm", st.dot_height_mm},
              {"dot_pitch_mm", st.dot_pitch_mm},
              {"cell_pitch_mm", st.cell_pitch_mm},
              {"line_pitch_mm", st.line_pitch_mm}}},
            {"text", l.layout.text},
            {"cells", l.layout.cells},
            {"dots", dots},
            {"size_mm", {l.layout.width_mm, l.layout.depth_mm}},
            {"origin_mm", {l.x0_mm, l.y0_mm}},
            {"reach_row", l.reach_row},
            {"plate_mm", {{"south", l.plate_south_mm}, {"north", l.plate_north_mm}, {"east", l.plate_east_mm}}},
            {"plate_top_units", l.plate_top_units},
            {"plate_bottom_units", l.plate_bottom_units}};
}


void readLegendRecord(const json& record, const std::string& path, int version, Scene& s) {
    // Up to version 4 the sidecar held the legend as asked for, and reading
    // placed and translated it again (with whatever braille table was
    // installed): such a sidecar cannot say what was printed.
    if (version < 5)
        fail(path, "this sidecar (version " + std::to_string(version) +
                       ") records the braille legend as asked for, not as placed; make the model and its "
                       "sidecar again with this tsf (tsf gen ... --title ...)");
    SceneLegend legend;
    readLegend(record, path, s, legend, s.params.words);
    s.features.set(std::move(legend));
}

nlohmann::json legendFactsJson(const Scene& s) {
    if (!(sceneLegend(s))) return nullptr;
    const SceneLegend& l = *sceneLegend(s);
    const BrailleStandard& st = l.layout.standard;
    size_t cells = 0;
    for (const auto& line : l.layout.cells) cells += line.size();
    nlohmann::json lines = nlohmann::json::array();
    for (size_t k = 0; k < l.layout.text.size(); ++k)
        lines.push_back({{"text", l.layout.text[k]}, {"braille", brailleUnicode(l.layout.cells[k])}});
    return {{"lines", lines}, {"table", s.params.words.braille_table}, {"cells", cells}, {"dots", l.layout.dots.size()},
                   {"plate_mm", {{0, l.plate_south_mm}, {l.plate_east_mm, l.plate_north_mm}}},
                   {"standard", st.name}, {"dot_base_mm", st.dot_base_mm}, {"dot_height_mm", st.dot_height_mm},
                   {"dot_pitch_mm", st.dot_pitch_mm}, {"cell_pitch_mm", st.cell_pitch_mm},
                   {"line_pitch_mm", st.line_pitch_mm}};
}

std::string legendFactsLines(const Scene& s) {
    if (!(sceneLegend(s))) return "";
    std::ostringstream o;
    const SceneLegend& l = *sceneLegend(s);
    const BrailleStandard& st = l.layout.standard;
    o << "  legend    braille (" << s.params.words.braille_table << ") on a plate " << formatFixed(l.plate_east_mm, 1) << " x "
      << formatFixed(l.plate_north_mm - l.plate_south_mm, 1) << " mm north of the pillars, ";
    if (s.params.bottom == Bottom::Mirrored)
        o << "from z = " << formatFixed(s.zMm(l.plate_bottom_units), 2) << " to " << formatFixed(s.zMm(l.plate_top_units), 2)
          << " mm (the band the pillars it stands against share), ";
    o << l.layout.dots.size()
      << " dots " << formatFixed(st.dot_base_mm, 2) << " mm across, " << formatFixed(st.dot_height_mm, 2) << " mm high (";
    if (s.params.printer_layer_mm > 0)
        o << formatSignificant(st.dot_height_mm / s.params.printer_layer_mm, 3) << " whole layers of "
          << formatSignificant(s.params.printer_layer_mm, 3) << " mm; ";
    o << st.name << ")\n";
    if (s.params.printer_layer_mm <= 0)
        o << "  note      braille dots " << formatFixed(st.dot_height_mm, 2)
          << " mm high: whole layers at 0.1, 0.15, 0.2 and 0.3 mm layers; give --layer (your printer's layer height) "
             "and they are the fewest whole layers of it that reach the standard's "
          << formatFixed(kNlsSpec800.dot_height_mm, 2) << " mm\n";
    for (size_t k = 0; k < l.layout.text.size(); ++k)
        o << "            " << brailleUnicode(l.layout.cells[k]) << "  " << l.layout.text[k] << "\n";
    return o.str();
}

}  // namespace tsf
