// tsf gen: field in, model out (mesh file, OpenSCAD, scene sidecar), verified.
#include <cstdio>
#include <iostream>

#include "gen/cli/commands.h"
#include "gen/cli/gen_options.h"
#include "gen/cli/gen_summary.h"
#include "gen/cli/stage_timer.h"
#include "gen/direct_mesher.h"
#include "gen/error.h"
#include "gen/mesh_io/mesh_writer.h"

namespace tsf::cli {
namespace {

struct GenCommandOptions {
    GenOptions gen;
    std::string output;
    std::string scad;
    bool ascii = false;
    bool no_verify = false;
    bool json = false;
    bool progress = false;
};

// Grids above this many cells print progress lines without being asked.
constexpr int64_t kProgressCells = 250000;

void runGen(const GenCommandOptions& o) {
    if (o.output.empty() && o.scad.empty())
        throw InputError("nothing to write: give -o MODEL.stl|.3mf|.off|.obj and/or --scad MODEL.scad");
    StageTimer timer(o.progress);
    GenSummary summary;
    summary.input = o.gen.input;

    timer.begin("reading");
    const HexField field = loadField(o.gen);
    summary.field = &field;
    if (field.grid.cellCount() > kProgressCells && !o.progress && !o.json)
        std::fprintf(stderr, "tsf: %d x %d cells, this may take a few seconds\n", field.grid.cols, field.grid.rows);
    timer.begin("scene");
    const Scene scene = buildScene(field, o.gen.scene);
    summary.scene = &scene;
    timer.begin("meshing");
    const Mesh mesh = meshScene(scene);
    summary.mesh = &mesh;

    if (!o.output.empty()) {
        timer.begin("writing");
        MeshWriteOptions wo;
        wo.ascii_stl = o.ascii;
        wo.title = "tsf " TSF_VERSION " " + o.gen.input;
        writeMesh(mesh, o.output, wo);
        summary.outputs.push_back({o.output, "model"});
    }
    timer.end();
    summary.timings_ms = timer.stagesMs();
    if (o.json)
        std::cout << summaryJson(summary).dump(2) << "\n";
    else
        std::cout << formatSummary(summary);
}

}  // namespace

void addGenCommand(CLI::App& app) {
    auto opts = std::make_shared<GenCommandOptions>();
    CLI::App* cmd = app.add_subcommand("gen", "Generate a printable hex-pillar model from a field");
    cmd->footer(
        "Examples:\n"
        "  tsf gen examples/volcano.csv -o volcano.stl\n"
        "  tsf gen examples/airports-europe.csv --points x=lon,y=lat --bins 40 --mirror -o europe.3mf\n"
        "Frame: x east, y north, z up, millimetres; the model stands on z = 0.");
    addGenOptions(cmd, opts->gen);
    cmd->add_option("-o,--output", opts->output, "Model file: .stl (binary), .3mf, .off or .obj");
    cmd->add_option("--scad", opts->scad, "Also write a parametric OpenSCAD file");
    cmd->add_flag("--ascii", opts->ascii, "Write ASCII STL instead of binary");
    cmd->add_flag("--no-verify", opts->no_verify, "Skip verifying the model before writing it");
    cmd->add_flag("--json", opts->json, "Print the summary as JSON");
    cmd->add_flag("--progress", opts->progress, "Print each stage and its time on stderr");
    cmd->callback([opts] { runGen(*opts); });
}

void addInfoCommand(CLI::App& app) {
    auto opts = std::make_shared<GenOptions>();
    auto json = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand("info", "Show what tsf sees in an input file and the model it would make");
    addGenOptions(cmd, *opts);
    cmd->add_flag("--json", *json, "Print as JSON");
    cmd->callback([opts, json] {
        const HexField field = loadField(*opts);
        const Scene scene = buildScene(field, opts->scene);
        if (*json) {
            nlohmann::json j = sceneFactsJson(scene);
            j["input"] = opts->input;
            j["field"] = {{"how", field.how}, {"pitch_data_units", field.pitch_data}};
            std::cout << j.dump(2) << "\n";
        } else {
            std::cout << "tsf info: " << opts->input << "\n  input     " << field.how << "\n" << formatSceneFacts(scene);
        }
    });
}

}  // namespace tsf::cli
