// The edge ruler's sidecar record, facts, key paragraph and OpenSCAD piece.
// See ruler.h.
#include <algorithm>
#include <cmath>
#include <sstream>

#include "gen/model/features/ruler/ruler.h"
#include "gen/model/sidecar_fields.h"
#include "gen/util/number_format.h"

namespace tsf {

using namespace sidecar;

namespace {

std::vector<const RulerTooth*> teethOn(const SceneRuler& r, bool south) {
    std::vector<const RulerTooth*> out;
    for (const RulerTooth& t : r.teeth)
        if (t.south == south) out.push_back(&t);
    return out;
}

// What a tooth marks for a reader: columns counted from the west, rows from
// the south, both from 1 (the grid's row 0 is its north row).
int32_t columnFromWest(const RulerTooth& t) { return t.col + 1; }
int32_t rowFromSouth(const Scene& s, const RulerTooth& t) { return s.grid.rows - t.row; }

// The data coordinates teeth `step` apart stand at, for a reader: to as
// many decimals as tell one tooth's from the next ("10.067, 10.133 and
// 10.2"), thousands by commas.
std::string coordinateList(const std::vector<double>& v, double step) {
    const int decimals = step > 0 && std::isfinite(step) ? std::max(0, 1 - int(std::floor(std::log10(step)))) : 0;
    std::string out;
    for (size_t k = 0; k < v.size(); ++k) {
        const double whole = std::fabs(v[k]) >= 1 ? std::floor(std::log10(std::fabs(v[k]))) + 1 : 1;
        out += (k == 0 ? "" : k + 1 == v.size() ? " and " : ", ") +
               formatForReader(v[k], std::clamp(int(whole) + (step >= 10 ? 0 : decimals), 1, 15));
    }
    return out;
}

// Where the teeth of one edge stand in the data's own coordinates (the
// centres of the cells they stand at), as a sentence; "" when the input
// gives no coordinates.
std::string placeSentence(const Scene& s, const std::vector<const RulerTooth*>& teeth, bool south, int every) {
    if (!s.place.known || teeth.empty()) return "";
    std::vector<double> at;
    for (const RulerTooth* t : teeth) at.push_back(south ? s.place.x(t->col, t->row) : s.place.y(t->row));
    const double step = std::fabs(south ? s.place.x_per_col : s.place.y_per_row) * every;
    const std::string& axis = south ? s.place.axes.x : s.place.axes.y;
    const std::string& unit = s.place.axes.unit;
    std::string out = std::string(teeth.size() == 1 ? "It stands at " : "They stand at ") + axis + " " +
                      coordinateList(at, step) + (unit.empty() ? "" : " " + unit);
    if (teeth.size() > 1) out += ", " + formatForReader(step, 3) + (unit.empty() ? "" : " " + unit) + " apart";
    return out + ". ";
}

std::string list(const std::vector<int32_t>& v) {
    std::string out;
    for (size_t k = 0; k < v.size(); ++k)
        out += (k == 0 ? "" : k + 1 == v.size() ? " and " : ", ") + std::to_string(v[k]);
    return out;
}

}  // namespace

json rulerRecord(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return nullptr;
    json teeth = json::array();
    for (const RulerTooth& t : r->teeth) teeth.push_back({t.south ? "south" : "west", t.kept, t.ordinal, t.xy, t.ridge});
    return {{"every", {r->every_x, r->every_y}}, {"every_given", r->every_given},
            {"spacing_mm", {r->spacing_x_mm, r->spacing_y_mm}}, {"lines", {r->lines_x, r->lines_y}},
            {"top_units", r->top_units}, {"teeth", teeth}};
}

void readRulerRecord(const json& j, const std::string& sp, int /*version*/, Scene& s) {
    if (!j.is_object()) fail(sp, std::string("expected an object, found ") + typeName(j));
    SceneRuler r;
    const json& every = getArray(j, sp, "every");
    if (every.size() != 2) fail(join(sp, "every"), "expected [along the south edge, along the west edge]");
    r.every_x = int(toInt(every[0], sp + ".every[0]"));
    r.every_y = int(toInt(every[1], sp + ".every[1]"));
    if (r.every_x < 2 || r.every_y < 2) fail(join(sp, "every"), "expected at least 2 cells between teeth");
    const json& given = member(j, sp, "every_given");
    if (!given.is_boolean()) fail(join(sp, "every_given"), "expected true or false");
    r.every_given = given.get<bool>();
    std::tie(r.spacing_x_mm, r.spacing_y_mm) = getFinitePair(j, sp, "spacing_mm");
    const json& lines = getArray(j, sp, "lines");
    if (lines.size() != 2) fail(join(sp, "lines"), "expected [south, west]");
    r.lines_x = int32_t(toInt(lines[0], sp + ".lines[0]"));
    r.lines_y = int32_t(toInt(lines[1], sp + ".lines[1]"));
    r.top_units = getInt(j, sp, "top_units");
    const json& teeth = getArray(j, sp, "teeth");
    for (size_t i = 0; i < teeth.size(); ++i) {
        const std::string p = sp + ".teeth[" + std::to_string(i) + "]";
        const json& t = teeth[i];
        if (!t.is_array() || t.size() != 5 || !t[0].is_string() || !t[3].is_array() || !t[4].is_array())
            fail(p, "expected [\"south\" or \"west\", cell, line, [x, y, ...], [ridge x, y, ...]]");
        RulerTooth tooth;
        const std::string edge = t[0].get<std::string>();
        if (edge != "south" && edge != "west") fail(p + "[0]", "expected \"south\" or \"west\"");
        tooth.south = edge == "south";
        const int64_t k = toInt(t[1], p + "[1]");
        if (k < 0 || size_t(k) >= s.keptCount()) fail(p + "[1]", "is not the index of a cell");
        tooth.kept = int32_t(k);
        tooth.col = s.col[size_t(k)];
        tooth.row = s.row[size_t(k)];
        tooth.ordinal = int32_t(toInt(t[2], p + "[2]"));
        for (size_t v = 0; v < t[3].size(); ++v) tooth.xy.push_back(toNumber(t[3][v], p + "[3][" + std::to_string(v) + "]"));
        for (size_t v = 0; v < t[4].size(); ++v) tooth.ridge.push_back(toNumber(t[4][v], p + "[4][" + std::to_string(v) + "]"));
        r.teeth.push_back(std::move(tooth));
    }
    s.features.set(std::move(r));
    s.params.requests.set(RulerRequest{sceneRuler(s)->every_given ? std::optional<int>(sceneRuler(s)->every_x) : std::nullopt});
}

nlohmann::json rulerFactsJson(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return nullptr;
    json south = json::array(), west = json::array();
    // With the data's coordinates, each tooth's x or y in them, and the axes.
    for (const RulerTooth* t : teethOn(*r, true)) {
        json tooth = {{"column_from_west", columnFromWest(*t)}, {"line", t->ordinal}};
        if (s.place.known) tooth["x"] = s.place.x(t->col, t->row);
        south.push_back(std::move(tooth));
    }
    for (const RulerTooth* t : teethOn(*r, false)) {
        json tooth = {{"row_from_south", rowFromSouth(s, *t)}, {"line", t->ordinal}};
        if (s.place.known) tooth["y"] = s.place.y(t->row);
        west.push_back(std::move(tooth));
    }
    json facts = {{"every", {r->every_x, r->every_y}}, {"every_given", r->every_given},
                  {"spacing_mm", {r->spacing_x_mm, r->spacing_y_mm}}, {"lines", {r->lines_x, r->lines_y}},
                  {"tooth_depth_mm", kRulerToothDepthMm}, {"ridge_above_floor_mm", s.zMm(r->top_units - s.floor_units)},
                  {"south_teeth", south}, {"west_teeth", west}};
    if (s.place.known)
        facts["data_axes"] = {{"x", s.place.axes.x}, {"y", s.place.axes.y}, {"unit", s.place.axes.unit}};
    return facts;
}

std::string rulerFactsLines(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return "";
    std::ostringstream o;
    o << "  ruler     " << teethOn(*r, true).size() << " of " << r->lines_x << " teeth on the south edge every "
      << r->every_x << " columns (" << formatFixed(r->spacing_x_mm, 1) << " mm), " << teethOn(*r, false).size() << " of "
      << r->lines_y << " on the west edge every " << r->every_y << " rows (" << formatFixed(r->spacing_y_mm, 1)
      << " mm)" << (r->every_given ? "" : ", chosen") << "; " << formatSignificant(kRulerToothDepthMm)
      << " mm out, a ridge " << formatFixed(s.zMm(r->top_units - s.floor_units), 2) << " mm above the floor\n";
    return o.str();
}

std::string rulerKeyParagraph(const Scene& s, const KeyNumbers& /*numbers*/) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return "";
    std::vector<int32_t> columns, rows;
    const std::vector<const RulerTooth*> south = teethOn(*r, true), west = teethOn(*r, false);
    for (const RulerTooth* t : south) columns.push_back(columnFromWest(*t));
    for (const RulerTooth* t : west) rows.push_back(rowFromSouth(s, *t));
    const std::string rise = formatSignificant(s.zMm(r->top_units - s.floor_units), 2);
    std::string out = "An edge ruler: small teeth stand out at the foot of the south and west edges, each a ridge " + rise +
                      (rise == "1" ? " millimetre" : " millimetres") + " high. ";
    const auto edge = [&](const char* where, const char* order, const std::vector<int32_t>& marks, int every,
                          double mm, const char* what, int32_t of, const char* counted) {
        if (marks.empty()) return std::string("The ") + where + " edge has no tooth: its pillars leave no room. ";
        return std::string("Along the ") + where + " edge, " + order + ", " +
               (marks.size() == 1 ? "the tooth marks " + std::string(what) + " " : "the teeth mark " + std::string(what) + "s ") +
               list(marks) + " of " + std::to_string(of) + ", " + counted + " (every " + std::to_string(every) + ", " +
               formatSignificant(mm, 3) + " millimetres apart). ";
    };
    out += edge("south", "from west to east", columns, r->every_x, r->spacing_x_mm, "column", s.grid.cols,
                "counted from the west") +
           placeSentence(s, south, true, r->every_x);
    out += edge("west", "from south to north", rows, r->every_y, r->spacing_y_mm, "row", s.grid.rows,
                "counted from the south") +
           placeSentence(s, west, false, r->every_y);
    out += "Count the teeth along each edge to say where a value is.";
    return out;
}

