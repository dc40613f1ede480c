#include "gen/scad/scad_emitter.h"

#include "gen/scad/scad_attachments.h"

#include <algorithm>
#include <limits>
#include <array>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <ostream>
#include <system_error>
#include <unordered_map>

#include <nlohmann/json.hpp>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "gen/scad/scad_library.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace fs = std::filesystem;

namespace {

// Shortest decimal text that OpenSCAD parses back to exactly `v` (OpenSCAD
// 2021.01 reads decimals correctly rounded; checked in tests/scad).

// One line of text safe inside a // comment.
std::string oneLine(const std::string& s) {
    std::string out = s;
    for (char& ch : out)
        if (static_cast<unsigned char>(ch) < 0x20) ch = ' ';
    return out;
}

// The largest of the usual slider steps that `v` is a whole multiple of, or
// the finest one: the customizer then shows the value without rounding it.
double sliderStep(double v, std::initializer_list<double> steps) {
    for (double step : steps)
        if (std::round(v / step) * step == v) return step;
    return *(steps.end() - 1);
}

std::string range(double lo, double step, double hi) {
    return "// [" + formatShortest(lo) + ":" + formatShortest(step) + ":" + formatShortest(hi) + "]";
}

// The customizer parameters with their values for a Scene, in file order.
struct Parameters {
    double cell_mm, max_height_mm, baseline, value_max, z_step_mm, base_mm;
    std::string transfer;
    bool mirrored;
};

Parameters parametersOf(const Scene& s) {
    return {s.pitch_mm,       s.mapping.max_height_mm, s.mapping.baseline,
            s.mapping.value_max, s.z_snap_mm,        s.params.base_mm,
            toString(s.mapping.transfer), s.params.bottom == Bottom::Mirrored};
}

// Library parts a strategy needs, in the order they are pasted.
std::vector<std::string> libraryParts(ScadOptions::Strategy strategy, bool marks, bool shaped,
                                      const std::vector<ScadAttachment>& attachments) {
    std::vector<std::string> parts{"tsf_model.scad", "tsf_polyhedron.scad"};
    const auto add = [&parts](const std::string& part) {
        if (std::find(parts.begin(), parts.end(), part) == parts.end()) parts.push_back(part);
    };
    if (strategy == ScadOptions::Strategy::Csg && !shaped) add("tsf_csg.scad");
    if (marks) add("tsf_marks.scad");
    // A joined attachment's cells are drawn by corner, as shaped tops are.
    const bool joined = std::any_of(attachments.begin(), attachments.end(), [](const ScadAttachment& a) { return !a.joined.empty(); });
    if (shaped || joined) add("tsf_tilt.scad");
    for (const ScadAttachment& a : attachments) add(a.library_file);
    return parts;
}

// True when some top is tilted or dimpled (gen/model/features/top_shapes.h).
bool hasShapedTops(const Scene& s) {
    return std::find(s.shapes.shaped.begin(), s.shapes.shaped.end(), uint8_t(1)) != s.shapes.shaped.end();
}

std::string stemOf(const std::string& file_name) { return fs::path(file_name).stem().string(); }

void emitHeader(std::string& o, const Scene& s, const ScadOptions& opts, const std::string& file_name) {
    const std::string name = fs::path(file_name).filename().string();
    const std::string stem = stemOf(file_name);
    const bool csg = opts.strategy == ScadOptions::Strategy::Csg;
    o += "// " + oneLine(name) + " - a tactile model of hexagonal pillars, written by tsf " TSF_VERSION "\n//\n";
    if (!opts.source.empty()) o += "// Source:    " + oneLine(opts.source) + "\n";
    if (!opts.command.empty()) o += "// Command:   " + oneLine(opts.command) + "\n";
    o += "// Grid:      " + std::to_string(s.grid.cols) + " columns x " + std::to_string(s.grid.rows) + " rows, " +
         std::to_string(s.keptCount()) + " cells with a pillar";
    if (s.cells_nodata_kept > 0) o += " (" + std::to_string(s.cells_nodata_kept) + " without data, as pits below the floor)";
    o += "\n";
    o += std::string("// Bottom:    ") +
         (s.params.bottom == Bottom::Mirrored ? "mirrored (the underside shows the data negated)" : "flat") + "\n";
    o += std::string("// Strategy:  ") +
         (csg ? "csg - a union of one prism per cell, done by CGAL: exact and editable per\n"
                "//            pillar, but slow (minutes for a few thousand cells)\n"
              : "polyhedron - the terrain is one closed polyhedron() built from the values;\n"
                "//            renders in seconds\n");
    for (const std::string& note : s.notes) o += "// Note:      " + oneLine(note) + "\n";
    o += "//\n"
         "// Render to STL with plain OpenSCAD (nothing else is needed):\n"
         "//   openscad -o " + stem + ".stl --export-format binstl " + name + "\n"
         "// The same through tsf (progress, timing, clear errors, a PNG preview):\n"
         "//   tsf render " + name + " -o " + stem + ".stl --png " + stem + ".png\n"
         "// Change a parameter for one render, or use a saved parameter set (" + stem + ".json):\n"
         "//   tsf render " + name + " -o " + stem + ".stl -D height=25\n"
         "//   openscad -p " + stem + ".json -P \"mirrored bottom\" -o " + stem + ".stl --export-format binstl " + name + "\n"
         "// Export binary STL (binstl) or 3MF: OpenSCAD's ASCII STL keeps only 6 significant digits.\n"
         "//\n"
         "// To edit: change a parameter below (in the OpenSCAD GUI: Window > Customizer), or\n"
         "// a number in `values` further down, and render again (F6).\n\n";
}

void emitParameters(std::string& o, const Scene& s) {
    const Parameters p = parametersOf(s);
    o += "/* [Model size] */\n"
         "// Distance between neighbouring hexagon centres = width across flats (mm)\n"
         "cell = " + formatShortest(p.cell_mm) + ";  " +
         range(p.cell_mm < 1 ? 0.05 : 1, sliderStep(p.cell_mm, {0.5, 0.1, 0.01, 0.001}),
               std::max(50.0, std::ceil(2 * p.cell_mm))) + "\n\n";

    o += "/* [Heights] */\n"
         "// Height of the pillar for value_max above the floor (mm)\n"
         "height = " + formatShortest(p.max_height_mm) + ";  " +
         range(0, sliderStep(p.max_height_mm, {0.5, 0.1, 0.01, 0.001}), std::max(100.0, std::ceil(2 * p.max_height_mm))) +
         "\n"
         "// How a value becomes a height: linear, sqrt (counts, areas) or log (two decades)\n"
         "transfer = \"" + p.transfer + "\";  // [linear, sqrt, log]\n"
         "// Value at the floor, height 0 (data units); smaller values sit at the floor\n"
         "baseline = " + formatShortest(p.baseline) + ";\n"
         "// Value at full height (data units); larger values are capped\n"
         "value_max = " + formatShortest(p.value_max) + ";\n"
         "// Height grid (mm): every height is rounded to a multiple of it; your layer height gives crisp steps\n"
         "snap = " + formatShortest(p.z_step_mm) + ";  " +
         range(std::min(0.001, p.z_step_mm), sliderStep(p.z_step_mm, {0.001, 0.0001, 0.00001, 0.000001}), 1) + "\n\n";

    o += "/* [Base] */\n"
         "// Flat bottom: thickness under the floor. Mirrored bottom: thinnest point of the slab (mm, >= snap)\n"
         "base = " + formatShortest(p.base_mm) + ";  " +
         range(std::min(0.1, p.base_mm), sliderStep(p.base_mm, {0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001}),
               std::max(20.0, std::ceil(2 * p.base_mm))) + "\n\n";

    o += "/* [Mirror] */\n"
         "// The underside shows the data negated; every pillar has the same thickness\n"
         "mirror = " + std::string(p.mirrored ? "true" : "false") + ";\n\n";

    if (s.faces.empty()) return;
    o += "/* [Orientation marks] */\n"
         "// The V notch at the origin (south-west) corner and the raised right triangle (long leg east)\n"
         "orientation_marks = true;\n"
         "// How far the triangle stands above its flat region (mm)\n"
         "mark_height = " + formatShortest(s.params.marks.triangle_height_mm) + ";  " +
         range(0.1, 0.1, std::max(5.0, std::ceil(2 * s.params.marks.triangle_height_mm))) + "\n\n";
}

// "[col, row]" of a kept cell.
std::string cellRef(const Scene& s, int32_t kept) {
    return "[" + std::to_string(s.col[size_t(kept)]) + ", " + std::to_string(s.row[size_t(kept)]) + "]";
}

// The faces of the orientation marks as data for tsf_marks.scad (see there).
void emitMarks(std::string& o, const Scene& s) {
    if (s.faces.empty()) return;
    const int64_t lattice = latticeVertexIdCount(s.grid);
    // Which faces have a planar vertex on a ring, for the "at" lists.
    std::unordered_map<int64_t, std::vector<int32_t>> faces_at;
    for (size_t f = 0; f < s.faces.faces.size(); ++f)
        for (const auto& ring : s.faces.faces[f].rings)
            for (int64_t id : ring) {
                auto& at = faces_at[id];
                if (std::find(at.begin(), at.end(), int32_t(f)) == at.end()) at.push_back(int32_t(f));
            }
    o += "// ----------------------------------------------------------------- Marks ---\n"
         "// Orientation marks placed by tsf (docs/model.md): each entry is a piece of the\n"
         "// footprint drawn instead of the hexagons it covers (format: tsf_marks.scad).\n"
         "// Heights still come from `values` and the parameters above.\n"
         "marks = [\n";
    for (size_t f = 0; f < s.faces.faces.size(); ++f) {
        const PlanarFace& face = s.faces.faces[f];
        std::vector<int64_t> ids;
        std::unordered_map<int64_t, size_t> local;
        for (const auto& ring : face.rings)
            for (int64_t id : ring)
                if (local.emplace(id, ids.size()).second) ids.push_back(id);
        std::string points, tris, rings, across, at, cells;
        for (int64_t id : ids) {
            PlanarPoint p;
            if (id < lattice) {
                const LatticePoint q = latticeVertexPoint(s.grid, id);
                p = {double(q.i), double(q.j)};
            } else {
                p = s.faces.extra[size_t(id - lattice)];
            }
            points += std::string(points.empty() ? "" : ", ") + "[" + formatShortest(p.i) + ", " + formatShortest(p.j) + "]";
            std::string refs;
            if (id < lattice) {
                int32_t col[3], row[3];
                latticeVertexCells(s.grid, id, col, row);
                for (int n = 0; n < 3; ++n) {
                    const int32_t k = s.keptAt(col[n], row[n]);
                    if (k >= 0 && !s.drawn_by_face[size_t(k)]) refs += std::string(refs.empty() ? "" : ", ") + cellRef(s, k);
                }
            }
            for (int32_t g : faces_at[id]) refs += std::string(refs.empty() ? "" : ", ") + "[" + std::to_string(g) + "]";
            at += std::string(at.empty() ? "" : ", ") + "[" + refs + "]";
        }
        for (const auto& t : face.triangles)
            tris += std::string(tris.empty() ? "" : ", ") + "[" + std::to_string(local[t[0]]) + ", " +
                    std::to_string(local[t[1]]) + ", " + std::to_string(local[t[2]]) + "]";
        for (size_t r = 0; r < face.rings.size(); ++r) {
            std::string ring, ac;
            for (size_t n = 0; n < face.rings[r].size(); ++n) {
                ring += std::string(n ? ", " : "") + std::to_string(local[face.rings[r][n]]);
                const Across& a = face.across[r][n];
                ac += std::string(n ? ", " : "") +
                      (a.kind == Across::Kind::Outside ? std::string("undef")
                       : a.kind == Across::Kind::Cell  ? cellRef(s, a.index)
                                                       : "[" + std::to_string(a.index) + "]");
            }
            rings += std::string(r ? ", " : "") + "[" + ring + "]";
            across += std::string(r ? ", " : "") + "[" + ac + "]";
        }
        for (int32_t k : face.cells) cells += std::string(cells.empty() ? "" : ", ") + cellRef(s, k);
        o += "    [" + cellRef(s, face.anchor) + ", " + (face.raise_units > 0 ? "true" : "false") + ",\n" +
             "     [" + points + "],\n" +
             "     [" + tris + "],\n" +
             "     [" + rings + "],\n" +
             "     [" + across + "],\n" +
             "     [" + at + "],\n" +
             "     [" + cells + "]]" + (f + 1 < s.faces.faces.size() ? "," : "") + "  // face " + std::to_string(f) +
             (face.raise_units > 0 ? ": the triangle" : face.cells.size() > 1 ? ": the triangle's flat region" : ": cut by the notch") +
             "\n";
    }
    o += "];\n\n";
}

std::string cornerList(const std::array<int32_t, 6>& dz) {
    std::string t = "[";
    for (size_t e = 0; e < 6; ++e) t += (e ? ", " : "") + std::to_string(dz[e]);
    return t + "]";
}

std::string crossingList(const Scene& s, const std::vector<int64_t>& crossing, size_t k) {
    std::string t = "[";
    for (size_t e = 0; e < 6; ++e) {
        const int64_t id = crossing[6 * k + e];
        t += e ? ", " : "";
        if (id < 0) {
            t += "undef";
            continue;
        }
        const size_t n = size_t(id - s.shapes.first_id);
        t += "[" + formatShortest(s.shapes.extra[n].i) + ", " + formatShortest(s.shapes.extra[n].j) + ", " +
             std::to_string(s.shapes.extra_z[n]) + "]";
    }
    return t + "]";
}

// Tilted and dimpled tops as data for tsf_tilt.scad (see there), one grid row per line.
void emitTops(std::string& o, const Scene& s) {
    if (!hasShapedTops(s)) return;
    const TopShapes& t = s.shapes;
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    const Parameters p = parametersOf(s);
    o += "// ------------------------------------------------------------------ Tops ---\n"
         "// Tilted tops and dimpled structural cells, resolved by tsf (docs/model.md):\n"
         "// per cell undef (a level hexagon) or [corner offsets of the top (z steps),\n"
         "// centre offset, the same for a mirrored bottom, where the top crosses each\n"
         "// neighbour [i, j, z], the same for the bottoms] (format: tsf_tilt.scad).\n"
         "// They hold for the values and parameters above: run tsf gen again to change those.\n"
         "tops_made_for = [" + formatShortest(p.cell_mm) + ", " + formatShortest(p.max_height_mm) + ", \"" + p.transfer + "\", " +
         formatShortest(p.baseline) + ", " + formatShortest(p.value_max) + ", " + formatShortest(p.z_step_mm) + ", " + formatShortest(p.base_mm) + ", " +
         (p.mirrored ? "true" : "false") + "];\n"
         "tops_thickness = " + std::to_string(mirrored ? s.mirror_thickness_units : 0) + ";\n"
         "tops = [\n";
    for (int32_t r = 0; r < s.grid.rows; ++r) {
        std::string line = "    [";
        for (int32_t c = 0; c < s.grid.cols; ++c) {
            const int32_t k = s.keptAt(c, r);
            line += c ? ", " : "";
            if (k < 0 || !t.shaped[size_t(k)] || (!s.drawn_by_face.empty() && s.drawn_by_face[size_t(k)])) {
                line += "undef";
                continue;
            }
            const size_t kk = size_t(k);
            line += "[" + cornerList(t.top_dz[kk]) + ", " + std::to_string(t.top_centre_dz[kk]) + ", " +
                    (mirrored ? cornerList(t.bottom_dz[kk]) + ", " + std::to_string(t.bottom_centre_dz[kk]) : "[], 0") + ", " +
                    crossingList(s, t.crossing_top, kk) + ", " + (mirrored ? crossingList(s, t.crossing_bottom, kk) : "[]") +
                    "]";
        }
        o += line + (r + 1 < s.grid.rows ? "],\n" : "]\n");
    }
    o += "];\n\n";
}

void emitValues(std::string& o, const Scene& s) {
    const HexGrid& g = s.grid;
    std::vector<std::string> cells(size_t(g.cellCount()));
    size_t width = 0;
    for (int32_t r = 0; r < g.rows; ++r) {
        for (int32_t c = 0; c < g.cols; ++c) {
            const int32_t k = s.keptAt(c, r);
            std::string& text = cells[size_t(g.index(c, r))];
            text = k < 0 ? "undef" : std::isnan(s.value[size_t(k)]) ? "nodata" : formatShortest(s.value[size_t(k)]);
            width = std::max(width, text.size());
        }
    }
    o += "/* [Hidden] */\n\n"
         "// ------------------------------------------------------------------ Data ---\n"
         "// The cell values: one row of the hex grid per line, north row first, west to\n"
         "// east; odd rows (1, 3, ...) are shifted half a cell east.\n"
         "//   undef  = no pillar (outside the model)\n"
         "//   nodata = no value: a pit below the floor (inside the model)\n"
         "// Change a number and render again; write a number over undef to add a pillar.\n"
         "nodata = \"nodata\";\n";
    if (s.y_scale != 1.0) {
        o += "// True aspect: the hexagons are stretched north-south by this factor, so rows of\n"
             "// pillars stand one cell apart as the raster's rows do on the ground (1 = regular\n"
             "// hexagons, rows 0.866 of a cell apart). Every module of the tsf library reads it.\n"
             "$tsf_y_scale = " + formatShortest(s.y_scale) + ";\n";
    }
    o += "values = [\n";
    for (int32_t r = 0; r < g.rows; ++r) {
        std::string line = "    [";
        for (int32_t c = 0; c < g.cols; ++c) {
            const std::string& text = cells[size_t(g.index(c, r))];
            if (c > 0) line += ", ";
            line.append(width - text.size(), ' ');
            line += text;
        }
        line += r + 1 < g.rows ? "]," : "] ";
        line += "  // row " + std::to_string(r);
        if (r == 0) line += " (north)";
        if (r + 1 == g.rows && g.rows > 1) line += " (south)";
        o += line + "\n";
    }
    o += "];\n\n";
}

void emitCall(std::string& o, const Scene& s, const ScadOptions& opts, const std::vector<ScadAttachment>& attachments) {
    // The features' modules wrap the terrain call, the first innermost.
    std::string wrap, joined;
    for (auto a = attachments.rbegin(); a != attachments.rend(); ++a) wrap += a->call_prefix;
    for (const ScadAttachment& a : attachments)
        if (!a.joined.empty()) joined += (joined.empty() ? "" : ",\n                                  ") + a.joined;
    const std::string polyhedron =
        joined.empty() ? "tsf_terrain_polyhedron(model);\n" : "tsf_terrain_polyhedron(model, joined = [" + joined + "]);\n";
    o += "// ----------------------------------------------------------------- Model ---\n";
    if (!opts.inline_library) o += std::string("use <") + kScadLibraryCopyDir + "/" + kScadLibraryEntry + ">\n";
    o += "model = tsf_model(values, cell_mm = cell, max_height_mm = height, base_mm = base,\n"
         "                  transfer = transfer, baseline = baseline, value_max = value_max,\n"
         "                  z_step_mm = snap, mirrored = mirror";
    if (!s.faces.empty()) o += ",\n                  faces = orientation_marks ? marks : [], mark_height_mm = mark_height";
    const bool shaped = hasShapedTops(s);
    if (shaped) o += ",\n                  shapes = tops, min_thickness_units = tops_thickness";
    if (s.params.bottom == Bottom::Mirrored) {
        // The room tsf's Scene keeps below the lowest cell with data (a
        // texture's relief; tilted tops: all of it): the model stands on z = 0.
        int64_t room = std::numeric_limits<int64_t>::max();
        for (size_t k = 0; k < s.keptCount(); ++k)
            if (s.kind[k] == CellKind::Data) room = std::min(room, s.bottom[k]);
        if (room > 0 && room != std::numeric_limits<int64_t>::max())
            o += ",\n                  mirror_room_units = " + std::to_string(room);
    }
    for (const ScadAttachment& a : attachments) o += a.model_argument;
    o += ");\n";
    if (shaped) {
        o += "assert([cell, height, transfer, baseline, value_max, snap, base, mirror] == tops_made_for,\n"
             "       \"the tilted tops were resolved by tsf for the parameters it wrote; run tsf gen again to change them\");\n";
        // The CSG strategy's prisms have level tops: a shaped model is one polyhedron.
        if (opts.strategy == ScadOptions::Strategy::Csg)
            o += "// Tilted tops are drawn as one polyhedron (the CSG strategy's prisms have level tops).\n";
        o += wrap + polyhedron;
        return;
    }
    o += wrap;
    o += opts.strategy == ScadOptions::Strategy::Csg ? "tsf_terrain_csg(model);\n" : polyhedron;
}

void emitInlineLibrary(std::string& o, const Scene& s, const ScadOptions& opts,
                       const std::vector<ScadAttachment>& attachments) {
    const std::string dir = opts.library_dir.empty() ? scadLibraryDir() : opts.library_dir;
    const std::vector<std::string> parts = libraryParts(opts.strategy, !s.faces.empty(), hasShapedTops(s), attachments);
    std::string list;
    for (const std::string& part : parts) list += (list.empty() ? "" : ", ") + part;
    o += "\n// ---------------------------------------------------- tsf OpenSCAD library ---\n"
         "// " + list + " from tsf " TSF_VERSION ", pasted here so that this\n"
         "// file needs nothing else. The whole library, with the orientation marks, is\n"
         "// scad_lib/ in the tsf sources (installed in share/tsf/scad_lib).\n\n";
    for (const std::string& part : parts) {
        std::string text = readScadLibraryFile(dir, part);
        if (!text.empty() && text.back() != '\n') text += '\n';
        o += text + "\n";
    }
}

void requireScadPath(const std::string& path) {
    if (fs::path(path).extension() != ".scad")
        throw InputError(path, 0, 0, "an OpenSCAD file name must end in .scad");
}

}  // namespace

