// tsf verify: is a mesh a printable solid, does it hold the data, is it the
// same solid as another mesh? See docs/verifier.md.
#include <iostream>
#include <memory>
#include <optional>
#include <string>

#include "app/bed_size.h"
#include "app/commands.h"
#include "app/gen_options.h"
#include "app/key_stamp.h"
#include "app/printer_fit.h"
#include "gen/util/error.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/model/scene_json.h"
#include "verify/verify_model.h"
#include "verify/verify_parts.h"
#include "gen/model/build_scene.h"

namespace tsf::cli {
namespace {

struct VerifyCommandOptions {
    std::string model;
    std::string against;    ///< field file: rebuild the Scene with the gen options
    GenOptions gen;
    std::string scene;      ///< scene sidecar
    std::string reference;  ///< reference mesh
    bool exact = false;
    bool json = false;
    bool strict = false;
    bool no_printability = false;
    bool tactile = false;
    bool quick = false;
    double nozzle_mm = kDefaultNozzleMm;
    double layer_mm = kDefaultLayerMm;
    std::string bed;
    double tolerance_mm = kDefaultAgreementToleranceMm;
    double height_tolerance_mm = 0;
    size_t max_offenders = 10;
};

// The reader's findings as lines for the report.
std::vector<std::string> readNotes(const MeshReadReport& r, const std::string& prefix) {
    std::vector<std::string> notes;
    // The reader's notes say what was merged; this line says what was read.
    notes.push_back(prefix + r.format + ": " + std::to_string(r.input_triangles) + " triangles, " +
                    std::to_string(r.input_vertices) + " vertices in the file");
    if (r.degenerate_index_triangles)
        notes.push_back(prefix + std::to_string(r.degenerate_index_triangles) + " triangles repeat a vertex (kept)");
    for (const std::string& n : r.notes) notes.push_back(prefix + n);
    return notes;
}

bool given(const CLI::App* cmd, const char* option) { return cmd->get_option(option)->count() > 0; }

void runVerify(CLI::App* cmd, const VerifyCommandOptions& o) {
    // Model options only make sense with a field to rebuild the Scene from.
    if (o.against.empty()) {
        for (const CLI::Option* opt : cmd->get_options()) {
            const std::string& g = opt->get_group();
            if ((g == "Input" || g == "Model (millimetres)") && opt->count() > 0)
                throw InputError(opt->get_name() + " describes how a field becomes a model; it needs --against FIELD");
        }
    }

    // Keys beside the model from another run of tsf gen (a run killed while
    // it renamed its files) would tell a reader about another model.
    checkKeysMatchModel(o.model);

    MeshReadReport read;
    // A 3MF written in parts (tsf gen --parts: the components of its one
    // build item, or an object whose volumes are named) is judged part by
    // part and as an assembly; any other file, several objects included, as
    // one mesh.
    std::vector<MeshPart> parts = readMeshParts(o.model, &read);
    if (read.format == "3mf" && !read.written_in_parts) {
        parts.clear();
        read = {};
        parts.push_back({"model", readMesh(o.model, &read)});
    }
    if (parts.size() > 1 && !o.reference.empty())
        throw InputError(o.model, 0, 0,
                         "has " + std::to_string(parts.size()) +
                             " parts; --reference compares one solid with another: write the model as one solid "
                             "(tsf gen without --parts) to compare it");
    const Mesh mesh = parts.size() == 1 ? std::move(parts[0].mesh) : Mesh{};

    std::optional<Scene> scene;
    if (!o.against.empty()) {
        GenOptions g = o.gen;
        g.input = o.against;
        refuseBandSeries(g, "verify --against");
        // --layer, --nozzle and --bed shape the model in tsf gen (heights on
        // whole layers, the fit into the bed, the steepest tilt): the same
        // options shape the Scene it is checked against.
        PrinterSpec printer;
        if (given(cmd, "--layer")) printer.layer_mm = o.layer_mm;
        if (given(cmd, "--nozzle")) printer.nozzle_mm = o.nozzle_mm;
        if (given(cmd, "--bed")) printer.bed = o.bed;
        GivenOptions model_given;
        model_given.width = given(cmd, "--width");
        model_given.depth = given(cmd, "--depth");
        model_given.snap = given(cmd, "--snap");
        model_given.max_slope = given(cmd, "--max-slope");
        (void)applyPrinterFit(printer, model_given, g);
        // As tsf gen made it: an STL or 3MF holds a z grid float32 resolves.
        const std::string ext = lowerCaseExtension(o.model);
        g.scene.stored_as_float32 = ext == ".stl" || ext == ".3mf";
        scene = buildScene(loadField(g), g.scene);
    } else if (!o.scene.empty()) {
        std::optional<SceneModelRecord> written_with;
        scene = readSceneJson(o.scene, &written_with);
        // A sidecar beside a newer (or older) model of the same name: refuse
        // rather than judge this model by another run's data.
        if (written_with) checkSceneModelRecord(*written_with, o.scene, o.model);
    }

    VerifyOptions vo;
    vo.name = o.model;
    vo.read_notes = readNotes(read, "");
    vo.exact = o.exact;
    vo.max_offenders = o.max_offenders;
    vo.height_tolerance_mm = o.height_tolerance_mm;
    vo.distance_tolerance_mm = o.tolerance_mm;
    vo.printability = !o.no_printability;
    vo.nozzle_mm = o.nozzle_mm;
    vo.layer_mm = o.layer_mm;
    if (!o.bed.empty()) {
        const BedSize bed = parseBedSize(o.bed, "--bed", /*need_height=*/true);
        vo.bed_mm = {bed.width_mm, bed.depth_mm, bed.height_mm};
    }
    vo.fail_on_warnings = o.strict;
    vo.tactile = o.tactile;
    if (o.quick) {
        // What tsf gen's self-check keeps above kQuickVerifyTriangles.
        vo.self_intersections = false;
        vo.printability = false;
    }

    Mesh reference;
    if (!o.reference.empty()) {
        MeshReadReport ref_read;
        reference = readMesh(o.reference, &ref_read);
        for (const std::string& n : readNotes(ref_read, "reference: ")) vo.read_notes.push_back(n);
        vo.reference = &reference;
        vo.reference_name = o.reference;
    }

    if (parts.size() > 1) {
        const PartsVerifyReport pr = verifyParts(parts, scene ? &*scene : nullptr, vo);
        if (o.json) {
            nlohmann::json j = toJson(pr);
            j["against"] = o.against.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.against);
            j["scene"] = o.scene.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.scene);
            std::cout << j.dump(2) << "\n";
        } else {
            std::cout << formatPartsReport(pr);
        }
        std::cout.flush();
        if (!pr.passed()) throw CLI::RuntimeError(kExitCheckFailed);
        return;
    }
    const VerifyReport report = verifyModel(mesh, scene ? &*scene : nullptr, vo);
    if (o.json) {
        nlohmann::json j = toJson(report);
        j["against"] = o.against.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.against);
        j["scene"] = o.scene.empty() ? nlohmann::json(nullptr) : nlohmann::json(o.scene);
        std::cout << j.dump(2) << "\n";
    } else {
        std::cout << formatReport(report);
    }
    std::cout.flush();
    if (!report.passed()) throw CLI::RuntimeError(kExitCheckFailed);
}

}  // namespace

