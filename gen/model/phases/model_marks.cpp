#include "gen/model/phases/model_marks.h"

#include <utility>

#include "gen/model/feature_registry.h"
#include "gen/model/features/marks.h"
#include "gen/util/error.h"

namespace tsf {

void placeModelMarks(Scene& s) {
    // A piece of the model (a tile) draws the whole model's marks where the
    // model has them.
    std::optional<Marks> given = featureGivenMarks(s);
    if (!given) {
        placeMarks(s);
        return;
    }
    s.marks = std::move(*given);
    buildMarkFaces(s);
}

bool tabFallsBackToData(const SceneParams& params, const Scene& s) {
    return marksOnTab(params) && !carriedMarks(s) && s.keptCount() > 0;
}

SceneParams marksInData(const SceneParams& params) {
    SceneParams in_data = params;
    in_data.marks.place = MarkPlace::Data;
    return in_data;
}

void noteMarksInData(const std::string& tab_note, Scene& again) {
    again.notes.insert(again.notes.begin(), tab_note + "; they are placed in the data instead, where they fit");
}

}  // namespace tsf