const char* toString(ScadOptions::Strategy strategy) {
    return strategy == ScadOptions::Strategy::Csg ? "csg" : "polyhedron";
}

bool parseScadStrategy(const std::string& text, ScadOptions::Strategy& strategy) {
    if (text == "polyhedron") { strategy = ScadOptions::Strategy::Polyhedron; return true; }
    if (text == "csg") { strategy = ScadOptions::Strategy::Csg; return true; }
    return false;
}

std::vector<std::string> scadParameterNames() {
    return {"cell", "height", "transfer", "baseline", "value_max", "snap", "base", "mirror"};
}

std::string emitScad(const Scene& scene, const ScadOptions& opts, const std::string& file_name) {
    if (scene.keptCount() == 0) throw InputError("the model has no cell to draw; nothing to write to " + file_name);
    std::string o;
    emitHeader(o, scene, opts, file_name);
    emitParameters(o, scene);
    emitValues(o, scene);
    emitMarks(o, scene);
    emitTops(o, scene);
    // The terrain is one polyhedron unless it is the CSG strategy's union of level prisms.
    const bool one_polyhedron = opts.strategy == ScadOptions::Strategy::Polyhedron || hasShapedTops(scene);
    const std::vector<ScadAttachment> attachments = scadAttachments(scene, one_polyhedron);
    for (const ScadAttachment& a : attachments) o += a.data;
    emitCall(o, scene, opts, attachments);
    if (opts.inline_library) emitInlineLibrary(o, scene, opts, attachments);
    return o;
}

