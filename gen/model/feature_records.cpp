#include "gen/model/feature_records.h"

#include "gen/model/features/class_textures_record.h"
#include "gen/model/features/halves_facts.h"
#include "gen/model/features/legend_record.h"
#include "gen/model/features/orientation_tab_record.h"
#include "gen/model/features/scale_record.h"

namespace tsf {

const std::vector<FeatureRecord>& featureRecords() {
    static const std::vector<FeatureRecord> records = {
        {"marks.tab", tabRecord, readTabRecord},
        {"legend", legendRecord, readLegendRecord},
        {"scale", scaleRecord, readScaleRecord},
        {"class_textures", classTexturesRecord, readClassTexturesRecord},
    };
    return records;
}

const std::vector<FeatureFacts>& featureFacts() {
    static const std::vector<FeatureFacts> facts = {
        {"marks.tab", true, tabFactsJson, tabFactsLines},
        {"legend", true, legendFactsJson, legendFactsLines},
        {"scale", true, scaleFactsJson, scaleFactsLines},
        {"halves", false, halvesFactsJson, halvesFactsLines},
        {"class_textures", false, classTexturesFactsJson, classTexturesFactsLines},
    };
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