void addVerifyCommand(CLI::App& app) {
    auto opts = std::make_shared<VerifyCommandOptions>();
    CLI::App* cmd = app.add_subcommand("verify", "Check that a mesh is a printable solid, holds the data, "
                                                 "and matches a reference");
    cmd->footer(
        "Examples:\n"
        "  tsf verify model.stl                                  # a printable solid?\n"
        "  tsf verify model.stl --scene model.stl.scene.json     # ... standing at the data's heights?\n"
        "  tsf verify model.stl --against field.csv --mirror     # the same, rebuilt from the field\n"
        "  tsf verify openscad.stl --reference direct.stl        # the same solid as another mesh?\n"
        "  tsf verify model.stl --scene model.stl.scene.json --tactile  # ... and readable by hand?\n"
        "  tsf verify parts.3mf                                  # a 3MF of parts (tsf gen --parts): each part\n"
        "                                                        # alone, then touching but never overlapping\n"
        "Exit codes: 0 every check passed, 1 a check failed, 2 bad input.\n"
        "Coordinates in the report are millimetres: x east, y north, z up.");
    cmd->add_option("model", opts->model, "Mesh to check: STL (binary or ASCII), 3MF, OFF or OBJ")->required();

    auto* what = "What to check against";
    CLI::Option* against = cmd->add_option("--against", opts->against,
                                           "Field file the model was made from; give the same model options as to "
                                           "tsf gen (listed below) and its --layer, --nozzle and --bed (here "
                                           "WIDTHxDEPTHxHEIGHT), which shape the model as they do in tsf gen")->group(what);
    CLI::Option* scene = cmd->add_option("--scene", opts->scene, "Scene sidecar written by tsf gen (MODEL.scene.json)")
                             ->group(what);
    against->excludes(scene);
    cmd->add_option("--reference", opts->reference, "Another mesh that should be the same solid")->group(what);
    cmd->add_option("--tolerance", opts->tolerance_mm,
                    "--reference: largest distance between the two surfaces, mm")
        ->check(CLI::PositiveNumber)->capture_default_str()->group(what);
    cmd->add_option("--height-tolerance", opts->height_tolerance_mm,
                    "Largest height error of a cell, mm (default: half the z snap step)")
        ->check(CLI::PositiveNumber)->group(what);

    auto* print = "Printability (warnings)";
    cmd->add_option("--nozzle", opts->nozzle_mm, "Nozzle width, mm: thinner walls and narrower gaps are flagged")
        ->check(CLI::PositiveNumber)->capture_default_str()->group(print);
    cmd->add_option("--layer", opts->layer_mm, "Layer height, mm: a base thinner than two layers is flagged")
        ->check(CLI::PositiveNumber)->capture_default_str()->group(print);
    cmd->add_option("--bed", opts->bed, "Printable volume WIDTHxDEPTHxHEIGHT, mm (e.g. 220x220x250)")->group(print);
    cmd->add_flag("--strict", opts->strict, "Printability warnings fail the verification")->group(print);
    cmd->add_flag("--no-printability", opts->no_printability, "Skip the printability checks")->group(print);
    cmd->add_flag("--tactile", opts->tactile,
                  "Also check the model as a hand reads it: no sharp points or knife edges, no pit or valley a "
                  "fingertip cannot reach the bottom of, and (with --scene) orientation marks of tactile size, "
                  "pillars that stand a hand's push, neighbouring steps of 0.5 mm (with --scene only the data "
                  "tops must be reached: the pits of cells without data and the groove beside the pillars hold no "
                  "value: docs/tactile.md)")
        ->group(print);
    cmd->add_flag("--quick", opts->quick,
                  "Only the checks tsf gen's self-check keeps on a model above 3 million triangles: topology, "
                  "solid, the read-backs and --reference; no self-intersection test, no printability "
                  "(docs/verifier.md: what each level catches)")
        ->excludes(cmd->get_option("--tactile"))
        ->group(print);

    auto* out = "Output";
    cmd->add_flag("--json", opts->json, "Print every figure as JSON")->group(out);
    cmd->add_flag("--exact", opts->exact, "Use CGAL's exact-construction kernel (slower; see docs/verifier.md)")
        ->group(out);
    cmd->add_option("--max-offenders", opts->max_offenders, "Worst offenders listed per check")
        ->check(CLI::Range(0, 100000))->capture_default_str()->group(out);

    addGenOptions(cmd, opts->gen, /*with_input=*/false);
    cmd->callback([cmd, opts] { runVerify(cmd, *opts); });
}

}  // namespace tsf::cli
