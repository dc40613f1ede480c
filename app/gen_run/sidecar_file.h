// MODEL.scene.json: the scene sidecar that lets `tsf verify --scene` check
// any mesh of this model later (gen/model/scene_json.h).
#pragma once

#include <optional>

#include "app/gen_run/gen_command_options.h"
#include "app/gen_summary.h"
#include "gen/model/scene.h"
#include "gen/util/file_stamp.h"

namespace tsf::cli {

/// Writes the sidecar to sidecarPath(o) and lists it in the summary. It is
/// committed after the model and names the model file's size and hash
/// (model_stamp; none without one model file): a run killed between the
/// two leaves a new model beside an older sidecar, and `tsf verify
/// --scene` refuses that pair instead of judging one model by another's data.
/// `cells`: sceneCellsJson(scene), formatted while the model was written
/// (nullptr: formatted here).
void writeSidecarFile(const GenCommandOptions& o, const Scene& scene, const std::optional<FileStamp>& model_stamp,
                      const std::string* cells, GenSummary& summary);

}  // namespace tsf::cli
