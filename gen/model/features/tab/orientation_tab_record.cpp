// The orientation tab's record in the scene sidecar. See
// orientation_tab_record.h.
#include "gen/model/features/tab/orientation_tab_record.h"

#include <cmath>
#include <sstream>

#include "gen/model/features/tab/orientation_tab.h"
#include "gen/model/sidecar_fields.h"
#include "gen/util/number_format.h"

namespace tsf {

using namespace sidecar;

namespace {

// The orientation tab as placed (version 6), read as recorded; checked
// against the cells once they are read (checkTab).
OrientationTab tabFrom(const json& t, const std::string& path) {
    OrientationTab tab;
    auto xy = [&](const json& v, const std::string& p, size_t n) {
        if (!v.is_array() || v.size() != n) fail(p, "expected [x, y" + std::string(n == 3 ? ", lattice id]" : "]"));
        OutlinePoint q{toNumber(v[0], p + "[0]"), toNumber(v[1], p + "[1]"), -1};
        if (!std::isfinite(q.x_mm) || !std::isfinite(q.y_mm)) fail(p, "expected finite numbers");
        if (n == 3) {
            if (!v[2].is_number_integer()) fail(p + "[2]", "expected a lattice id (an integer, -1 for none)");
            q.lattice = v[2].get<int64_t>();
        }
        return q;
    };
    const json& outline = member(t, path, "outline");
    if (!outline.is_array() || outline.size() < 4) fail(join(path, "outline"), "expected at least four corners");
    for (size_t n = 0; n < outline.size(); ++n)
        tab.outline.push_back(xy(outline[n], join(path, "outline") + "[" + std::to_string(n) + "]", 3));
    const json& joined = member(t, path, "joined");
    if (!joined.is_array() || joined.size() != outline.size()) fail(join(path, "joined"), "expected one flag per corner");
    for (const json& f : joined) {
        if (!f.is_number_integer() || (f.get<int64_t>() != 0 && f.get<int64_t>() != 1)) fail(join(path, "joined"), "expected 0 or 1");
        tab.joined.push_back(uint8_t(f.get<int64_t>()));
    }
    const json& touched = member(t, path, "touched");
    if (!touched.is_array()) fail(join(path, "touched"), "expected [[kept index, edge], ...]");
    for (const json& e : touched) {
        if (!e.is_array() || e.size() != 2 || !e[0].is_number_integer() || !e[1].is_number_integer())
            fail(join(path, "touched"), "expected [[kept index, edge], ...]");
        const int64_t k = e[0].get<int64_t>(), edge = e[1].get<int64_t>();
        if (k < 0 || k > std::numeric_limits<int32_t>::max() || edge < 0 || edge >= kHexCorners)
            fail(join(path, "touched"), "a kept index or an edge (0..5) is out of range");
        tab.touched.push_back({int32_t(k), int(edge)});
    }
    tab.bottom_units = getInt(t, path, "bottom_units");
    tab.top_units = getInt(t, path, "top_units");
    const json& box = member(t, path, "box_mm");
    if (!box.is_array() || box.size() != 4) fail(join(path, "box_mm"), "expected [west, east, south, north]");
    tab.x_west_mm = toNumber(box[0], join(path, "box_mm[0]"));
    tab.x_east_mm = toNumber(box[1], join(path, "box_mm[1]"));
    tab.y_south_mm = toNumber(box[2], join(path, "box_mm[2]"));
    tab.y_north_mm = toNumber(box[3], join(path, "box_mm[3]"));
    const json& notch = member(t, path, "notch");
    if (!notch.is_null()) {
        const std::string np = join(path, "notch");
        tab.has_notch = true;
        tab.notch_depth_mm = getNumber(notch, np, "depth_mm");
        tab.notch_width_mm = getNumber(notch, np, "width_mm");
        tab.notch_opening_deg = getNumber(notch, np, "opening_deg");
    }
    const json& tri = member(t, path, "triangle");
    if (!tri.is_null()) {
        const std::string tp = join(path, "triangle");
        const json& corners = member(tri, tp, "corners_mm");
        if (!corners.is_array() || corners.size() != 3) fail(join(tp, "corners_mm"), "expected three [x, y] corners");
        for (size_t n = 0; n < 3; ++n) tab.triangle[n] = xy(corners[n], join(tp, "corners_mm") + "[" + std::to_string(n) + "]", 2);
        tab.triangle_raise_units = getInt(tri, tp, "raise_units");
        if (tab.triangle_raise_units < 1) fail(join(tp, "raise_units"), "must be at least 1");
        const json& under = member(tri, tp, "underside");
        if (!under.is_boolean()) fail(join(tp, "underside"), "expected true or false");
        tab.under_triangle = under.get<bool>();
        tab.has_triangle = true;
    }
    return tab;
}


}  // namespace

json tabRecord(const Scene& s) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return nullptr;
    const OrientationTab& t = *tab;
    json outline = json::array(), touched = json::array(), tri = json::array();
    for (const OutlinePoint& p : t.outline) outline.push_back(json::array({p.x_mm, p.y_mm, p.lattice}));
    for (const auto& [k, e] : t.touched) touched.push_back(json::array({k, e}));
    for (const OutlinePoint& p : t.triangle) tri.push_back(json::array({p.x_mm, p.y_mm}));
    return {{"outline", outline},
                {"joined", t.joined},
                {"touched", touched},
                {"bottom_units", t.bottom_units},
                {"top_units", t.top_units},
                {"box_mm", {t.x_west_mm, t.x_east_mm, t.y_south_mm, t.y_north_mm}},
                {"notch", t.has_notch ? json{{"depth_mm", t.notch_depth_mm}, {"width_mm", t.notch_width_mm},
                                             {"opening_deg", t.notch_opening_deg}}
                                      : json(nullptr)},
                {"triangle", t.has_triangle ? json{{"corners_mm", tri}, {"raise_units", t.triangle_raise_units},
                                                   {"underside", t.under_triangle}}
                                            : json(nullptr)}};

}

