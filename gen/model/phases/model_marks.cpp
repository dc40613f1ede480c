#include "gen/model/phases/model_marks.h"

#include <utility>

#include "gen/model/feature_registry.h"
#include "gen/model/features/marks.h"
#include "gen/model/scene_tiles.h"
#include "gen/util/error.h"

namespace tsf {

void placeModelMarks(const SceneParams& params, Scene& s) {
    const TileRequest* tile = params.requests.get<TileRequest>();
    if (!tile || !tile->marks) {
        placeMarks(s);
        return;
    }
    // A tile draws the model's marks where the model has them.
    s.marks = {};
    s.marks.notch = tile->marks->notch;
    s.marks.triangle = tile->marks->triangle;
    if (s.marks.triangle) {
        const int32_t anchor = s.marks.triangle->anchor;
        if (anchor < 0 || size_t(anchor) >= s.kept_index.size() || s.kept_index[size_t(anchor)] < 0)
            throw InputError("a tile does not hold the cell its orientation triangle stands on");
        s.marks.triangle->anchor = s.kept_index[size_t(anchor)];
    }
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
