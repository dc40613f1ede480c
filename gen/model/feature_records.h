// The features' own records in the scene sidecar (gen/model/scene_json.h)
// and their facts in the summary: each feature that holds data of its own
// in the Scene (the orientation tab, the braille legend, the tactile scale,
// the halves) writes, reads and reports it in its own modules, and these
// are the lists of them, so the sidecar and the summary name none. A
// feature of the registry (gen/model/feature_registry.h: the tab, the
// scale) hands its record and facts in through its Feature; the lists take
// them from there, where it stood (the tab first, the scale after the
// legend).
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
    /// Written as null when the Scene has none (the features that were
    /// always in the sidecar); else left out then.
    bool listed_when_absent = true;
};

/// What a feature says of itself in tsf gen's summary and `tsf info`
/// (app/gen_summary.h).
struct FeatureFacts {
    /// Where its facts sit in the summary's scene JSON, dotted: "marks.tab".
    const char* path;
    /// True: the member is null when the Scene has none; false: left out.
    bool listed_when_absent;
    nlohmann::json (*json)(const Scene& scene);  ///< null when the Scene has none
    std::string (*lines)(const Scene& scene);    ///< "  label     text\n" lines; "" when none
};

/// Every feature's facts, in the order the summary prints them.
const std::vector<FeatureFacts>& featureFacts();

/// A dotted path as its keys: "marks.tab" -> {"marks", "tab"}.
std::vector<std::string> dottedPath(const char* path);

/// Every feature record, in the order they are read.
const std::vector<FeatureRecord>& featureRecords();

/// A record's path as its keys.
inline std::vector<std::string> recordPath(const FeatureRecord& record) { return dottedPath(record.path); }

/// A facts entry's path as its keys.
inline std::vector<std::string> factsPath(const FeatureFacts& facts) { return dottedPath(facts.path); }

}  // namespace tsf
