// The features' own records in the scene sidecar (gen/model/scene_json.h):
// each feature that holds data of its own in the Scene (the orientation
// tab, the braille legend, the tactile scale) writes and reads it in its
// own module, and this is the one list of them, so the sidecar reads and
// writes them without naming any.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"

namespace tsf {

struct FeatureRecord {
    /// Where the record sits in the sidecar, dotted: "legend", "marks.tab".
    const char* path;
    /// The record of the Scene's feature as placed; null when it has none.
    nlohmann::json (*write)(const Scene& scene);
    /// Reads a record that is not null into the Scene, as recorded (nothing
    /// is placed again): called once the cells, the faces and the shapes
    /// are read, in the order of featureRecords(); `version` is the
    /// sidecar's. Throws InputError naming the member's path.
    void (*read)(const nlohmann::json& record, const std::string& path, int version, Scene& scene);
};

/// Every feature record, in the order they are read.
const std::vector<FeatureRecord>& featureRecords();

/// A record's path as its keys: "marks.tab" -> {"marks", "tab"}.
std::vector<std::string> recordPath(const FeatureRecord& record);

}  // namespace tsf
