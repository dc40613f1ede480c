// The orientation marks of a model or of one of its tiles: a tile draws
// the model's own notch and triangle where the model has them; a model
// places its own (gen/model/features/marks.h; the tab that carries them is
// a feature of the registry, gen/model/features/tab/).
// When a tab was asked for and no pillar on the west side can carry it,
// the marks go in the data instead, where they fit, as the thesis places
// them, rather than nowhere: the Scene is built again for that.
#pragma once

#include <string>

#include "gen/model/scene.h"

namespace tsf {

/// The notch and the triangle: the ones a piece of the model is given
/// where the whole has them (Feature::given_marks: a tile's) or placed for
/// the model, with the faces they need. Throws InputError when a tile does
/// not hold the triangle's cell.
void placeModelMarks(Scene& s);

/// The marks were asked on a tab (the registry's feature placed in
/// FeaturePhase::Marks) and none could be placed (its last note says why).
bool tabFallsBackToData(const SceneParams& params, const Scene& s);

/// The parameters of the build again: the marks in the data.
SceneParams marksInData(const SceneParams& params);

/// The rebuilt Scene's first note: why the tab's marks are in the data
/// (tab_note: the note of the build without a tab).
void noteMarksInData(const std::string& tab_note, Scene& again);

}  // namespace tsf