namespace {
// The parameter sets tsf writes; any other name in the file was saved by a person.
constexpr const char* kSetAsGenerated = "as generated";
constexpr const char* kSetLayerSteps = "layer steps 0.2 mm";
constexpr const char* kSetFlatBottom = "flat bottom";
constexpr const char* kSetMirroredBottom = "mirrored bottom";
constexpr const char* kSetHalfSize = "half size";
}  // namespace

std::string emitScadParameterSets(const Scene& scene) {
    const Parameters p = parametersOf(scene);
    nlohmann::ordered_json all;
    all["cell"] = formatShortest(p.cell_mm);
    all["height"] = formatShortest(p.max_height_mm);
    all["transfer"] = p.transfer;
    all["baseline"] = formatShortest(p.baseline);
    all["value_max"] = formatShortest(p.value_max);
    all["snap"] = formatShortest(p.z_step_mm);
    all["base"] = formatShortest(p.base_mm);
    all["mirror"] = p.mirrored ? "true" : "false";
    if (!scene.faces.empty()) {
        all["orientation_marks"] = "true";
        all["mark_height"] = formatShortest(scene.params.marks.triangle_height_mm);
    }

    // A coarse height grid must stay below the base (base >= snap).
    constexpr double kLayerMm = 0.2;  // a common FDM layer height
    nlohmann::ordered_json layers;
    layers["snap"] = formatShortest(kLayerMm);
    if (p.base_mm < kLayerMm) layers["base"] = formatShortest(kLayerMm);

    nlohmann::ordered_json flip;
    flip["mirror"] = p.mirrored ? "false" : "true";

    nlohmann::ordered_json half;
    half["cell"] = formatShortest(p.cell_mm / 2);
    half["height"] = formatShortest(p.max_height_mm / 2);
    half["base"] = formatShortest(std::max(p.base_mm / 2, p.z_step_mm));

    // What stands where tsf placed it for the parameters as generated (the
    // orientation tab, the legend's plate; the file asserts the tab's): the
    // other sets leave it out (a mirrored model's plate would float over a
    // flat one).
    for (const ScadAttachment& a : scadAttachments(scene, /*join=*/false)) {
        if (a.placed_switch.empty()) continue;
        all[a.placed_switch] = "true";
        for (nlohmann::ordered_json* set : {&layers, &flip, &half}) (*set)[a.placed_switch] = "false";
    }

    nlohmann::ordered_json sets;
    sets[kSetAsGenerated] = all;
    sets[kSetLayerSteps] = layers;
    sets[p.mirrored ? kSetFlatBottom : kSetMirroredBottom] = flip;
    sets[kSetHalfSize] = half;
    nlohmann::ordered_json doc;
    doc["parameterSets"] = sets;
    doc["fileFormatVersion"] = "1";
    return doc.dump(4) + "\n";
}

