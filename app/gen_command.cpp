// tsf gen: field in, model out (mesh file, OpenSCAD, scene sidecar), verified.
#include <cmath>
#include <filesystem>
#include <future>
#include <iostream>
#include <limits>
#include <optional>
#include <system_error>

#include "app/commands.h"
#include "app/gen_options.h"
#include "app/gen_run/bed_fit.h"
#include "app/gen_run/bed_tiles.h"
#include "app/gen_run/gen_command_options.h"
#include "app/gen_run/key_files.h"
#include "app/gen_run/legibility_pass.h"
#include "app/gen_run/model_files.h"
#include "app/gen_run/model_request.h"
#include "app/gen_run/model_verdict.h"
#include "app/gen_run/read_field.h"
#include "app/gen_run/request_checks.h"
#include "app/gen_run/run_preview.h"
#include "app/gen_run/run_report.h"
#include "app/gen_run/scad_files.h"
#include "app/gen_run/sidecar_file.h"
#include "app/gen_summary.h"
#include "app/input_report.h"
#include "app/printer_fit.h"
#include "app/stage_timer.h"
#include "app/tiles_output.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/model/build_scene.h"
#include "gen/model/scene_json.h"
#include "gen/readers/cf_time.h"
#include "gen/util/atomic_file.h"
#include "gen/util/error.h"
#include "gen/util/file_stamp.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
namespace {

// One model from the options: the request checked, the field read, the
// Scene built and fitted to the bed, the model made and verified (made
// again with defaults that pass when tsf's own fail a legibility check),
// then every file written as a temporary file and all renamed together.
void runGen(GenCommandOptions o, nlohmann::json* json_out = nullptr) {
    const ScadOptions so = scadOptions(o);
    checkGenRequest(o, so);
    StageTimer timer(o.progress);
    GenSummary summary;
    summary.input = o.gen.input;
    summary.printer_notes = applyPrinterFit(o.printer, o.given, o.gen);

    timer.begin("reading");
    HexField field = readGenField(o, summary);
    summary.field = &field;
    timer.begin("scene");
    // STL and 3MF store float32: the z grid must be one float32 resolves.
    const std::string model_ext = o.output.empty() ? "" : lowerCaseExtension(o.output);
    o.gen.scene.stored_as_float32 = model_ext == ".stl" || model_ext == ".3mf";
    Scene scene = buildSceneForBed(o, field);
    summary.scene = &scene;
    if (const std::string note = cellNozzleNote(scene.pitch_mm, o.printer); !note.empty())
        summary.printer_notes.push_back(note);

    // Every file of this run is written to a temporary file first and all
    // are renamed together at the end (a signal then leaves the old files
    // or the new ones, never a mix). The model file may be written while
    // it is verified (ModelRequest::write_ahead): a refusal then leaves
    // nothing behind either.
    std::optional<OutputSet> written(std::in_place);
    const ModelRequest rq = modelRequest(o, scene);
    VerifiedModel made = makeModelOrRefuse(scene, rq, timer);
    const LegibilityOutcome legibility = passLegibility(o, field, scene, made, rq, timer, summary);
    const std::optional<VerifiedTiles> tiles = tilesForBed(o, field, scene, rq, timer, summary);
    summarizeVerdict(made, rq, scene, o.keep_unprintable, summary);

    if (!o.output.empty()) timer.begin("writing");
    // The sidecar's cells do not depend on the model file: formatted on a
    // thread of their own while the model is converted, written and synced
    // (a million cells: 0.15 s of formatting off the writing path).
    std::future<std::string> sidecar_cells;
    if (!o.no_sidecar) {
        try {
            sidecar_cells = std::async(std::launch::async, [&scene] { return sceneCellsJson(scene); });
        } catch (const std::system_error&) {
            // No thread to be had: they are formatted as the sidecar is written.
        }
    }
    writeModelFiles(o, made, tiles, summary);
    if (!o.preview.empty()) {
        timer.begin("drawing preview");
        writeRunPreview(o, field, scene, made, tiles, summary);
    }
    if (!o.scad.empty()) {
        timer.begin("writing OpenSCAD");
        writeScadFiles(o, so, scene, summary);
    }
    // The model file's stamp, for its sidecar and its keys (tiles and halves
    // are several files: none).
    std::optional<FileStamp> model_stamp;
    if (!o.output.empty() && !made.halves && !tiles) {
        model_stamp = written->stampOf(o.output);
        if (!model_stamp) model_stamp = stampFile(written->currentPath(o.output));
    }
    if (!o.no_sidecar) {
        const bool formatted = sidecar_cells.valid();
        const std::string cells = formatted ? sidecar_cells.get() : std::string();
        writeSidecarFile(o, scene, model_stamp, formatted ? &cells : nullptr, summary);
    }
    if (!o.no_key && (!o.output.empty() || !o.scad.empty())) {
        timer.begin("writing key");
        writeKeyFiles(o, field, scene, tiles, legibility, model_stamp, summary);
    }
    written->commit();
    written.reset();
    // Tiles an earlier run wrote under this name that this run did not:
    // left beside the new ones they would be printed with them.
    if (!o.output.empty())
        for (const std::string& stale : removeStaleTiles(o.output, tiles ? tilePaths(*tiles, o.output) : std::vector<std::string>()))
            summary.printer_notes.push_back("removed " + std::filesystem::path(stale).filename().string() +
                                            ", a tile of an earlier run under this name");
    std::optional<PrintCheckReport> printed;
    if (o.print_check) {
        timer.begin("print check");
        printed = printCheck(o);
    }
    timer.end();
    summary.timings_ms = timer.stagesMs();
    reportRun(o, summary, printed, json_out);
}

/// "pr.stl" -> "pr-band-03.stl" (the band zero-padded to `width` digits).
std::string bandPath(const std::string& path, int band, int width) {
    if (path.empty()) return path;
    std::filesystem::path p(path);
    std::string n = std::to_string(band);
    n.insert(0, size_t(std::max(0, width - int(n.size()))), '0');
    return (p.parent_path() / (p.stem().string() + "-band-" + n + p.extension().string())).string();
}

/// What a band stands for, short: its date when the file says one (a CF
/// time step), else "band N".
std::string bandLabel(const HexField& field, int band) {
    for (const ReadFact& f : field.input.facts)
        if (f.name == "band" && stepLabel(f.value) != f.value) return stepLabel(f.value);
    return "band " + std::to_string(band);
}

/// --band 1-12: one model per band, on one value scale (the same baseline,
/// value at full height and transfer), so pillars of two steps compare by
/// touch; each model's files carry its band (MODEL-band-03.stl), its legend
/// title and key name its step.
void runGenSeries(GenCommandOptions o) {
    if (o.output.empty() && o.scad.empty())
        throw InputError("nothing to write: give -o MODEL.stl|.3mf|.off|.obj and/or --scad MODEL.scad");
    if (!o.gen.points.empty()) throw InputError("--band is for rasters with several bands; a table of points has none");
    const std::vector<int> bands = o.gen.band_series;
    // The common scale: every band's values.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::vector<std::string> labels;
    for (int b : bands) {
        FieldLoadOptions one = o.gen;
        one.band = b;
        const HexField f = loadField(one);
        for (double v : f.values)
            if (std::isfinite(v)) {
                lo = std::min(lo, v);
                hi = std::max(hi, v);
            }
        labels.push_back(bandLabel(f, b));
    }
    if (!(lo <= hi)) throw InputError(o.gen.input, 0, 0, "--band: no band of the series has data");
    SceneParams& p = o.gen.scene;
    switch (p.baseline_mode) {
        case BaselineMode::Auto:
            if (lo < 0) p.baseline_value = lo, p.baseline_mode = BaselineMode::Value;
            else p.baseline_mode = BaselineMode::Zero;
            break;
        case BaselineMode::Min: p.baseline_value = lo, p.baseline_mode = BaselineMode::Value; break;
        default: break;
    }
    if (!p.value_max) p.value_max = hi;
    const int width = int(std::to_string(bands.back()).size());
    const std::string title = p.words.title;
    nlohmann::json series = nlohmann::json::array();
    for (size_t k = 0; k < bands.size(); ++k) {
        GenCommandOptions one = o;
        one.gen.band = bands[k];
        one.gen.band_series.clear();
        one.output = bandPath(o.output, bands[k], width);
        one.scad = bandPath(o.scad, bands[k], width);
        one.preview = bandPath(o.preview, bands[k], width);
        one.series_index = int(k) + 1;
        one.series_count = int(bands.size());
        // The legend names the step: where the title says {band}, else after it.
        if (const size_t at = title.find("{band}"); at != std::string::npos)
            one.gen.scene.words.title = title.substr(0, at) + labels[k] + title.substr(at + 6);
        else if (!title.empty())
            one.gen.scene.words.title = title + " " + labels[k];
        if (!o.json) std::cout << (k ? "\n" : "") << "band " << bands[k] << " (" << labels[k] << "), " << k + 1 << " of "
                               << bands.size() << "\n";
        nlohmann::json j;
        runGen(one, o.json ? &j : nullptr);
        if (o.json) series.push_back({{"band", bands[k]}, {"label", labels[k]}, {"model", std::move(j)}});
    }
    const double baseline = p.baseline_mode == BaselineMode::Zero ? 0.0 : p.baseline_value;
    if (o.json) {
        std::cout << nlohmann::json{{"series", series},
                                    {"common_scale",
                                     {{"baseline", baseline}, {"value_max", *p.value_max}, {"values_min", lo},
                                      {"values_max", hi}}}}
                         .dump(2)
                  << "\n";
    } else {
        std::cout << "\nseries    " << bands.size() << " models on one scale: " << formatSignificant(baseline) << " at the floor, "
                  << formatSignificant(*p.value_max) << " at full height (the values of every band run from "
                  << formatSignificant(lo) << " to " << formatSignificant(hi) << ")\n";
    }
}

}  // namespace

