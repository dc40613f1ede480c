// The classes of a categorical model (a land-cover map, soil types): which
// class codes its cells hold, how many cells each, at what height, and the
// names the file gives them. Facts for the summary and the key; nothing is
// decided here.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/raster.h"
#include "gen/model/scene.h"

namespace tsf {

struct SceneClass {
    double code = 0;       ///< the class's value in the data
    std::string name;      ///< from the file ("" when it names none)
    int64_t cells = 0;     ///< kept cells that hold it
    double height_mm = 0;  ///< its height above the floor (mm, on the z grid), as its cells stand
    /// Its texture (gen/model/features/class_textures.h) when the classes are
    /// told apart by texture; "" when they stand at heights.
    std::string texture;
    bool texture_shared = false;  ///< one of the rarer classes that share the last texture
};

/// Every class the Scene's data cells hold, from the lowest, with its name
/// from `names` (the file's, gen/field/raster.h) where it has one. With
/// `order` (FieldInput::class_order) the cells hold ranks, 1 for order[0],
/// and each class is told by its code; without, they hold the codes.
/// Lowest first; with textures (Scene::textures), commonest first, the
/// order the textures are handed out in.
std::vector<SceneClass> sceneClasses(const Scene& scene, const std::vector<RasterClass>& names,
                                     const std::vector<double>& order = {});

/// "11 Open water" or "11" (no name): how a person is told a class.
std::string className(const SceneClass& c);

}  // namespace tsf
