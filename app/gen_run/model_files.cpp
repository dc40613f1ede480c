#include "app/gen_run/model_files.h"

#include <filesystem>
#include <string>
#include <vector>

#include "app/halves_output.h"
#include "app/tiles_output.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/three_mf_writer.h"

namespace tsf::cli {

namespace {

// --parts: one 3MF object made of the model's parts, laid out as asked.
void writeParts(const GenCommandOptions& o, const std::vector<MeshPart>& parts, MeshWriteOptions wo, GenSummary& summary) {
    wo.parts_layout = o.parts_layout == "prusaslicer" ? MeshWriteOptions::PartsLayout::PrusaSlicer
                                                      : MeshWriteOptions::PartsLayout::Portable;
    write3mfParts(parts, o.output, wo);
    std::string names;
    for (const MeshPart& p : parts) names += (names.empty() ? "" : ", ") + p.name;
    summary.outputs.push_back({o.output, "model, one object in " + std::to_string(parts.size()) + " parts: " + names});
}

}  // namespace

MeshWriteOptions modelWriteOptions(const GenCommandOptions& o) {
    MeshWriteOptions wo;
    wo.ascii_stl = o.ascii;
    // The input's file name only: a shared model must not carry the folders
    // of the machine it was made on.
    wo.title = "tsf " TSF_VERSION " " + std::filesystem::path(o.gen.input).filename().string();
    return wo;
}

void writeModelFiles(const GenCommandOptions& o, const VerifiedModel& made, const std::optional<VerifiedTiles>& tiles,
                     GenSummary& summary) {
    if (o.output.empty()) return;
    const MeshWriteOptions wo = modelWriteOptions(o);
    if (made.written_ahead) {
        summary.outputs.push_back({o.output, "model"});  // written while it was verified
    } else if (made.halves) {
        writeHalves(*made.halves, o.output, wo, summary);
    } else if (tiles) {
        writeTiles(*tiles, o.output, wo, summary);
    } else if (o.parts) {
        writeParts(o, made.parts, wo, summary);
    } else {
        writeMesh(made.mesh, o.output, wo);
        summary.outputs.push_back({o.output, "model"});
    }
}

}  // namespace tsf::cli
