#include "gen/model/scene_classes.h"

#include <cmath>
#include <map>

#include "gen/model/features/class_textures.h"
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
        // As the cell stands: its top above the floor (mirrored: its bottom).
        c.height_mm = s.zMm(s.params.bottom == Bottom::Mirrored ? s.bottom[k] : s.top[k] - s.floor_units);
    }
    std::vector<SceneClass> out;
    for (auto& [value, c] : by_code) {
        for (const RasterClass& n : names)
            if (n.code == c.code) c.name = n.name;
        out.push_back(std::move(c));
    }
    if (s.textures) {
        std::vector<SceneClass> by_texture;
        for (const ClassTexture& t : s.textures->classes)
            for (SceneClass& c : out)
                if (c.code == t.code) {
                    c.texture = textureName(t.texture);
                    c.texture_shared = t.shared;
                    by_texture.push_back(std::move(c));
                }
        out.swap(by_texture);
    }
    return out;
}

std::string className(const SceneClass& c) {
    return formatSignificant(c.code) + (c.name.empty() ? "" : " " + c.name);
}

}  // namespace tsf