void addGenCommand(CLI::App& app) {
    auto opts = std::make_shared<GenCommandOptions>();
    CLI::App* cmd = app.add_subcommand("gen", "Generate a printable hex-pillar model from a field");
    cmd->footer(
        "Examples:\n"
        "  tsf gen examples/volcano.csv -o volcano.stl\n"
        "  tsf gen examples/airports-europe.csv --points x=lon,y=lat --bins 40 --mirror -o europe.3mf\n"
        "  tsf gen examples/airports-europe.csv --points x=lon,y=lat --bins 40 --title \"European airports\" \\\n"
        "      --units airports --parts --print-check -o airports.3mf\n"
        "Frame: x east, y north, z up, millimetres; the model stands on z = 0.");
    addGenOptions(cmd, opts->gen);
    cmd->add_option("-o,--output", opts->output, "Model file: .stl (binary), .3mf, .off or .obj");
    cmd->add_option("--scad", opts->scad, "Also write a parametric OpenSCAD file");
    cmd->add_flag("--ascii", opts->ascii, "Write ASCII STL instead of binary");
    cmd->add_option("--preview", opts->preview,
                    "Also draw the model to this PNG: framed to fill it, coloured by height, north arrow, scale bar "
                    "and size in mm; with --mirror the underside beside the top (drawn by tsf, no OpenSCAD needed)");
    cmd->add_flag("--no-verify", opts->no_verify, "Skip verifying the model before writing it");
    cmd->add_option("--about", opts->about,
                    "What the model shows, in your words, for the key's first paragraph (MODEL.key.txt and .brf; "
                    "the file's own description, long_name and units by default)");
    cmd->add_flag("--no-key", opts->no_key,
                  "Leave out the model's key (MODEL.key.txt for a screen reader, MODEL.key.brf for an embosser: what "
                  "the model shows, its values and heights, how to find north)");
    cmd->add_flag("--keep-unprintable", opts->keep_unprintable,
                  "Write the model even when its self-check finds walls thinner than the nozzle (they would not print)");
    cmd->add_flag("--verify-full", opts->verify_full,
                  "Run every check even on very large models (self-intersections, printability; minutes)");
    cmd->add_flag("--json", opts->json, "Print the summary as JSON");
    cmd->add_flag("--progress", opts->progress, "Print each stage and its time on stderr");
    cmd->add_flag("--no-scene", opts->no_sidecar, "Do not write the MODEL.scene.json sidecar");
    cmd->add_flag("--force", opts->force,
                  "Replace MODEL.json (parameter sets beside --scad) and MODEL.scene.json even when they exist "
                  "and were not written by tsf");
    cmd->add_option("--scad-strategy", opts->scad_strategy,
                    "polyhedron: one polyhedron() built from the values (fast, default) | csg: union of one prism "
                    "per cell (slow, tolerant of hand-added geometry); see docs/openscad.md")
        ->check(CLI::IsMember({"polyhedron", "csg"}))->capture_default_str();
    cmd->add_flag("--scad-library-beside", opts->scad_library_beside,
                  "Copy the OpenSCAD library into a folder beside the .scad instead of inlining it");
    auto* printer = "Printer (docs/printing.md)";
    cmd->add_option("--bed", opts->printer.bed,
                    "Bed WIDTHxDEPTH, mm: the model is fitted into it less 5 mm on each side (unless --width/--depth); "
                    "a larger model is refused (or cut into tiles: --tile)")
        ->group(printer);
    cmd->add_option("--nozzle", opts->printer.nozzle_mm,
                    "Nozzle diameter, mm: raster cells at least 4 nozzle widths; thin walls flagged")
        ->check(CLI::Range(0.05, 3.0))->group(printer);
    cmd->add_option("--layer", opts->printer.layer_mm,
                    "Layer height, mm (0.01 to 1): heights snap to whole layers (unless --snap)")
        ->check(CLI::Range(0.01, 1.0))->group(printer);
    cmd->add_flag("--tile", opts->printer.tile,
                  "With --bed: keep the model's size and cut it into tiles that each fit the bed, written as "
                  "MODEL-tile-ROW-COL.ext, joined by dovetail teeth, each with its place pitted into its underside; "
                  "each tile and the assembly verified (docs/printing.md)")
        ->group(printer);
    cmd->add_flag("--parts", opts->parts,
                  "Write the 3MF as one object made of parts - pillars (with the notch), marks (the raised "
                  "triangle), legend (the braille dots) - so a slicer can give each its own colour or material; "
                  "each part is verified alone and with the others (docs/printing.md)");
    cmd->add_option("--parts-layout", opts->parts_layout,
                    "How --parts lays the parts out in the 3MF: portable (each part a 3MF object with its own colour, "
                    "the components of one object: every 3MF reader sees the parts) | prusaslicer (one object whose "
                    "parts only PrusaSlicer's own config names: PrusaSlicer loads it as one object of parts without "
                    "asking)")
        ->check(CLI::IsMember({"portable", "prusaslicer"}))->capture_default_str();
    cmd->add_flag("--print-check", opts->print_check,
                  "After writing -o MODEL.stl|.3mf, slice it with PrusaSlicer as tsf print-check does (with --layer, "
                  "--nozzle, --bed when given) and add its report: supports?, layers, time, filament");
    cmd->callback([cmd, opts] {
        // The command line goes into the OpenSCAD header so a file says how it was made.
        opts->command_line = invocation();
        opts->given.width = cmd->get_option("--width")->count() > 0;
        opts->given.depth = cmd->get_option("--depth")->count() > 0;
        opts->given.snap = cmd->get_option("--snap")->count() > 0;
        opts->given.max_slope = cmd->get_option("--max-slope")->count() > 0;
        // A series keeps one value scale: its heights and transfer are never changed band by band.
        const bool series = !opts->gen.band_series.empty();
        opts->legibility_given.height = series || cmd->get_option("--height")->count() > 0;
        opts->legibility_given.transfer = series || cmd->get_option("--transfer")->count() > 0;
        opts->legibility_given.cell = series || cmd->get_option("--cell")->count() > 0 ||
                                      cmd->get_option("--bins")->count() > 0 || cmd->get_option("--bin")->count() > 0;
        // The pieces are not the model the sidecar describes: none is written for them.
        if (opts->gen.scene.halves || opts->printer.tile) opts->no_sidecar = true;
        if (!opts->gen.band_series.empty()) runGenSeries(*opts);
        else runGen(*opts);
    });
}

void addInfoCommand(CLI::App& app) {
    auto opts = std::make_shared<GenOptions>();
    auto json = std::make_shared<bool>(false);
    CLI::App* cmd = app.add_subcommand("info", "Show what tsf sees in an input file and the model it would make");
    addGenOptions(cmd, *opts);
    cmd->add_flag("--json", *json, "Print as JSON");
    cmd->callback([opts, json] {
        refuseBandSeries(*opts, "info");
        const HexField field = loadField(*opts);
        const Scene scene = buildScene(field, opts->scene);
        if (*json) {
            nlohmann::json j = sceneFactsJson(scene);
            j["input"] = opts->input;
            j["read"] = fieldInputJson(field.input);
            j["field"] = {{"how", field.how}, {"pitch_data_units", field.pitch_data}};
            std::cout << j.dump(2) << "\n";
        } else {
            std::cout << "tsf info: " << opts->input << "\n"
                      << formatFieldInput(field.input) << "  input     " << field.how << "\n"
                      << formatSceneFacts(scene);
        }
    });
}

}  // namespace tsf::cli
