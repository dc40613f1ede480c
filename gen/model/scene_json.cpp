// Scene <-> JSON sidecar. See scene_json.h.
#include "gen/model/scene_json.h"

#include <charconv>

#include <array>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <sstream>
#include <tuple>
#include <utility>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "gen/util/file_bytes.h"
#include "gen/model/feature_records.h"
#include "gen/model/sidecar_fields.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/top_shapes.h"

namespace tsf {

using namespace sidecar;

namespace {

constexpr Transfer kTransfers[] = {Transfer::Linear, Transfer::Sqrt, Transfer::Log};
constexpr Cull kCulls[] = {Cull::None, Cull::Hull, Cull::Concave};
constexpr Bottom kBottoms[] = {Bottom::Flat, Bottom::Mirrored};
constexpr BaselineMode kBaselines[] = {BaselineMode::Auto, BaselineMode::Zero, BaselineMode::Min, BaselineMode::Value};

// 1-based line and column of a byte offset in text.
void lineColumn(const std::string& text, size_t byte, int& line, int& column) {
    line = 1;
    column = 1;
    for (size_t i = 0; i < byte && i < text.size(); ++i) {
        if (text[i] == '\n') {
            ++line;
            column = 1;
        } else {
            ++column;
        }
    }
}

// nlohmann's messages start "[json.exception.parse_error.101] parse error at
// line L, column C: "; keep what follows the last such prefix.
std::string withoutPrefix(const std::string& what) {
    const auto colon = what.find(": ");
    if (what.rfind("[json.exception.", 0) == 0 && colon != std::string::npos) return what.substr(colon + 2);
    const auto bracket = what.find("] ");
    return bracket != std::string::npos ? what.substr(bracket + 2) : what;
}

}  // namespace

namespace {
// How a shaped cell is drawn (version 5): the planar ids of its fan's centre
// and of the points where its edges cross a neighbour's tilted top.
json fanJson(const Scene& s, size_t k) {
    const TopShapes& t = s.shapes;
    const auto crossings = [&](const std::vector<int64_t>& all) {
        return std::vector<int64_t>(all.begin() + std::ptrdiff_t(kHexCorners * k),
                                    all.begin() + std::ptrdiff_t(kHexCorners * (k + 1)));
    };
    json f = {{"centre_top", t.centre_top_id[k]}, {"crossings_top", crossings(t.crossing_top)}};
    if (s.params.bottom == Bottom::Mirrored) {
        f["centre_bottom"] = t.centre_bottom_id[k];
        f["crossings_bottom"] = crossings(t.crossing_bottom);
    }
    return f;
}

// True when kept cell k has a "shape" member: offsets of its own (a tilt,
// a dimple or bump, a structural cell). Needs non-empty shapes.
bool hasShapeRecord(const TopShapes& t, size_t k) {
    bool any = t.top_centre_dz[k] != 0 || t.structural[k];
    for (int32_t dz : t.top_dz[k]) any = any || dz != 0;
    return any;
}

// True when kept cell k is written without "fan" or "shape" (cellJson).
bool plainCell(const Scene& s, size_t k) {
    const TopShapes& t = s.shapes;
    return t.empty() || (!isShaped(t, k) && !hasShapeRecord(t, k));
}

// A plain cell's line as cellJson(...).dump() writes it (members in
// nlohmann's key order, its number format for the value), without building
// the object: a million-cell sidecar spends its time here.
void appendPlainCell(std::string& out, const Scene& s, size_t k) {
    char buf[24];
    auto integer = [&](const char* key, int64_t v) {
        out += key;
        out.append(buf, size_t(std::to_chars(buf, buf + sizeof buf, v).ptr - buf));
    };
    integer("{\"bottom\":", s.bottom[k]);
    integer(",\"col\":", s.col[k]);
    integer(",\"row\":", s.row[k]);
    integer(",\"top\":", s.top[k]);
    out += ",\"value\":";
    out += std::isnan(s.value[k]) ? std::string("null") : json(s.value[k]).dump();
    out += '}';
}

json cellJson(const Scene& s, size_t k) {
    json c = {{"col", s.col[k]}, {"row", s.row[k]}, {"value", numberOrNull(s.value[k])}, {"top", s.top[k]},
              {"bottom", s.bottom[k]}};
    const TopShapes& t = s.shapes;
    if (t.empty()) return c;
    if (isShaped(t, k)) c["fan"] = fanJson(s, k);
    if (!hasShapeRecord(t, k)) return c;
    json shape = {{"top_dz", t.top_dz[k]}, {"centre_dz", t.top_centre_dz[k]}, {"slope", {t.slope_x[k], t.slope_y[k]}},
                  {"structural", bool(t.structural[k])}};
    if (!t.bottom_dz.empty()) {
        shape["bottom_dz"] = t.bottom_dz[k];
        shape["bottom_centre_dz"] = t.bottom_centre_dz[k];
    }
    c["shape"] = std::move(shape);
    return c;
}


json pointsJson(const std::vector<PlanarPoint>& points) {
    json a = json::array();
    for (const PlanarPoint& p : points) a.push_back({p.i, p.j});
    return a;
}

// The planar faces the marks need, as built (version 5): read back as they
// are, so reading a sidecar triangulates nothing.
json facesJson(const Scene& s) {
    if (s.faces.empty()) return nullptr;
    json faces = json::array();
    for (const PlanarFace& f : s.faces.faces) {
        json across = json::array();
        for (const auto& ring : f.across) {
            json r = json::array();
            for (const Across& a : ring) r.push_back({int(a.kind), a.index});
            across.push_back(std::move(r));
        }
        faces.push_back({{"anchor", f.anchor},
                         {"raise_units", f.raise_units},
                         {"cells", f.cells},
                         {"rings", f.rings},
                         {"across", across},
                         {"triangles", f.triangles},
                         {"read_point", f.read_point ? json{f.read_point->i, f.read_point->j} : json(nullptr)}});
    }
    return {{"extra", pointsJson(s.faces.extra)}, {"faces", faces}};
}

json shapesJson(const Scene& s) {
    const TopShapes& t = s.shapes;
    if (t.empty()) return nullptr;
    return {{"tilt", toString(s.params.tilt)}, {"steepness", s.params.steepness},
            {"structural_texture", s.params.structural_texture}, {"cells_tilted", t.cells_tilted},
            {"cells_clamped", t.cells_clamped}, {"cells_clamped_level", t.cells_flat_clamped},
            {"cells_textured", t.cells_textured}, {"dimple_units", t.dimple_units}, {"first_id", t.first_id},
            {"extra", pointsJson(t.extra)}, {"extra_z", t.extra_z}};
}

json pointJson(const PlanarPoint& p) { return json::array({p.i, p.j}); }

json marksJson(const Marks& m) {
    json j = json::object();
    if (m.notch)
        j["notch"] = {{"apex", pointJson(m.notch->apex)},         {"mouth_a", pointJson(m.notch->mouth_a)},
                      {"mouth_b", pointJson(m.notch->mouth_b)},   {"depth_mm", m.notch->depth_mm},
                      {"width_mm", m.notch->width_mm},            {"opening_deg", m.notch->opening_deg}};
    else
        j["notch"] = nullptr;
    if (m.triangle)
        j["triangle"] = {{"corner", pointJson(m.triangle->corner)}, {"east", pointJson(m.triangle->east)},
                         {"north", pointJson(m.triangle->north)},   {"leg_x_mm", m.triangle->leg_x_mm},
                         {"leg_y_mm", m.triangle->leg_y_mm},        {"raise_units", m.triangle->raise_units},
                         {"anchor", m.triangle->anchor}};
    else
        j["triangle"] = nullptr;
    return j;
}

PlanarPoint pointFrom(const json& obj, const std::string& path, const char* key) {
    const json& v = member(obj, path, key);
    const std::string p = join(path, key);
    if (!v.is_array() || v.size() != 2) fail(p, "expected [i, j]");
    const PlanarPoint q{toNumber(v[0], p + "[0]"), toNumber(v[1], p + "[1]")};
    if (!std::isfinite(q.i) || !std::isfinite(q.j)) fail(p, "expected finite numbers");
    return q;
}

// A mark's point lies on its model: within the grid's lattice box grown by
// the box's own size on every side (a notch's mouth may open beyond the
// outermost cells). Further out is no mark of this grid, and would make the
// cells it is sought among unbounded.
PlanarPoint markPointFrom(const json& obj, const std::string& path, const char* key, const HexGrid& g) {
    const PlanarPoint q = pointFrom(obj, path, key);
    const double w = 2.0 * g.cols + 2, d = 3.0 * g.rows + 2;  // the box in lattice units (hex_grid.h)
    if (q.i < -w || q.i > 2 * w || q.j < -d || q.j > 2 * d) fail(join(path, key), "lies far outside the grid");
    return q;
}

Marks marksFrom(const json& j, const std::string& path, const HexGrid& g) {
    Marks m;
    const json& notch = member(j, path, "notch");
    if (!notch.is_null()) {
        const std::string np = join(path, "notch");
        Notch n;
        n.apex = markPointFrom(notch, np, "apex", g);
        n.mouth_a = markPointFrom(notch, np, "mouth_a", g);
        n.mouth_b = markPointFrom(notch, np, "mouth_b", g);
        n.depth_mm = getNumber(notch, np, "depth_mm");
        n.width_mm = getNumber(notch, np, "width_mm");
        n.opening_deg = getNumber(notch, np, "opening_deg");
        m.notch = n;
    }
    const json& tri = member(j, path, "triangle");
    if (!tri.is_null()) {
        const std::string tp = join(path, "triangle");
        OrientationTriangle t;
        t.corner = markPointFrom(tri, tp, "corner", g);
        t.east = markPointFrom(tri, tp, "east", g);
        t.north = markPointFrom(tri, tp, "north", g);
        t.leg_x_mm = getNumber(tri, tp, "leg_x_mm");
        t.leg_y_mm = getNumber(tri, tp, "leg_y_mm");
        t.raise_units = getInt(tri, tp, "raise_units");
        if (t.raise_units < 1) fail(join(tp, "raise_units"), "must be at least 1");
        t.anchor = getInt32(tri, tp, "anchor", 0, std::numeric_limits<int32_t>::max());
        m.triangle = t;
    }
    return m;
}

json sceneHeadJson(const Scene& s) {
    const SceneParams& p = s.params;
    json hull = json::array();
    for (const LatticePoint& q : s.hull) hull.push_back({q.i, q.j});
    json head = {
        {"format", kSceneJsonFormat},
        {"version", kSceneJsonVersion},
        {"grid", {{"cols", s.grid.cols}, {"rows", s.grid.rows}}},
        {"pitch_mm", s.pitch_mm},
        {"y_scale", s.y_scale},
        {"z_snap_mm", s.z_snap_mm},
        {"params",
         {{"pitch_mm", p.pitch_mm},
          {"fit_width_mm", p.fit_width_mm},
          {"fit_depth_mm", p.fit_depth_mm},
          {"max_height_mm", p.max_height_mm},
          {"base_mm", p.base_mm},
          {"transfer", toString(p.transfer)},
          {"baseline_mode", toString(p.baseline_mode)},
          {"baseline_value", p.baseline_value},
          {"value_max", p.value_max ? json(*p.value_max) : json(nullptr)},
          {"z_snap_mm", p.z_snap_mm},
          {"cull", toString(p.cull)},
          {"bottom", toString(p.bottom)},
          {"true_aspect", p.true_aspect}}},
        {"mapping",
         {{"transfer", toString(s.mapping.transfer)},
          {"baseline", s.mapping.baseline},
          {"value_max", s.mapping.value_max},
          {"max_height_mm", s.mapping.max_height_mm}}},
        {"floor_units", s.floor_units},
        {"mirror_thickness_units", s.mirror_thickness_units},
        {"cells_with_data", s.cells_with_data},
        {"cells_nonempty", s.cells_nonempty},
        {"cells_nodata_kept", s.cells_nodata_kept},
        {"nodata_pit_units", s.nodata_pit_units},
        {"one_to_one", s.one_to_one},
        {"marks", marksJson(s.marks)},
        {"faces", facesJson(s)},
        {"shapes", shapesJson(s)},
        {"hull", hull},
        {"notes", s.notes},
    };
    // The features' own records (gen/model/feature_records.h), null when
    // the Scene has none.
    for (const FeatureRecord& r : featureRecords()) {
        json record = r.write(s);
        if (record.is_null() && !r.listed_when_absent) continue;
        json* at = &head;
        for (const std::string& key : recordPath(r)) at = &(*at)[key];
        *at = std::move(record);
    }
    return head;
}
}  // namespace

json sceneToJson(const Scene& s) {
    json j = sceneHeadJson(s);
    json cells = json::array();
    for (size_t k = 0; k < s.keptCount(); ++k) cells.push_back(cellJson(s, k));
    j["cells"] = std::move(cells);
    return j;
}

namespace {
std::array<int32_t, 6> getCorners(const json& obj, const std::string& path, const char* key) {
    const json& a = getArray(obj, path, key);
    const std::string p = path + "." + key;
    if (a.size() != 6) fail(p, "expected 6 corner offsets");
    std::array<int32_t, 6> out{};
    for (size_t e = 0; e < 6; ++e) {
        const int64_t v = toInt(a[e], p + "[" + std::to_string(e) + "]");
        if (v < -(int64_t(1) << 30) || v > (int64_t(1) << 30)) fail(p, "corner offset out of range");
        out[e] = int32_t(v);
    }
    return out;
}

std::vector<PlanarPoint> pointsFrom(const json& obj, const std::string& path, const char* key) {
    const json& a = getArray(obj, path, key);
    const std::string p = join(path, key);
    std::vector<PlanarPoint> out;
    out.reserve(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        const std::string q = p + "[" + std::to_string(i) + "]";
        if (!a[i].is_array() || a[i].size() != 2) fail(q, "expected [i, j]");
        const PlanarPoint pt{toNumber(a[i][0], q + "[0]"), toNumber(a[i][1], q + "[1]")};
        if (!std::isfinite(pt.i) || !std::isfinite(pt.j)) fail(q, "expected finite numbers");
        out.push_back(pt);
    }
    return out;
}

// A list of integers each in [lo, hi).
std::vector<int64_t> idsFrom(const json& a, const std::string& path, int64_t lo, int64_t hi, const char* what) {
    if (!a.is_array()) fail(path, std::string("expected an array, found ") + typeName(a));
    std::vector<int64_t> out;
    out.reserve(a.size());
    for (size_t i = 0; i < a.size(); ++i) {
        const std::string q = path + "[" + std::to_string(i) + "]";
        const int64_t v = toInt(a[i], q);
        if (v < lo || v >= hi) fail(q, std::string("is not ") + what);
        out.push_back(v);
    }
    return out;
}

// The marks' planar faces as recorded (version 5); every id, cell and
// neighbour is checked, so a drawn face never reaches outside the Scene.
void readFaces(const json& j, Scene& s) {
    s.faces = {};
    s.drawn_by_face.assign(s.keptCount(), 0);
    if (j.is_null()) return;
    const std::string fp = "faces";
    if (!j.is_object()) fail(fp, std::string("expected an object or null, found ") + typeName(j));
    s.faces.extra = pointsFrom(j, fp, "extra");
    const int64_t ids = latticeVertexIdCount(s.grid) + int64_t(s.faces.extra.size());
    const int64_t n = int64_t(s.keptCount());
    const json& faces = getArray(j, fp, "faces");
    for (size_t i = 0; i < faces.size(); ++i) {
        const std::string p = fp + ".faces[" + std::to_string(i) + "]";
        const json& f = faces[i];
        PlanarFace face;
        face.anchor = getInt32(f, p, "anchor", 0, std::max<int64_t>(0, n - 1));
        if (n == 0) fail(join(p, "anchor"), "is not the index of a cell");
        face.raise_units = getInt(f, p, "raise_units");
        if (face.raise_units < 0 || face.raise_units > (int64_t(1) << 40)) fail(join(p, "raise_units"), "out of range");
        for (const int64_t k : idsFrom(member(f, p, "cells"), join(p, "cells"), 0, n, "the index of a cell"))
            face.cells.push_back(int32_t(k));
        const json& rings = getArray(f, p, "rings");
        const json& across = getArray(f, p, "across");
        if (rings.empty()) fail(join(p, "rings"), "a face has at least one ring");
        if (across.size() != rings.size()) fail(join(p, "across"), "expected one list per ring");
        for (size_t r = 0; r < rings.size(); ++r) {
            const std::string rp = join(p, "rings") + "[" + std::to_string(r) + "]";
            face.rings.push_back(idsFrom(rings[r], rp, 0, ids, "a planar vertex id"));
            if (face.rings.back().size() < 3) fail(rp, "a ring has at least 3 vertices");
            const std::string ap = join(p, "across") + "[" + std::to_string(r) + "]";
            if (!across[r].is_array() || across[r].size() != face.rings.back().size())
                fail(ap, "expected one entry per edge of the ring");
            std::vector<Across> ring_across;
            for (size_t e = 0; e < across[r].size(); ++e) {
                const std::string ep = ap + "[" + std::to_string(e) + "]";
                const json& a = across[r][e];
                if (!a.is_array() || a.size() != 2) fail(ep, "expected [kind, index]");
                const int64_t kind = toInt(a[0], ep + "[0]"), index = toInt(a[1], ep + "[1]");
                Across x;
                if (kind == int(Across::Kind::Outside) && index == -1) x.kind = Across::Kind::Outside;
                else if (kind == int(Across::Kind::Face) && index >= 0 && index < int64_t(faces.size())) x.kind = Across::Kind::Face;
                else if (kind == int(Across::Kind::Cell) && index >= 0 && index < n) x.kind = Across::Kind::Cell;
                else fail(ep, "expected [0, -1] (outside), [1, face] or [2, cell]");
                x.index = int32_t(index);
                ring_across.push_back(x);
            }
            face.across.push_back(std::move(ring_across));
        }
        const json& tris = getArray(f, p, "triangles");
        for (size_t t = 0; t < tris.size(); ++t) {
            const std::string tp = join(p, "triangles") + "[" + std::to_string(t) + "]";
            const std::vector<int64_t> v = idsFrom(tris[t], tp, 0, ids, "a planar vertex id");
            if (v.size() != 3) fail(tp, "expected three vertex ids");
            face.triangles.push_back({v[0], v[1], v[2]});
        }
        if (face.triangles.empty()) fail(join(p, "triangles"), "a face has at least one triangle");
        const json& rp = member(f, p, "read_point");
        if (!rp.is_null()) face.read_point = pointFrom(f, p, "read_point");
        for (const int32_t k : face.cells) s.drawn_by_face[size_t(k)] = 1;
        s.faces.faces.push_back(std::move(face));
    }
}

// A shaped cell's fan (version 5), as fanJson wrote it.
void readFan(const json& f, const std::string& p, size_t k, int64_t first, int64_t last, bool mirrored, TopShapes& t) {
    auto id = [&](const char* key) {
        const int64_t v = getInt(f, p, key);
        if (v < first || v >= last) fail(join(p, key), "is not the id of a fan centre");
        return v;
    };
    auto crossings = [&](const char* key, std::vector<int64_t>& into) {
        const std::vector<int64_t> v = idsFrom(member(f, p, key), join(p, key), -1, last, "a crossing id or -1");
        if (v.size() != size_t(kHexCorners)) fail(join(p, key), "expected 6 crossing ids");
        for (size_t e = 0; e < v.size(); ++e) {
            if (v[e] != -1 && v[e] < first) fail(join(p, key), "is not a crossing id");
            into[size_t(kHexCorners) * k + e] = v[e];
        }
    };
    t.shaped[k] = 1;
    t.centre_top_id[k] = id("centre_top");
    crossings("crossings_top", t.crossing_top);
    if (mirrored) {
        t.centre_bottom_id[k] = id("centre_bottom");
        crossings("crossings_bottom", t.crossing_bottom);
    }
}

// Shaped tops (version 3): per-cell offsets, then the geometry made from them
// (version 5: the geometry as recorded).
void readShapes(const json& j, const json& cells, Scene& s, int64_t version) {
    const auto it = j.find("shapes");
    if (it == j.end() || it->is_null()) return;
    const json& h = *it;
    if (!h.is_object()) fail("shapes", "expected an object or null");
    const std::string tilt = getString(h, "shapes", "tilt");
    s.params.tilt = tilt == "points" ? TiltSource::Points : tilt == "gradient" ? TiltSource::Gradient : TiltSource::None;
    s.params.steepness = toNumber(member(h, "shapes", "steepness"), "shapes.steepness");
    TopShapes& t = s.shapes;
    const size_t n = s.keptCount();
    const bool mirrored = s.params.bottom == Bottom::Mirrored;
    t = levelTopShapes(n, mirrored);
    t.cells_tilted = getInt(h, "shapes", "cells_tilted");
    t.cells_clamped = getInt(h, "shapes", "cells_clamped");
    t.cells_flat_clamped = getInt(h, "shapes", "cells_clamped_level");
    t.cells_textured = getInt(h, "shapes", "cells_textured");
    t.dimple_units = getInt(h, "shapes", "dimple_units");
    for (size_t k = 0; k < n; ++k) {
        const auto sh = cells[k].find("shape");
        if (sh == cells[k].end()) continue;
        const std::string cp = "cells[" + std::to_string(k) + "].shape";
        t.top_dz[k] = getCorners(*sh, cp, "top_dz");
        t.top_centre_dz[k] = int32_t(getInt32(*sh, cp, "centre_dz", -(int64_t(1) << 30), int64_t(1) << 30));
        if (mirrored) {
            t.bottom_dz[k] = getCorners(*sh, cp, "bottom_dz");
            t.bottom_centre_dz[k] = int32_t(getInt32(*sh, cp, "bottom_centre_dz", -(int64_t(1) << 30), int64_t(1) << 30));
        }
        const json& slope = getArray(*sh, cp, "slope");
        if (slope.size() != 2) fail(cp + ".slope", "expected [x, y]");
        t.slope_x[k] = toNumber(slope[0], cp + ".slope[0]");
        t.slope_y[k] = toNumber(slope[1], cp + ".slope[1]");
        const json& st = member(*sh, cp, "structural");
        if (!st.is_boolean()) fail(cp + ".structural", "expected true or false");
        t.structural[k] = st.get<bool>();
    }
    if (version < 5) {
        buildTopShapeGeometry(s);  // older sidecars: made again from the offsets
        return;
    }
    t.first_id = getInt(h, "shapes", "first_id");
    if (t.first_id != latticeVertexIdCount(s.grid) + int64_t(s.faces.extra.size()))
        fail("shapes.first_id", "must follow the lattice's and the faces' ids");
    t.extra = pointsFrom(h, "shapes", "extra");
    const std::vector<int64_t> z = idsFrom(member(h, "shapes", "extra_z"), "shapes.extra_z", -(int64_t(1) << 50),
                                           int64_t(1) << 50, "a height in z units");
    if (z.size() != t.extra.size()) fail("shapes.extra_z", "expected one height per extra point");
    t.extra_z = z;
    const int64_t last = t.first_id + int64_t(t.extra.size());
    t.shaped.assign(n, 0);
    t.centre_top_id.assign(n, -1);
    t.centre_bottom_id.assign(n, -1);
    t.crossing_top.assign(size_t(kHexCorners) * n, -1);
    t.crossing_bottom.assign(size_t(kHexCorners) * n, -1);
    for (size_t k = 0; k < n; ++k) {
        const auto f = cells[k].find("fan");
        if (f != cells[k].end()) readFan(*f, "cells[" + std::to_string(k) + "].fan", k, t.first_id, last, mirrored, t);
    }
}
}  // namespace

Scene sceneFromJson(const json& j) {
    if (!j.is_object()) fail("", std::string("expected an object, found ") + typeName(j));
    const std::string format = getString(j, "", "format");
    if (format != kSceneJsonFormat) fail("format", "expected \"" + std::string(kSceneJsonFormat) + "\", found \"" + format + "\"");
    const int64_t version = getInt(j, "", "version");
    if (version < 1 || version > kSceneJsonVersion)
        fail("version", "unsupported version " + std::to_string(version) + " (this tsf reads version " +
                            std::to_string(kSceneJsonVersion) + ")");

    Scene s;
    const json& grid = member(j, "", "grid");
    s.grid.cols = getInt32(grid, "grid", "cols", 0, std::numeric_limits<int32_t>::max());
    s.grid.rows = getInt32(grid, "grid", "rows", 0, std::numeric_limits<int32_t>::max());
    if (s.grid.cellCount() > kMaxSceneJsonCells)
        fail("grid", "a grid of " + std::to_string(s.grid.cellCount()) + " cells is larger than the " +
                         std::to_string(kMaxSceneJsonCells) + " a sidecar may describe");
    s.pitch_mm = getPositive(j, "", "pitch_mm");
    // buildScene's smallest cell (scene_check.cpp): a smaller one is no model of ours.
    if (!(s.pitch_mm >= 50 * kXYSnapMm)) fail("pitch_mm", "expected at least " + std::to_string(50 * kXYSnapMm) + " mm");
    if (version >= 8) {
        s.y_scale = getPositive(j, "", "y_scale");
        if (s.y_scale < 0.25 || s.y_scale > 4.0) fail("y_scale", "expected a stretch between 0.25 and 4");
    }
    s.z_snap_mm = getPositive(j, "", "z_snap_mm");

    const json& params = member(j, "", "params");
    SceneParams& p = s.params;
    p.pitch_mm = getNumber(params, "params", "pitch_mm");
    p.fit_width_mm = getNumber(params, "params", "fit_width_mm");
    p.fit_depth_mm = getNumber(params, "params", "fit_depth_mm");
    p.max_height_mm = getNumber(params, "params", "max_height_mm");
    p.base_mm = getNumber(params, "params", "base_mm");
    p.transfer = getEnum(params, "params", "transfer", kTransfers);
    p.baseline_mode = getEnum(params, "params", "baseline_mode", kBaselines);
    p.baseline_value = getNumber(params, "params", "baseline_value");
    const json& vmax = member(params, "params", "value_max");
    if (!vmax.is_null()) p.value_max = toNumber(vmax, "params.value_max");
    p.z_snap_mm = getPositive(params, "params", "z_snap_mm");
    p.cull = getEnum(params, "params", "cull", kCulls);
    p.bottom = getEnum(params, "params", "bottom", kBottoms);
    if (version >= 8) {
        const json& aspect = member(params, "params", "true_aspect");
        if (!aspect.is_boolean()) fail("params.true_aspect", std::string("expected true or false, found ") + typeName(aspect));
        p.true_aspect = aspect.get<bool>();
    }

    const json& mapping = member(j, "", "mapping");
    s.mapping.transfer = getEnum(mapping, "mapping", "transfer", kTransfers);
    s.mapping.baseline = getNumber(mapping, "mapping", "baseline");
    s.mapping.value_max = getNumber(mapping, "mapping", "value_max");
    s.mapping.max_height_mm = getNumber(mapping, "mapping", "max_height_mm");

    s.floor_units = getInt(j, "", "floor_units");
    s.mirror_thickness_units = getInt(j, "", "mirror_thickness_units");
    s.cells_with_data = getInt(j, "", "cells_with_data");
    s.cells_nonempty = getInt(j, "", "cells_nonempty");
    s.cells_nodata_kept = getInt(j, "", "cells_nodata_kept");
    if (version >= 2) {
        s.nodata_pit_units = getInt(j, "", "nodata_pit_units");
        const json& one = member(j, "", "one_to_one");
        if (!one.is_boolean()) fail("one_to_one", std::string("expected true or false, found ") + typeName(one));
        s.one_to_one = one.get<bool>();
        s.marks = marksFrom(member(j, "", "marks"), "marks", s.grid);
    }

    const json& hull = getArray(j, "", "hull");
    for (size_t i = 0; i < hull.size(); ++i) {
        const std::string hp = "hull[" + std::to_string(i) + "]";
        if (!hull[i].is_array() || hull[i].size() != 2) fail(hp, "expected [i, j]");
        s.hull.push_back({toInt(hull[i][0], hp + "[0]"), toInt(hull[i][1], hp + "[1]")});
    }
    const json& notes = getArray(j, "", "notes");
    for (size_t i = 0; i < notes.size(); ++i) {
        if (!notes[i].is_string()) fail("notes[" + std::to_string(i) + "]", "expected a string");
        s.notes.push_back(notes[i].get<std::string>());
    }

    const json& cells = getArray(j, "", "cells");
    if (int64_t(cells.size()) > s.grid.cellCount())
        fail("cells", std::to_string(cells.size()) + " cells do not fit a grid of " +
                          std::to_string(s.grid.cellCount()));
    s.kept_index.assign(size_t(s.grid.cellCount()), -1);
    s.col.reserve(cells.size());
    s.row.reserve(cells.size());
    s.value.reserve(cells.size());
    s.top.reserve(cells.size());
    s.bottom.reserve(cells.size());
    int64_t previous = -1;
    for (size_t k = 0; k < cells.size(); ++k) {
        const std::string cp = "cells[" + std::to_string(k) + "]";
        const json& c = cells[k];
        const int32_t col = getInt32(c, cp, "col", 0, int64_t(s.grid.cols) - 1);
        const int32_t row = getInt32(c, cp, "row", 0, int64_t(s.grid.rows) - 1);
        const int64_t index = s.grid.index(col, row);
        if (index <= previous) fail(cp, "cells must be listed once each, ordered by row then column");
        previous = index;
        const json& v = member(c, cp, "value");
        const double value = v.is_null() ? std::numeric_limits<double>::quiet_NaN() : toNumber(v, cp + ".value");
        const int64_t top = getInt(c, cp, "top");
        const int64_t bottom = getInt(c, cp, "bottom");
        if (!(bottom < top)) fail(cp + ".top", "must be above bottom (" + std::to_string(top) + " <= " + std::to_string(bottom) + ")");
        s.kept_index[size_t(index)] = int32_t(k);
        s.col.push_back(col);
        s.row.push_back(row);
        s.value.push_back(value);
        s.top.push_back(top);
        s.bottom.push_back(bottom);
        s.kind.push_back(std::isnan(value) ? CellKind::NoData : CellKind::Data);
    }
    if (s.marks.triangle && size_t(s.marks.triangle->anchor) >= s.keptCount())
        fail("marks.triangle.anchor", "is not the index of a cell");
    if (version >= 5) readFaces(j.contains("faces") ? j["faces"] : json(nullptr), s);
    else buildMarkFaces(s);  // older sidecars: the faces are built again from the marks
    readShapes(j, cells, s, version);
    // The features' own records (gen/model/feature_records.h), as placed.
    for (const FeatureRecord& r : featureRecords()) {
        const json* at = &j;
        for (const std::string& key : recordPath(r))
            at = at->is_object() && at->contains(key) ? &(*at)[key] : nullptr;
        if (at && !at->is_null()) r.read(*at, r.path, int(version), s);
    }
    return s;
}

namespace {

// The cells' text (see sceneCellsJson) into `block`, handed to flush(block)
// whenever it passes 1 MiB and at the end (flush clears what it takes).
template <class Flush>
void formatCells(const Scene& scene, std::string& block, const Flush& flush) {
    const size_t n = scene.keptCount();
    for (size_t k = 0; k < n; ++k) {
        block += k ? ",\n    " : "\n    ";
        if (plainCell(scene, k)) appendPlainCell(block, scene, k);
        else block += cellJson(scene, k).dump();
        if (block.size() > (size_t(1) << 20)) flush(block);
    }
    block += n == 0 ? "]\n}\n" : "\n  ]\n}\n";
    flush(block);
}

}  // namespace

std::string sceneCellsJson(const Scene& scene) {
    std::string text;
    formatCells(scene, text, [](std::string&) {});
    return text;
}

void writeSceneJson(const Scene& scene, const std::string& path, const SceneModelRecord* model, const std::string* cells) {
    // Everything but the cells indented; then one cell per line, so a person
    // can find a cell with a text editor and the file stays compact. Cells are
    // streamed a block at a time: a million-cell scene never exists as a JSON tree.
    json head_json = sceneHeadJson(scene);
    if (model)
        head_json["model"] = {{"file", model->file},
                              {"bytes", model->stamp.bytes},
                              {stampHashName(model->stamp.algorithm), toHex(model->stamp.hash)}};
    std::string head = head_json.dump(2);
    head.pop_back();  // the closing brace
    while (!head.empty() && (head.back() == '\n' || head.back() == ' ')) head.pop_back();
    writeFileAtomically(path, [&](std::ostream& out) {
        out << head << ",\n  \"cells\": [";
        if (cells) {
            out << *cells;
            return;
        }
        std::string block;
        formatCells(scene, block, [&out](std::string& b) {
            out << b;
            b.clear();
        });
    });
}

namespace {

std::optional<SceneModelRecord> modelRecordFromJson(const json& j) {
    if (!j.is_object() || !j.contains("model")) return std::nullopt;
    const json& m = j["model"];
    if (!m.is_object()) fail("model", std::string("expected an object, found ") + typeName(m));
    SceneModelRecord r;
    r.file = getString(m, "model", "file");
    r.stamp.bytes = getInt(m, "model", "bytes");
    if (r.file.empty() || r.file.find('/') != std::string::npos) fail("model.file", "expected a file name without folder");
    if (r.stamp.bytes < 0) fail("model.bytes", "must not be negative");
    // XXH3 since tsf wrote it; FNV-1a in sidecars written before.
    r.stamp.algorithm = m.contains("xxh3_64") || !m.contains("fnv1a64") ? StampHash::Xxh3_64 : StampHash::Fnv1a64;
    const char* key = stampHashName(r.stamp.algorithm);
    if (!parseHex64(getString(m, "model", key), r.stamp.hash))
        fail(std::string("model.") + key, "expected 16 lower-case hex digits");
    return r;
}

}  // namespace

void checkSceneModelRecord(const SceneModelRecord& record, const std::string& sidecar_path,
                           const std::string& model_path) {
    if (std::filesystem::path(model_path).filename().string() != record.file) return;
    const FileStamp now = stampFile(model_path, record.stamp.algorithm);
    if (now == record.stamp) return;
    throw InputError(sidecar_path, 0, 0,
                     "was written with another version of " + record.file + " (" + std::to_string(record.stamp.bytes) +
                         " bytes, hash " + toHex(record.stamp.hash) + "; " + model_path + " has " +
                         std::to_string(now.bytes) + " bytes, hash " + toHex(now.hash) +
                         "): the model and its sidecar come from different runs of tsf gen (one may have been "
                         "interrupted); run tsf gen again");
}

Scene parseSceneJson(const std::string& text, const std::string& path, std::optional<SceneModelRecord>* model) {
    json j;
    try {
        j = json::parse(text);
    } catch (const json::parse_error& e) {
        int line = 0, column = 0;
        lineColumn(text, e.byte > 0 ? e.byte - 1 : 0, line, column);
        throw InputError(path, line, column, "not valid JSON: " + withoutPrefix(e.what()));
    } catch (const json::exception& e) {
        // e.g. a number too large for a double: no position is known.
        throw InputError(path, 0, 0, "not valid JSON: " + withoutPrefix(e.what()));
    }
    try {
        Scene s = sceneFromJson(j);
        if (model) *model = modelRecordFromJson(j);
        return s;
    } catch (const InputError& e) {
        throw InputError(path, 0, 0, e.detail());
    }
}

Scene readSceneJson(const std::string& path, std::optional<SceneModelRecord>* model) {
    return parseSceneJson(readFileBytes(path, kMaxSceneJsonBytes), path, model);
}

}  // namespace tsf
