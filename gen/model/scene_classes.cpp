#include "gen/model/scene_classes.h"

#include <cmath>
#include <map>

#include "gen/model/feature_registry.h"
#include "gen/util/number_format.h"

namespace tsf {

std::vector<SceneClass> sceneClasses(const Scene& s, const std::vector<RasterClass>& names, const std::vector<double>& order) {
    std::map<double, SceneClass> by_code;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data || !std::isfinite(s.value[k])) continue;
        // By the cell's value: the rank with an order (so the map is by height), else the code.
        SceneClass& c = by_code[s.value[k]];
        const size_t rank = size_t(s.value[k]);
        c.code = order.empty() ? s.value[k] : rank >= 1 && rank <= order.size() ? order[rank - 1] : NAN;
        ++c.cells;
        const int32_t col = s.col[k], row = s.row[k];
        if (col == 0 || row == 0 || col == s.grid.cols - 1 || row == s.grid.rows - 1) ++c.border_cells;
        // As the cell stands: its top above the floor (mirrored: its bottom).
        c.height_mm = s.zMm(s.params.bottom == Bottom::Mirrored ? s.bottom[k] : s.top[k] - s.floor_units);
    }
    int64_t border = 0;
    for (const auto& [value, c] : by_code) border += c.border_cells;
    for (auto& [value, c] : by_code)
        c.background = by_code.size() > 1 && border > 0 && double(c.border_cells) > kBackgroundBorderShare * double(border);
    std::vector<SceneClass> out;
    for (auto& [value, c] : by_code) {
        for (const RasterClass& n : names)
            if (n.code == c.code) c.name = n.name;
        out.push_back(std::move(c));
    }
    // Told apart by a feature (a class map's textures): in its order.
    if (const std::vector<ClassMark> marks = featureClassMarks(s); !marks.empty()) {
        std::vector<SceneClass> in_order;
        for (const ClassMark& m : marks)
            for (SceneClass& c : out)
                if (c.code == m.code) {
                    c.texture = m.name;
                    c.texture_shared = m.shared;
                    in_order.push_back(std::move(c));
                }
        out.swap(in_order);
    }
    return out;
}

const SceneClass* backgroundClass(const std::vector<SceneClass>& classes) {
    for (const SceneClass& c : classes)
        if (c.background) return &c;
    return nullptr;
}

std::string backgroundSentence(const std::vector<SceneClass>& classes) {
    const SceneClass* b = backgroundClass(classes);
    if (!b) return "";
    int64_t border = 0, cells = 0;
    for (const SceneClass& c : classes) {
        border += c.border_cells;
        cells += c.cells;
    }
    const auto percent = [](int64_t part, int64_t whole) {
        return std::to_string(int(std::lround(100.0 * double(part) / double(std::max<int64_t>(1, whole))))) + " percent";
    };
    return "Class " + className(*b) + " rings the edge of the map (" + percent(b->border_cells, border) +
           " of the edge, " + percent(b->cells, cells) + " of the model): it is most likely a background, such as the "
           "area outside a survey, rather than a class of interest.";
}

std::string backgroundRemedy(const std::vector<SceneClass>& classes) {
    const SceneClass* b = backgroundClass(classes);
    if (!b) return "";
    return "If class " + formatSignificant(b->code) + " is a background, --nodata " + formatSignificant(b->code) +
           " leaves it out (its hexagons become no-data pits or are culled); if it is a real class (sea round an "
           "island), --class-names FILE names it";
}

std::string className(const SceneClass& c) {
    return formatSignificant(c.code) + (c.name.empty() ? "" : " " + c.name);
}

}  // namespace tsf
