// The tactile scale's record in the scene sidecar. See scale_record.h.
#include "gen/model/features/scale_record.h"

#include <sstream>
#include <tuple>

#include "gen/model/features/scale.h"
#include "gen/model/sidecar_fields.h"
#include "gen/util/number_format.h"

namespace tsf {

using namespace sidecar;

namespace {

// The tactile scale as placed (written since version 4), read as recorded.
SceneScale scaleFrom(const json& j, const std::string& sp, const Scene& s) {
    if (!j.is_object()) fail(sp, std::string("expected an object, found ") + typeName(j));
    SceneScale sc;
    sc.step = getPositive(j, sp, "step");
    const json& given = member(j, sp, "step_given");
    if (!given.is_boolean()) fail(join(sp, "step_given"), "expected true or false");
    sc.step_given = given.get<bool>();
    sc.x0_i = getInt(j, sp, "x0_i");
    sc.y0_j = getInt(j, sp, "y0_j");
    sc.y1_j = getInt(j, sp, "y1_j");
    const json& x = getArray(j, sp, "x_mm");
    if (x.size() != 3) fail(join(sp, "x_mm"), "expected [west, steps' west, east]");
    sc.x0_mm = toNumber(x[0], sp + ".x_mm[0]");
    sc.xs_mm = toNumber(x[1], sp + ".x_mm[1]");
    sc.x1_mm = toNumber(x[2], sp + ".x_mm[2]");
    if (!(sc.x0_mm < sc.xs_mm && sc.xs_mm < sc.x1_mm)) fail(join(sp, "x_mm"), "expected three increasing x");
    std::tie(sc.y0_mm, sc.y1_mm) = getFinitePair(j, sp, "y_mm");
    if (!(sc.y0_mm < sc.y1_mm)) fail(join(sp, "y_mm"), "expected south < north");
    sc.foot_top_units = getInt(j, sp, "foot_top_units");
    const json& steps = getArray(j, sp, "steps");
    for (size_t i = 0; i < steps.size(); ++i) {
        const std::string p = sp + ".steps[" + std::to_string(i) + "]";
        if (!steps[i].is_array() || steps[i].size() != 4) fail(p, "expected [value, top_units, y_south_mm, y_north_mm]");
        ScaleStep st;
        st.value = toNumber(steps[i][0], p + "[0]");
        st.top_units = toInt(steps[i][1], p + "[1]");
        st.y_south_mm = toNumber(steps[i][2], p + "[2]");
        st.y_north_mm = toNumber(steps[i][3], p + "[3]");
        if (!(st.y_south_mm < st.y_north_mm) || st.y_south_mm < sc.y0_mm || st.y_north_mm > sc.y1_mm)
            fail(p, "the step does not lie on the scale");
        sc.steps.push_back(st);
    }
    if (sc.steps.empty()) fail(join(sp, "steps"), "a scale has at least one step");
    auto keptList = [&](const char* key, bool none_allowed) {
        std::vector<int32_t> out;
        const json& a = getArray(j, sp, key);
        for (size_t i = 0; i < a.size(); ++i) {
            const std::string p = sp + "." + key + "[" + std::to_string(i) + "]";
            const int64_t k = toInt(a[i], p);
            if (none_allowed && k == -1) {
                out.push_back(-1);
                continue;
            }
            if (k < 0 || size_t(k) >= s.keptCount()) fail(p, "is not the index of a cell");
            out.push_back(int32_t(k));
        }
        return out;
    };
    sc.contacts = keptList("contacts", false);
    sc.fillers = keptList("fillers", true);  // -1: contacts further apart than a notch
    return sc;
}


}  // namespace

json scaleRecord(const Scene& s) {
    if (!sceneScale(s)) return nullptr;
    const SceneScale& sc = *sceneScale(s);
    json steps = json::array();
    for (const ScaleStep& st : sc.steps) steps.push_back({st.value, st.top_units, st.y_south_mm, st.y_north_mm});
    return {{"step", sc.step},         {"step_given", sc.step_given}, {"x0_i", sc.x0_i},
            {"y0_j", sc.y0_j},         {"y1_j", sc.y1_j},             {"x_mm", {sc.x0_mm, sc.xs_mm, sc.x1_mm}},
            {"y_mm", {sc.y0_mm, sc.y1_mm}}, {"foot_top_units", sc.foot_top_units},
            {"steps", steps},          {"contacts", sc.contacts}, {"fillers", sc.fillers}};
}


void readScaleRecord(const json& record, const std::string& path, int /*version*/, Scene& s) {
    const SceneScale& sc = s.features.set(scaleFrom(record, path, s));
    s.params.requests.set(ScaleRequest{sc.step_given ? std::optional<double>(sc.step) : std::nullopt});
}

nlohmann::json scaleFactsJson(const Scene& s) {
    if (!sceneScale(s)) return nullptr;
    const SceneScale& sc = *sceneScale(s);
    nlohmann::json steps = nlohmann::json::array();
    for (const ScaleStep& st : sc.steps)
        steps.push_back({{"value", st.value}, {"top_mm", s.zMm(st.top_units)},
                         {"height_above_floor_mm", s.zMm(st.top_units - sc.foot_top_units)}});
    return {{"step", sc.step}, {"step_given", sc.step_given}, {"floor_value", s.mapping.baseline},
                  {"floor_mm", s.zMm(sc.foot_top_units)}, {"steps", steps},
                  {"footprint_mm", {{sc.x0_mm, sc.y0_mm}, {sc.x1_mm, sc.y1_mm}}},
                  {"tread_mm", {sc.x1_mm - sc.xs_mm, sc.steps.empty() ? 0.0 : sc.steps[0].y_north_mm - sc.steps[0].y_south_mm}},
                  {"contacts", sc.contacts.size()}};
}

std::string scaleFactsLines(const Scene& s) {
    if (!sceneScale(s)) return "";
    std::ostringstream o;
    const SceneScale& sc = *sceneScale(s);
    std::ostringstream values;
    for (size_t k = 0; k < sc.steps.size(); ++k) values << (k ? ", " : "") << formatSignificant(sc.steps[k].value, 6);
    o << "  scale     " << sc.steps.size() << " steps every " << formatSignificant(sc.step, 6) << (sc.step_given ? "" : " (chosen)")
      << " east of the pillars, lowest in the south, on a foot at the floor (= " << formatSignificant(s.mapping.baseline, 6)
      << "): " << values.str() << "; treads " << formatFixed(sc.x1_mm - sc.xs_mm, 1) << " x "
      << formatFixed(sc.steps.empty() ? 0.0 : sc.steps[0].y_north_mm - sc.steps[0].y_south_mm, 1) << " mm, rising "
      << formatFixed(s.zMm(sc.steps.empty() ? 0 : sc.steps[0].top_units - sc.foot_top_units), 2) << " mm to "
      << formatFixed(s.zMm(sc.steps.empty() ? 0 : sc.steps.back().top_units - sc.foot_top_units), 2)
      << " mm above the floor\n";
    return o.str();
}

std::vector<TactileClaim> scaleTactileClaims(const Scene& s) {
    const SceneScale* sc = sceneScale(s);
    if (!sc) return {};
    std::vector<TactileClaim> out;
    int64_t below = sc->foot_top_units;
    for (const ScaleStep& st : sc->steps) {
        out.push_back({"the step for " + formatSignificant(st.value), 0.5 * (sc->xs_mm + sc->x1_mm),
                       0.5 * (st.y_south_mm + st.y_north_mm), s.zMm(st.top_units), s.zMm(below), kScaleMinRiserMm,
                       std::min(sc->x1_mm - sc->xs_mm, st.y_north_mm - st.y_south_mm), kScaleTreadMm,
                       "risers of 1 mm for what matters (3D-printed tactile graphics, printdisability.org); treads "
                       "of 1/4 in (APH, Guidelines for Design of Tactile Graphics, 1997)"});
        below = st.top_units;
    }
    return out;
}

std::string scaleKeyParagraph(const Scene& s, const KeyNumbers& say) {
    const SceneScale* sc = sceneScale(s);
    if (!sc) return "";
    std::string steps;
    for (size_t k = 0; k < sc->steps.size(); ++k)
        steps += (k == 0 ? "" : k + 1 == sc->steps.size() ? " and " : ", ") +
                 (k + 1 == sc->steps.size() ? say.amount(sc->steps[k].value) : say.number(sc->steps[k].value));
    return "A tactile scale stands east of the pillars: " + std::to_string(sc->steps.size()) +
           " steps, the lowest in the south, at " + steps + ". Put a finger on a pillar and one on the steps to read its value.";
}

}  // namespace tsf
