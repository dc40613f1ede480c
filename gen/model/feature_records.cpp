#include "gen/model/feature_records.h"

#include "gen/model/feature_registry.h"
#include "gen/model/features/class_textures_record.h"
#include "gen/model/features/halves_facts.h"
#include "gen/model/features/legend_record.h"

namespace tsf {

const std::vector<FeatureRecord>& featureRecords() {
    // The registry's features where they stood: the one carrying the marks
    // first, the features beside the pillars where the scale stood.
    static const std::vector<FeatureRecord> records = [] {
        std::vector<FeatureRecord> r;
        const auto add = [&r](FeaturePhase phase) {
            for (const Feature* f : featuresOf(phase))
                if (f->record) r.push_back({f->name, f->record, f->read_record, f->facts_listed_when_absent});
        };
        add(FeaturePhase::Marks);
        r.push_back({"legend", legendRecord, readLegendRecord});
        add(FeaturePhase::Beside);
        r.push_back({"class_textures", classTexturesRecord, readClassTexturesRecord});
        return r;
    }();
    return records;
}

const std::vector<FeatureFacts>& featureFacts() {
    static const std::vector<FeatureFacts> facts = [] {
        std::vector<FeatureFacts> r;
        const auto add = [&r](FeaturePhase phase) {
            for (const Feature* f : featuresOf(phase))
                if (f->facts_json) r.push_back({f->name, f->facts_listed_when_absent, f->facts_json, f->facts_lines});
        };
        add(FeaturePhase::Marks);
        r.push_back({"legend", true, legendFactsJson, legendFactsLines});
        add(FeaturePhase::Beside);
        r.push_back({"halves", false, halvesFactsJson, halvesFactsLines});
        r.push_back({"class_textures", false, classTexturesFactsJson, classTexturesFactsLines});
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
