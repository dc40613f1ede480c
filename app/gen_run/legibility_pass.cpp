#include "app/gen_run/legibility_pass.h"

#include <optional>
#include <vector>

#include "app/gen_run/model_request.h"
#include "app/legible_defaults.h"
#include "gen/model/build_scene.h"
#include "gen/readers/load_field.h"
#include "gen/util/error.h"

namespace tsf::cli {

LegibilityOutcome passLegibility(GenCommandOptions& o, HexField& field, Scene& scene, VerifiedModel& made,
                                 const ModelRequest& rq, StageTimer& timer, GenSummary& summary) {
    LegibilityOutcome out;
    if (!made.report) return out;
    if (failedLegibility(*made.report).empty()) return out;
    timer.begin("legibility");
    const LegibleDefaults ld =
        legibleDefaults(field, scene, *made.report, o.legibility_given, rq.verify_options, [&](int bins) -> std::optional<HexField> {
            GenOptions at = o.gen;
            at.bins = bins;
            try {
                return loadField(at);
            } catch (const InputError&) {
                return std::nullopt;
            }
        });
    summary.legibility = ld.lines;
    summary.legibility_json = ld.json;
    if (ld.params) {
        o.gen.scene = *ld.params;
        if (ld.bins > 0) {
            o.gen.bins = ld.bins;
            field = loadField(o.gen);
        }
        scene = buildScene(field, o.gen.scene);
        out.change = ld.key_note;
        made = makeModelOrRefuse(scene, rq, timer);
    }
    if (!failedLegibility(*made.report).empty() && ld.json.is_object() && ld.json.contains("key")) {
        out.key = "Where the model may not read well:";
        for (const auto& why : ld.json["key"]) out.key += " " + why.get<std::string>() + ".";
    }
    return out;
}

}  // namespace tsf::cli
