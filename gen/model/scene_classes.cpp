#include "gen/model/scene_classes.h"

#include <cmath>
#include <map>

#include "gen/util/number_format.h"

namespace tsf {

std::vector<SceneClass> sceneClasses(const Scene& s, const std::vector<RasterClass>& names) {
    std::map<double, SceneClass> by_code;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data || !std::isfinite(s.value[k])) continue;
        SceneClass& c = by_code[s.value[k]];
        c.code = s.value[k];
        ++c.cells;
        c.height_mm = s.zMm(snapUnits(s.mapping.heightMm(c.code), s.z_snap_mm));
    }
    std::vector<SceneClass> out;
    for (auto& [code, c] : by_code) {
        for (const RasterClass& n : names)
            if (n.code == code) c.name = n.name;
        out.push_back(std::move(c));
    }
    return out;
}

std::string className(const SceneClass& c) {
    return formatSignificant(c.code) + (c.name.empty() ? "" : " " + c.name);
}

}  // namespace tsf