bool isTsfParameterSetFile(const std::string& json_text) {
    const nlohmann::json doc = nlohmann::json::parse(json_text, nullptr, /*allow_exceptions=*/false);
    if (!doc.is_object() || !doc.contains("parameterSets") || !doc["parameterSets"].is_object()) return false;
    for (const auto& [name, set] : doc["parameterSets"].items())
        if (name != kSetAsGenerated && name != kSetLayerSteps && name != kSetFlatBottom &&
            name != kSetMirroredBottom && name != kSetHalfSize)
            return false;
    return true;
}

std::vector<std::string> scadOutputPaths(const ScadOptions& opts, const std::string& path) {
    const fs::path p(path);
    std::vector<std::string> out{path};
    if (opts.write_parameter_sets) out.push_back((p.parent_path() / (p.stem().string() + ".json")).string());
    if (!opts.inline_library) {
        const std::string dir = opts.library_dir.empty() ? scadLibraryDir() : opts.library_dir;
        for (const std::string& name : scadLibraryFiles(dir))
            out.push_back((p.parent_path() / kScadLibraryCopyDir / name).string());
    }
    return out;
}

void writeScad(const Scene& scene, const ScadOptions& opts, const std::string& path) {
    requireScadPath(path);
    ScadOptions resolved = opts;
    if (resolved.library_dir.empty()) resolved.library_dir = scadLibraryDir();
    // Everything is built in memory first, so a failure writes nothing.
    const std::string text = emitScad(scene, resolved, path);
    const std::string sets = resolved.write_parameter_sets ? emitScadParameterSets(scene) : std::string();
    const std::vector<std::string> outputs = scadOutputPaths(resolved, path);

    if (!resolved.inline_library) {
        const fs::path lib_dir = fs::path(path).parent_path() / kScadLibraryCopyDir;
        std::error_code ec;
        fs::create_directories(lib_dir, ec);
        if (ec) throw InputError(lib_dir.string(), 0, 0, "cannot create the library folder: " + ec.message());
        for (const std::string& name : scadLibraryFiles(resolved.library_dir)) {
            const std::string lib_text = readScadLibraryFile(resolved.library_dir, name);
            writeFileAtomically((lib_dir / name).string(), [&](std::ostream& out) { out << lib_text; });
        }
    }
    if (resolved.write_parameter_sets)
        writeFileAtomically(outputs[1], [&](std::ostream& out) { out << sets; });
    writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace tsf