void readTabRecord(const json& record, const std::string& path, int /*version*/, Scene& s) {
    const OrientationTab& tab = s.features.set(tabFrom(record, path));
    try {
        checkTab(s, tab);
    } catch (const InputError& e) {
        fail(path, e.what());
    }
}

nlohmann::json tabFactsJson(const Scene& s) {
    const OrientationTab* placed = sceneTab(s);
    if (!placed) return nullptr;
    const OrientationTab& t = *placed;
    const double w = t.x_east_mm - t.x_west_mm, d = t.y_north_mm - t.y_south_mm;
    nlohmann::json tab = {{"box_mm", {{"west", t.x_west_mm}, {"east", t.x_east_mm}, {"south", t.y_south_mm}, {"north", t.y_north_mm}}},
                          {"size_mm", {w, d, s.zMm(t.top_units - t.bottom_units)}},
                          {"z_mm", {s.zMm(t.bottom_units), s.zMm(t.top_units)}},
                          {"area_mm2", tabAreaMm2(t)},
                          {"cells_touched", t.touched.size()}};
    tab["notch"] = t.has_notch ? nlohmann::json{{"depth_mm", t.notch_depth_mm}, {"width_mm", t.notch_width_mm},
                                                {"opening_deg", t.notch_opening_deg},
                                                {"corner_mm", {t.x_west_mm, t.y_south_mm}}}
                               : nlohmann::json(nullptr);
    tab["triangle"] = t.has_triangle ? nlohmann::json{{"leg_x_mm", t.triangle[1].x_mm - t.triangle[0].x_mm},
                                                      {"leg_y_mm", t.triangle[2].y_mm - t.triangle[0].y_mm},
                                                      {"height_mm", s.zMm(t.triangle_raise_units)},
                                                      {"underside", t.under_triangle},
                                                      {"corner_mm", {t.triangle[0].x_mm, t.triangle[0].y_mm}}}
                                     : nlohmann::json(nullptr);
    return tab;
}

std::string tabFactsLines(const Scene& s) {
    const OrientationTab* tab = sceneTab(s);
    if (!tab) return "";
    std::ostringstream o;
    const OrientationTab& t = *tab;
    o << "  tab       " << formatFixed(t.x_east_mm - t.x_west_mm, 1) << " x " << formatFixed(t.y_north_mm - t.y_south_mm, 1)
      << " x " << formatFixed(s.zMm(t.top_units - t.bottom_units), 2) << " mm (" << formatFixed(tabAreaMm2(t), 0)
      << " mm^2) west of the pillars, "
      << (t.bottom_units == 0 ? std::string("from the bed to the floor")
                              : "from z = " + formatFixed(s.zMm(t.bottom_units), 2) + " to " + formatFixed(s.zMm(t.top_units), 2) + " mm")
      << ", corner (" << formatFixed(t.x_west_mm, 1) << ", " << formatFixed(t.y_south_mm, 1)
      << ") mm: it carries the marks and covers no data cell\n";
    if (t.has_notch)
        o << "  notch     V " << formatFixed(t.notch_depth_mm, 1) << " mm deep, " << formatFixed(t.notch_width_mm, 1)
          << " mm wide, " << formatFixed(t.notch_opening_deg, 0) << " degrees, at the model's south-west corner\n";
    if (t.has_triangle)
        o << "  triangle  raised " << formatFixed(s.zMm(t.triangle_raise_units), 2) << " mm on the tab, legs "
          << formatFixed(t.triangle[1].x_mm - t.triangle[0].x_mm, 1) << " mm east (x) and "
          << formatFixed(t.triangle[2].y_mm - t.triangle[0].y_mm, 1) << " mm north (y), right angle at ("
          << formatFixed(t.triangle[0].x_mm, 1) << ", " << formatFixed(t.triangle[0].y_mm, 1)
          << ") mm: turn the model so the notch is at your near left, and the longer leg runs to your right"
          << (t.under_triangle ? "; the same triangle on the tab's underside has its longer leg to your left when the "
                                 "model is turned over, as the data is mirrored there"
                               : "")
          << "\n";
    return o.str();
}

}  // namespace tsf
