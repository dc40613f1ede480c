#include "app/gen_run/sidecar_file.h"

#include <filesystem>
#include <string>

#include "gen/model/scene_json.h"

namespace tsf::cli {

void writeSidecarFile(const GenCommandOptions& o, const Scene& scene, const std::optional<FileStamp>& model_stamp,
                      const std::string* cells, GenSummary& summary) {
    const std::string sidecar = sidecarPath(o);
    std::optional<SceneModelRecord> model;
    if (model_stamp) model = SceneModelRecord{std::filesystem::path(o.output).filename().string(), *model_stamp};
    writeSceneJson(scene, sidecar, model ? &*model : nullptr, cells);
    summary.outputs.push_back({sidecar, "scene for tsf verify --scene"});
}

}  // namespace tsf::cli
