#include "gen/model/feature_records.h"

#include "gen/model/feature_registry.h"
#include "gen/model/features/halves_facts.h"

namespace tsf {

const std::vector<FeatureRecord>& featureRecords() {
    // The registry's features where they stood: the one carrying the marks
    // first, the legend, the features beside the pillars, the features of
    // the pillars themselves.
    static const std::vector<FeatureRecord> records = [] {
        std::vector<FeatureRecord> r;
        for (const Feature* f : featuresOf(
                 {FeaturePhase::Marks, FeaturePhase::BeforeMarks, FeaturePhase::Beside, FeaturePhase::Frame}))
            if (f->record)
                r.push_back({f->name, f->record, f->read_record,
                             f->facts_listed_when_absent || f->record_listed_when_absent});
        return r;
    }();
    return records;
}

const std::vector<FeatureFacts>& featureFacts() {
    static const std::vector<FeatureFacts> facts = [] {
        std::vector<FeatureFacts> r;
        for (const Feature* f : featuresMarksFirst())
            if (f->facts_json) r.push_back({f->name, f->facts_listed_when_absent, f->facts_json, f->facts_lines});
        r.push_back({"halves", false, halvesFactsJson, halvesFactsLines});
        for (const Feature* f : featuresOf({FeaturePhase::Frame}))
            if (f->facts_json) r.push_back({f->name, f->facts_listed_when_absent, f->facts_json, f->facts_lines});
        return r;
    }();
    return facts;
}

std::vector<std::string> dottedPath(const char* path) {
    std::vector<std::string> keys;
    std::string key;
    for (const char* c = path; *c; ++c) {
        if (*c == '.') {
            keys.push_back(key);
            key.clear();
        } else {
            key += *c;
        }
    }
    keys.push_back(key);
    return keys;
}

}  // namespace tsf