std::vector<TactileClaim> rulerTactileClaims(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return {};
    std::vector<TactileClaim> out;
    for (const RulerTooth& t : r->teeth) {
        const double x0 = std::min(t.ridge[0], t.ridge[4]), x1 = std::max(t.ridge[0], t.ridge[4]);
        const double y0 = std::min(t.ridge[1], t.ridge[5]), y1 = std::max(t.ridge[1], t.ridge[5]);
        out.push_back({std::string("the ") + (t.south ? "south" : "west") + " tooth of " +
                           (t.south ? "column " + std::to_string(t.col + 1) : "row " + std::to_string(s.grid.rows - t.row)),
                       0.5 * (x0 + x1), 0.5 * (y0 + y1), s.zMm(r->top_units), s.zMm(s.floor_units), 0.5,
                       std::min(x1 - x0, y1 - y0), 0.0,
                       "heights of at least 0.5 mm to detect (3D-printed tactile graphics, printdisability.org)"});
    }
    return out;
}

std::optional<ScadPiece> rulerScadPiece(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return std::nullopt;
    ScadPiece piece;
    piece.show_switch = "show_ruler";
    piece.variable = "edge_ruler";
    piece.what = "the edge ruler";
    piece.library_file = "tsf_ruler.scad";
    piece.module_call = "tsf_with_ruler(edge_ruler, show_ruler) ";
    piece.header = "/* [Edge ruler] */\n"
                   "// Teeth along the south and west edges, every " + std::to_string(r->every_x) + " columns and " +
                   std::to_string(r->every_y) + " rows (docs/model.md).\n"
                   "show_ruler = true;\n\n"
                   "/* [Hidden] */\n"
                   "// The teeth as tsf placed them, in mm, for the parameters as generated (they do not\n"
                   "// follow cell, base or snap; regenerate with tsf gen to change them): " +
                   std::to_string(r->teeth.size()) + " teeth";
    // [floor, top, [[footprint, ridge], ...]] (scad_lib/tsf_ruler.scad):
    // each [[x, y], ...] counter-clockwise.
    const auto ring = [](const std::vector<double>& xy) {
        std::string o = "[";
        for (size_t i = 0; i + 1 < xy.size(); i += 2)
            o += std::string(i ? ", " : "") + "[" + formatShortest(xy[i]) + ", " + formatShortest(xy[i + 1]) + "]";
        return o + "]";
    };
    std::string& v = piece.value;
    v = "[" + formatShortest(s.zMm(s.floor_units)) + ", " + formatShortest(s.zMm(r->top_units)) + ", [\n";
    for (size_t k = 0; k < r->teeth.size(); ++k)
        v += "  [" + ring(r->teeth[k].xy) + ", " + ring(r->teeth[k].ridge) + (k + 1 < r->teeth.size() ? "],\n" : "]\n");
    v += "]]";
    return piece;
}

}  // namespace tsf
