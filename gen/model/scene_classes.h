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
    /// What tells it apart when a feature does (Feature::class_marks: a
    /// class map's texture, gen/model/features/class_textures.h); "" when
    /// the classes stand at heights.
    std::string texture;
    bool texture_shared = false;  ///< one of the rarer classes that share the last texture
    int64_t border_cells = 0;     ///< of its cells, those on the grid's edge
    /// It holds most of the grid's edge (kBackgroundBorderShare of its data
    /// cells, and more than any other class): most likely a background (the
    /// area outside a survey, sea round an island), not a class of interest.
    bool background = false;
};

/// The share of the grid edge's data cells a class must hold to be named a
/// background: more than half (so at most one class is).
inline constexpr double kBackgroundBorderShare = 0.5;

/// Every class the Scene's data cells hold, from the lowest, with its name
/// from `names` (the file's, gen/field/raster.h) where it has one. With
/// `order` (FieldInput::class_order) the cells hold ranks, 1 for order[0],
/// and each class is told by its code; without, they hold the codes.
/// Lowest first; told apart by a feature (Feature::class_marks: a class
/// map's textures), in its order (commonest first, the order the textures
/// are handed out in).
std::vector<SceneClass> sceneClasses(const Scene& scene, const std::vector<RasterClass>& names,
                                     const std::vector<double>& order = {});

/// The background class (SceneClass::background) among `classes`, or null.
const SceneClass* backgroundClass(const std::vector<SceneClass>& classes);

/// One sentence for the summary and the key on a background class: which,
/// and how much of the edge and of the model; "" without one.
std::string backgroundSentence(const std::vector<SceneClass>& classes);

/// What to do about it, for the summary (command-line options); "" without one.
std::string backgroundRemedy(const std::vector<SceneClass>& classes);

/// "11 Open water" or "11" (no name): how a person is told a class.
std::string className(const SceneClass& c);

}  // namespace tsf
