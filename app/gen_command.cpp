// tsf gen: field in, model out (mesh file, OpenSCAD, scene sidecar), verified.
#include <cctype>
#include <cmath>
#include <limits>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>

#include "app/bed_size.h"
#include "app/commands.h"
#include "app/gen_options.h"
#include "app/gen_summary.h"
#include "app/ground_scale.h"
#include "app/halves_output.h"
#include "app/tiles_output.h"
#include "app/input_report.h"
#include "app/legible_defaults.h"
#include "app/key_stamp.h"
#include "app/stage_timer.h"
#include "app/preview.h"
#include "app/printer_fit.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/util/error.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh_io/three_mf_writer.h"
#include "gen/mesh/scene_parts.h"
#include "gen/scad/scad_emitter.h"
#include "gen/scad/scad_render_cost.h"
#include "gen/model/scene_json.h"
#include "pipeline/verified_model.h"
#include "gen/key/braille_ready_file.h"
#include "gen/key/model_key.h"
#include "gen/key/spoken_text.h"
#include "gen/readers/cf_time.h"
#include "gen/util/atomic_file.h"
#include "gen/util/file_bytes.h"
#include "gen/util/file_stamp.h"
#include "gen/util/number_format.h"
#include "gen/util/output_paths.h"
#include "runners/prusa_slicer/print_check.h"
#include "verify/verify_model.h"
#include "verify/verify_parts.h"
#include "gen/model/attachments.h"
#include "gen/model/build_scene.h"

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
    bool no_sidecar = false;
    bool no_key = false;  ///< --no-key: no MODEL.key.txt and MODEL.key.brf
    std::string scad_strategy = "polyhedron";
    bool scad_library_beside = false;
    std::string command_line;
    std::string preview;
    bool verify_full = false;
    bool keep_unprintable = false;  ///< write a model whose walls are thinner than the nozzle
    bool force = false;
    PrinterSpec printer;  ///< --bed, --nozzle, --layer (printer_fit.h)
    bool parts = false;        ///< --parts: the 3MF as one object with a part per feature
    std::string parts_layout = "portable";  ///< --parts-layout: portable | prusaslicer
    bool print_check = false;  ///< --print-check: slice the written model with PrusaSlicer
    GivenOptions given;   ///< model options the user gave himself
    LegibilityGiven legibility_given;  ///< what defaults that pass may not change (app/legible_defaults.h)
    std::string about;    ///< --about: what the model shows, in the maker's words (the key's first paragraph)
    int series_index = 0, series_count = 0;  ///< --band A-B: this model's place in the series (1-based; 0: none)
};

// Largest existing parameter-set file read to decide whether tsf wrote it
// (tsf writes a few KB).
constexpr int64_t kMaxOwnFileBytes = 64 << 20;
// A scene sidecar is told by the head alone: it grows with the grid (71 MiB
// at 1000 x 1000), and its "format" key comes among the first top-level keys
// (written in sorted order, before "hull", "marks" and the cells).
constexpr size_t kSceneHeadBytes = 64 << 10;

std::string sidecarPath(const GenCommandOptions& o) { return (o.output.empty() ? o.scad : o.output) + ".scene.json"; }

/// The model's key beside it: MODEL.key.txt and MODEL.key.brf for MODEL.stl
/// (or the .scad when no model file is written).
std::pair<std::string, std::string> keyPaths(const GenCommandOptions& o) {
    std::filesystem::path base(o.output.empty() ? o.scad : o.output);
    base.replace_extension();
    return {base.string() + ".key.txt", base.string() + ".key.brf"};
}

/// A .brf tsf wrote: Braille ASCII only (and CR, LF, form feeds), beside a
/// key text tsf wrote.
bool isTsfKeyBrf(const std::string& brf_path) {
    std::filesystem::path text(brf_path);
    text.replace_extension(".txt");
    std::error_code ec;
    if (!std::filesystem::exists(text, ec) || !isTsfModelKey(readFileHead(text.string(), 64))) return false;
    for (const char c : readFileBytes(brf_path, kMaxOwnFileBytes))
        if (!((c >= 0x20 && c <= 0x5F) || c == '\r' || c == '\n' || c == '\f')) return false;
    return true;
}

ScadOptions scadOptions(const GenCommandOptions& o) {
    ScadOptions so;
    parseScadStrategy(o.scad_strategy, so.strategy);
    so.inline_library = !o.scad_library_beside;
    // The file name only: a shared .scad must not carry the folders it was made in.
    so.source = std::filesystem::path(o.gen.input).filename().string();
    so.command = o.command_line;
    return so;
}

// A file tsf names itself (not given on the command line) that exists and
// was not written by tsf is refused unless --force.
// head_bytes > 0: only that many bytes are read and judged.
void refuseForeignFile(const std::string& path, bool (*ours)(const std::string&), const std::string& what,
                       const std::string& alternative, size_t head_bytes = 0) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec)) return;
    if (ours(head_bytes > 0 ? readFileHead(path, head_bytes) : readFileBytes(path, kMaxOwnFileBytes))) return;
    throw InputError(path, 0, 0,
                     "exists and was not written by tsf; it would be replaced by " + what +
                         ". Give --force to replace it, or " + alternative);
}

bool isTsfScene(const std::string& text) {
    return text.find("\"" + std::string(kSceneJsonFormat) + "\"") != std::string::npos;
}

// No output may be the input or another output, and files the user did not
// name (the parameter sets beside --scad, the scene sidecar) replace only
// what tsf wrote before, unless --force.
void checkOutputs(const GenCommandOptions& o, const ScadOptions& so) {
    std::vector<NamedPath> outputs;
    if (o.gen.scene.halves && !o.output.empty()) {
        const HalvesPaths h = halvesPaths(o.output);
        outputs.push_back({h.upper, "the upper half of -o"});
        outputs.push_back({h.lower, "the lower half of -o"});
        outputs.push_back({h.pins, "the pins of -o"});
    } else {
        outputs.push_back({o.output, "-o"});
    }
    outputs.push_back({o.preview, "--preview"});
    const std::vector<std::string> scad_paths = o.scad.empty() ? std::vector<std::string>() : scadOutputPaths(so, o.scad);
    if (!o.scad.empty()) outputs.push_back({o.scad, "--scad"});
    if (so.write_parameter_sets && !o.scad.empty())
        outputs.push_back({scad_paths[1], "the OpenSCAD parameter sets written beside --scad"});
    if (!o.no_sidecar) outputs.push_back({sidecarPath(o), "the scene sidecar (--no-scene leaves it out)"});
    if (!o.no_key) {
        outputs.push_back({keyPaths(o).first, "the model's key (--no-key leaves it out)"});
        outputs.push_back({keyPaths(o).second, "the model's braille key (--no-key leaves it out)"});
    }
    std::vector<NamedPath> inputs = {{o.gen.input, "the input"}};
    if (!o.gen.class_names.empty()) inputs.push_back({o.gen.class_names, "--class-names"});
    checkOutputPaths(inputs, outputs);
    if (o.force) return;
    if (so.write_parameter_sets && !o.scad.empty())
        refuseForeignFile(scad_paths[1], isTsfParameterSetFile, "the OpenSCAD parameter sets of --scad " + o.scad,
                          "choose another --scad name");
    if (!o.no_sidecar)
        refuseForeignFile(sidecarPath(o), isTsfScene, "the scene sidecar", "give --no-scene", kSceneHeadBytes);
    if (!o.no_key) {
        refuseForeignFile(keyPaths(o).first, isTsfModelKey, "the model's key", "give --no-key");
        std::error_code ec;
        if (std::filesystem::exists(keyPaths(o).second, ec) && !isTsfKeyBrf(keyPaths(o).second))
            throw InputError(keyPaths(o).second, 0, 0,
                             "exists and was not written by tsf; it would be replaced by the model's braille key. Give "
                             "--force to replace it, or give --no-key");
    }
}

// Grids above this many cells print progress lines without being asked.
constexpr int64_t kProgressCells = 250000;
// Input files above this size say so before they are read (seconds of work).
constexpr int64_t kProgressInputBytes = int64_t(64) << 20;

void announceLargeInput(const std::string& input, bool progress) {
    std::error_code ec;
    const auto bytes = std::filesystem::file_size(input, ec);
    if (ec || progress || int64_t(bytes) < kProgressInputBytes) return;
    std::fprintf(stderr, "tsf: reading %s (%lld MiB), this may take a while\n", input.c_str(),
                 static_cast<long long>(bytes >> 20));
}

/// The names of the checks passed, for the summary's details.
std::string passedChecksLine(const VerifyReport& r) {
    std::string passed;
    for (const Check& c : r.checks)
        if (c.status == CheckStatus::Pass) passed += (passed.empty() ? "" : ", ") + c.title;
    return passed.empty() ? "" : "  checks    passed: " + passed + "\n";
}

/// The verifier's verdict, its read-back and every check not passed.
std::string verifyLines(const VerifyReport& r) {
    std::string other;
    int passed = 0, failed = 0, warned = 0;
    for (const Check& c : r.checks) {
        if (c.status == CheckStatus::Pass) ++passed;
        else if (c.status != CheckStatus::Skipped) {
            (c.status == CheckStatus::Fail ? failed : warned) += 1;
            other += "  " + std::string(toString(c.status)) + "      " + c.title + (c.note.empty() ? "" : ": " + c.note) + "\n";
        }
    }
    std::string out = "  verify    " + std::string(r.passed() ? "passed" : "FAILED") + ": " + std::to_string(passed) +
                      " checks passed" + (failed ? ", " + std::to_string(failed) + " failed" : "") +
                      (warned ? ", " + std::to_string(warned) + (warned == 1 ? " warning" : " warnings") : "") + "\n";
    if (r.readback) {
        char buf[160];
        std::snprintf(buf, sizeof buf, "  read back %zu cells: heights within %.4f mm of the data (max error %.4f mm)\n",
                      r.readback->cells_checked, r.readback->tolerance_mm, r.readback->max_error_mm);
        out += buf;
    }
    return out + other;
}

/// A model whose walls are thinner than the nozzle does not print as
/// written (the slicer leaves them out): refused, nothing written, unless
/// --keep-unprintable. An InputError (exit 2): the options made it (cells or
/// a model too small for the nozzle).
void refuseUnprintable(const VerifyReport& r, double nozzle_mm, double layer_mm, bool tilted) {
    const Check* walls = r.find("wall_thickness");
    if (!walls || walls->status == CheckStatus::Pass || walls->status == CheckStatus::Skipped) return;
    std::string where;
    for (size_t k = 0; k < walls->worst.size() && k < 3; ++k) {
        const Offender& w = walls->worst[k];
        where += (k ? "; " : "") + formatSignificant(w.amount, 3) + " mm at (" + formatSignificant(w.at_mm.x, 4) + ", " +
                 formatSignificant(w.at_mm.y, 4) + ", " + formatSignificant(w.at_mm.z, 4) + ") mm";
    }
    throw InputError("the model has " + std::to_string(walls->count) + " walls thinner than the " +
                     formatSignificant(nozzle_mm, 3) + " mm nozzle, which would not print (" + where +
                     "); nothing was written. " +
                     (tilted ? "Give tilted tops a gentler --max-slope (at most " +
                                   formatSignificant(std::floor(maxSlopeDegFor(nozzle_mm, layer_mm) * 10) / 10, 3) +
                                   " degrees for this nozzle and " + formatSignificant(layer_mm, 3) + " mm layers), "
                             : std::string()) +
                     "make the cells larger (--cell, --width), give your printer's --nozzle, or --keep-unprintable "
                     "to write it anyway");
}

// One line per part for the summary: its triangles, pieces and volume; then the assembly's verdict.
std::string partsLines(const PartsVerifyReport& r) {
    std::string out;
    for (const PartReport& p : r.parts) {
        char buf[200];
        std::snprintf(buf, sizeof buf, "  part      %-8s %zu triangles, %zu %s, %.1f mm^3: %s\n", p.name.c_str(),
                      p.report.mesh.triangle_count, p.report.mesh.component_count,
                      p.report.mesh.component_count == 1 ? "piece" : "pieces", p.report.mesh.volume_mm3,
                      p.report.passed() ? "closed solid" : "FAILED");
        out += buf;
    }
    const Check* overlap = r.assembly.find("parts_overlap");
    out += "  parts     " + std::string(r.passed() ? "passed" : "FAILED") + " (each a closed solid; " +
           (overlap && overlap->status == CheckStatus::Pass ? "they touch and never overlap" : "overlap not proven absent") +
           ")\n";
    return out;
}

// The written model sliced by PrusaSlicer with the printer options given (else PrusaSlicer's defaults).
PrintCheckReport printCheck(const GenCommandOptions& o) {
    SlicerSettings s;
    if (o.printer.layer_mm > 0) s.layer_mm = o.printer.layer_mm;
    if (o.printer.nozzle_mm > 0) s.nozzle_mm = o.printer.nozzle_mm;
    if (!o.printer.bed.empty()) {
        const BedSize bed = parseBedSize(o.printer.bed, "--bed", /*need_height=*/false);
        s.bed_width_mm = bed.width_mm;
        s.bed_depth_mm = bed.depth_mm;
    }
    try {
        return runPrintCheck(o.output, s);
    } catch (const SlicerError& e) {
        std::cerr << "tsf: error: the model was written, but the print check failed: " << e.what() << "\n";
        throw CLI::RuntimeError(kExitToolFailed);
    }
}

// A model (or piece) that fails its own checks is a bug in tsf: never hand
// it to a printer. Prints the report and ends with kExitCheckFailed.
[[noreturn]] void refuseUnverified(const ModelVerificationFailed& e, StageTimer& timer) {
    timer.end();
    std::cerr << e.report();
    std::cerr << "tsf: the " << e.piece() << " failed verification; nothing was written. "
                 "Please report this with the input file.\n";
    throw CLI::RuntimeError(kExitCheckFailed);
}

void runGen(GenCommandOptions o, nlohmann::json* json_out = nullptr) {
    if (o.output.empty() && o.scad.empty())
        throw InputError("nothing to write: give -o MODEL.stl|.3mf|.off|.obj and/or --scad MODEL.scad");
    const ScadOptions so = scadOptions(o);
    checkOutputs(o, so);
    const std::string model_ext = o.output.empty() ? "" : lowerCaseExtension(o.output);
    if (o.parts && model_ext != ".3mf")
        throw InputError(o.output.empty() ? "--parts" : o.output, 0, 0,
                         "--parts writes a 3MF (one object, a part per feature): give -o MODEL.3mf; "
                         "STL, OFF and OBJ hold one solid");
    if (o.parts_layout != "portable" && !o.parts)
        throw InputError("--parts-layout", 0, 0, "--parts-layout lays out the parts of --parts: add --parts");
    if (o.gen.scene.halves && (o.parts || o.print_check))
        throw InputError(o.parts ? "--parts" : "--print-check", 0, 0,
                         "--halves writes each piece to a file of its own (MODEL-upper, MODEL-lower, MODEL-pins); "
                         "leave out --parts and --print-check and run tsf print-check on each piece");
    if (o.printer.tile) {
        if (o.printer.bed.empty())
            throw InputError("--tile", 0, 0, "--tile cuts the model into tiles that fit the bed: give --bed WIDTHxDEPTH");
        if (o.output.empty())
            throw InputError("--tile", 0, 0, "--tile writes each tile to a file of its own: give -o MODEL.stl|.3mf|.off|.obj");
        const char* other = o.parts ? "--parts" : o.print_check ? "--print-check" : !o.scad.empty() ? "--scad" : nullptr;
        if (other)
            throw InputError(other, 0, 0,
                             std::string("--tile writes each tile to a file of its own (MODEL-tile-ROW-COL); leave out ") + other +
                                 (o.print_check ? " and run tsf print-check on the tiles (it sums their time and filament)"
                                                : ": the tiles are not drawn in OpenSCAD or as parts yet"));
        if (o.gen.scene.halves || o.gen.scene.bottom == Bottom::Mirrored)
            throw InputError(o.gen.scene.halves ? "--halves" : "--mirror", 0, 0,
                             "--tile cuts a flat model: leave out --mirror and --halves");
    }
    if (o.print_check && model_ext != ".stl" && model_ext != ".3mf")
        throw InputError(o.output.empty() ? "--print-check" : o.output, 0, 0,
                         "--print-check slices the model file: give -o MODEL.stl or -o MODEL.3mf");
    if (!o.preview.empty() && lowerCaseExtension(o.preview) != ".png")
        throw InputError(o.preview, 0, 0, "--preview writes a PNG picture: give a name ending in .png");
    StageTimer timer(o.progress);
    GenSummary summary;
    summary.input = o.gen.input;
    summary.printer_notes = applyPrinterFit(o.printer, o.given, o.gen);

    timer.begin("reading");
    announceLargeInput(o.gen.input, o.progress);
    HexField field = loadField(o.gen);
    summary.field = &field;
    if (field.grid.cellCount() > kProgressCells && !o.progress && !o.json)
        std::fprintf(stderr, "tsf: %d x %d cells, this may take a few seconds\n", field.grid.cols, field.grid.rows);
    // A legend's units line takes the file's own units unless --units says otherwise.
    LegendRequest& legend = o.gen.scene.legend;
    if (!legend.title.empty() && legend.units.empty() && !field.input.units.empty()) {
        legend.units = field.input.units;
        summary.printer_notes.push_back("the legend's units are the file's: " + legend.units + " (--units to say otherwise)");
    }
    timer.begin("scene");
    // STL and 3MF store float32: the z grid must be one float32 resolves.
    o.gen.scene.stored_as_float32 = model_ext == ".stl" || model_ext == ".3mf";
    Scene scene = buildScene(field, o.gen.scene);
    // What stands beside the pillars does not shrink with them: fit again
    // (a culled outline can need a second step).
    // The field is read again for the smaller box: a raster resampled to fit
    // it keeps cells a fingertip tells apart (fewer of them), never narrower.
    for (int again = 0; again < 6 && shrinkFitToBed(scene, o.printer, o.gen); ++again) {
        field = loadField(o.gen);
        scene = buildScene(field, o.gen.scene);
    }
    summary.scene = &scene;
    if (const std::string note = cellNozzleNote(scene.pitch_mm, o.printer); !note.empty())
        summary.printer_notes.push_back(note);
    ModelRequest rq;
    rq.verify = !o.no_verify;
    rq.verify_full = o.verify_full;
    rq.parts = o.parts;
    rq.stored_as_float32 = o.gen.scene.stored_as_float32;
    rq.verify_options.name = o.output.empty() ? o.scad : o.output;
    if (o.printer.nozzle_mm > 0) rq.verify_options.nozzle_mm = o.printer.nozzle_mm;
    if (o.printer.layer_mm > 0) rq.verify_options.layer_mm = o.printer.layer_mm;
    rq.on_mesh = [&](const Mesh& mesh) {
        if (!o.printer.tile)
            checkFitsBed(mesh, scene, o.printer, o.gen.cell_mm > 0, o.gen.min_cell_mm, [&](double cell_mm) -> std::optional<std::pair<double, double>> {
                // The model made again at that cell: the field (a raster is
                // resampled for its cell) and the Scene, as asked otherwise.
                GenOptions at = o.gen;
                at.cell_mm = at.scene.pitch_mm = cell_mm;
                try {
                    const BoxMm f = sceneFootprint(buildScene(loadField(at), at.scene));
                    return std::make_pair(f.x1 - f.x0, f.y1 - f.y0);
                } catch (const InputError&) {
                    return std::nullopt;
                }
            });
        if (rq.verify && !rq.verify_full && mesh.triangleCount() > kQuickVerifyTriangles)
            std::fprintf(stderr, "tsf: %zu triangles: verifying topology and heights only (--verify-full for all checks)\n",
                         mesh.triangleCount());
    };
    VerifiedModel made;
    try {
        made = makeVerifiedModel(scene, rq, [&](const std::string& stage) { timer.begin(stage.c_str()); });
    } catch (const ModelVerificationFailed& e) {
        refuseUnverified(e, timer);
    }
    // Defaults that pass: a model made from tsf's defaults that fails a
    // legibility check is made again with what the user left to tsf
    // (app/legible_defaults.h); the summary says what changed and why.
    std::string legibility_key;
    std::string legibility_change;  // what the search changed, for the key's last section
    if (made.report) {
        const std::vector<std::string> failed = failedLegibility(*made.report);
        if (!failed.empty()) {
            timer.begin("legibility");
            const LegibleDefaults ld = legibleDefaults(
                field, scene, failed, o.legibility_given, rq.verify_options, [&](int bins) -> std::optional<HexField> {
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
                legibility_change = ld.key_note;
                try {
                    made = makeVerifiedModel(scene, rq, [&](const std::string& stage) { timer.begin(stage.c_str()); });
                } catch (const ModelVerificationFailed& e) {
                    refuseUnverified(e, timer);
                }
            }
            if (!failedLegibility(*made.report).empty() && ld.json.is_object() && ld.json.contains("key")) {
                legibility_key = "Where the model may not read well:";
                for (const auto& why : ld.json["key"])
                    legibility_key += " " + why.get<std::string>() + ".";
            }
        }
    }
    std::optional<VerifiedTiles> tiles;
    if (o.printer.tile) {
        const BedSize bed = parseBedSize(o.printer.bed, "--bed", /*need_height=*/false);
        ModelRequest trq = rq;
        trq.on_mesh = nullptr;
        try {
            tiles = makeVerifiedTiles(field, scene, bed.width_mm - 2 * kBedMarginMm, bed.depth_mm - 2 * kBedMarginMm,
                                      trq, [&](const std::string& stage) { timer.begin(stage.c_str()); });
        } catch (const ModelVerificationFailed& e) {
            refuseUnverified(e, timer);
        }
        if (tiles->tiles.size() == 1) {
            // It fits the bed as it is: one piece, as without --tile.
            summary.printer_notes.push_back("the model fits the bed: written in one piece, not tiled");
            tiles.reset();
        }
        for (const VerifiedTile& t : tiles ? tiles->tiles : std::vector<VerifiedTile>())
            if (tilePath(o.output, t.scene.tile->place) == o.gen.input)
                throw InputError(o.output, 0, 0, "a tile would be written over the input: give another -o");
        if (tiles) summarizeTiles(*tiles, summary);
    }
    const Mesh& mesh = made.mesh;
    summary.mesh = &mesh;
    if (made.report && !o.keep_unprintable)
        refuseUnprintable(*made.report, rq.verify_options.nozzle_mm, rq.verify_options.layer_mm,
                          scene.shapes.cells_tilted > 0);
    if (made.report) {
        summary.verify = toJson(*made.report);
        summary.verify_text = verifyLines(*made.report);
        summary.checks_text = passedChecksLine(*made.report);
        if (!scene.halves) summary.supports_text = supportsText(*made.report);
    }
    const std::vector<MeshPart>& parts = made.parts;
    if (made.parts_report) {
        summary.verify["parts"] = toJson(*made.parts_report);
        summary.verify_text += partsLines(*made.parts_report);
    }
    const std::optional<VerifiedHalves>& halves = made.halves;
    if (halves) summarizeHalves(*halves, summary);
    // Every file of this run is written to a temporary file first and all
    // are renamed together at the end (a signal then leaves the old files
    // or the new ones, never a mix).
    std::optional<OutputSet> written(std::in_place);
    if (!o.output.empty()) {
        timer.begin("writing");
        MeshWriteOptions wo;
        wo.ascii_stl = o.ascii;
        // The input's file name only: a shared model must not carry the folders
        // of the machine it was made on.
        wo.title = "tsf " TSF_VERSION " " + std::filesystem::path(o.gen.input).filename().string();
        if (halves) {
            writeHalves(*halves, o.output, wo, summary);
        } else if (tiles) {
            writeTiles(*tiles, o.output, wo, summary);
        } else if (o.parts) {
            wo.parts_layout = o.parts_layout == "prusaslicer" ? MeshWriteOptions::PartsLayout::PrusaSlicer
                                                              : MeshWriteOptions::PartsLayout::Portable;
            write3mfParts(parts, o.output, wo);
            std::string names;
            for (const MeshPart& p : parts) names += (names.empty() ? "" : ", ") + p.name;
            summary.outputs.push_back({o.output, "model, one object in " + std::to_string(parts.size()) + " parts: " + names});
        } else {
            writeMesh(mesh, o.output, wo);
            summary.outputs.push_back({o.output, "model"});
        }
    }
    if (!o.preview.empty()) {
        timer.begin("drawing preview");
        // A series' pictures share one colour scale: from the bed to the
        // top of the common height scale (the same height, the same colour).
        const double colour_top = o.series_count > 1 ? scene.zMm(scene.floor_units) + scene.mapping.max_height_mm : 0.0;
        auto piece = [](const Mesh& m) {
            const Bounds b = meshBounds(m);
            return formatFixed(b.max.x - b.min.x, 0) + " x " + formatFixed(b.max.y - b.min.y, 0) + " x " +
                   formatFixed(b.max.z - b.min.z, 0);
        };
        if (halves) {
            writeModelPreview(halvesSideBySide(*halves), o.preview, false, colour_top,
                              "upper half " + piece(halves->upper) + ", lower " + piece(halves->lower) + " mm");
        } else if (tiles) {
            double w = 0, d = 0, h = 0;
            for (const auto& t : tiles->tiles) {
                const Bounds b = meshBounds(t.model.mesh);
                w = std::max(w, b.max.x - b.min.x), d = std::max(d, b.max.y - b.min.y), h = std::max(h, b.max.z - b.min.z);
            }
            writeModelPreview(tilesApart(*tiles), o.preview, false, colour_top,
                              std::to_string(tiles->tiles.size()) + " tiles, each at most " + formatFixed(w, 0) + " x " +
                                  formatFixed(d, 0) + " x " + formatFixed(h, 0) + " mm");
        } else {
            writeModelPreview(mesh, o.preview, scene.params.bottom == Bottom::Mirrored, colour_top, "", 1200, 800,
                              field.input.categorical ? &scene : nullptr);
        }
        summary.outputs.push_back({o.preview, halves ? "preview picture of the pieces as they print"
                                              : tiles ? "preview picture of the tiles, drawn apart"
                                              : o.series_count > 1 ? "preview picture, coloured on the series' one height scale"
                                                      : "preview picture"});
    }
    if (!o.scad.empty()) {
        timer.begin("writing OpenSCAD");
        writeScad(scene, so, o.scad);
        const std::string slow = scadRenderWarning(estimateScadRender(scene, so.strategy), o.scad);
        if (!slow.empty()) std::fprintf(stderr, "tsf: warning: %s\n", slow.c_str());
        const std::vector<std::string> paths = scadOutputPaths(so, o.scad);
        for (size_t k = 0; k < paths.size(); ++k)
            summary.outputs.push_back({paths[k], k == 0 ? "OpenSCAD"
                                                 : so.write_parameter_sets && k == 1 ? "OpenSCAD parameter sets, openscad -p"
                                                                                     : "OpenSCAD library"});
    }
    // The model file's stamp, for its sidecar and its keys (tiles and halves
    // are several files: none).
    std::optional<FileStamp> model_stamp;
    if (!o.output.empty() && !halves && !tiles) model_stamp = stampFile(written->currentPath(o.output));
    if (!o.no_sidecar) {
        // The scene sidecar lets `tsf verify --scene` check any mesh of this
        // model later. It is committed after the model and names the model
        // file's size and hash: a run killed between the two leaves a new
        // model beside an older sidecar, and `tsf verify --scene` refuses
        // that pair instead of judging one model by another's data.
        const std::string sidecar = sidecarPath(o);
        std::optional<SceneModelRecord> model;
        if (model_stamp) model = SceneModelRecord{std::filesystem::path(o.output).filename().string(), *model_stamp};
        writeSceneJson(scene, sidecar, model ? &*model : nullptr);
        summary.outputs.push_back({sidecar, "scene for tsf verify --scene"});
    }
    if (!o.no_key && (!o.output.empty() || !o.scad.empty())) {
        // The key for a reader: what the model shows, its values and
        // heights, how to find north, in words and in braille.
        timer.begin("writing key");
        ModelKeyFacts facts;
        facts.input_name = std::filesystem::path(o.gen.input).filename().string();
        facts.field_how = spokenText(field.how);
        facts.version = TSF_VERSION;
        facts.about = o.about;
        facts.description = field.input.description;
        facts.variable = field.input.variable;
        facts.step = field.input.step;
        facts.units = field.input.units;
        facts.per_hexagon = field.per_hexagon;
        facts.points = field.input.kind == "points";
        if (!facts.points) facts.data_min = field.input.min, facts.data_max = field.input.max;
        for (int32_t r = 0; r < field.grid.rows; ++r)
            for (int32_t c = 0; c < field.grid.cols; ++c)
                if (!std::isfinite(field.at(c, r)) && scene.keptAt(c, r) < 0) facts.left_out_nodata.push_back({c, r});
        facts.series_index = o.series_index;
        facts.series_count = o.series_count;
        // What was read, for the last section (the band list and class
        // names are said elsewhere or are too long for a key).
        for (const ReadFact& f : field.input.facts)
            if (!f.name.empty() && f.name != "bands" && f.name != "class names")
                facts.read_facts.push_back(std::string(1, char(std::toupper(static_cast<unsigned char>(f.name[0])))) +
                                           f.name.substr(1) + ": " + f.value);
        facts.categorical = field.input.categorical;
        facts.legibility = legibility_key;
        if (!legibility_change.empty()) facts.made_notes.push_back(legibility_change);
        facts.class_names = field.input.classes;
        facts.class_order = field.input.class_order;
        if (const auto g = groundScale(scene, field)) facts.ground = groundSentence(*g);
        if (tiles)
            facts.assembly = "The model prints in " + std::to_string(tiles->tiles.size()) + " tiles, in " +
                             std::to_string(tiles->layout.rows) + " rows from north to south and " +
                             std::to_string(tiles->layout.cols) +
                             " columns from west to east. Along most edges between tiles, teeth of one tile lock into "
                             "the next when it is lowered onto them from above. "
                             "Under each tile, pits form an L: a corner pit, then one pit for each column number "
                             "going east, and one for each row number going south. " + tilesMarksSentence(*tiles);
        const std::vector<std::string> key = modelKeyParagraphs(scene, facts);
        const auto [text_path, brf_path] = keyPaths(o);
        // The model's stamp ends each key, after all a reader reads (key_stamp.h).
        const std::string stamp = model_stamp ? keyStampLine(std::filesystem::path(o.output).filename().string(), *model_stamp)
                                              : std::string();
        writeFileAtomically(text_path, [&](std::ostream& out) {
            out << modelKeyText(key);
            if (!stamp.empty()) out << "\n" << stamp << "\n";
        });
        std::string brf = brailleReadyFile(key, scene.params.legend.table);
        if (!stamp.empty()) {
            std::string line = stamp;
            // Braille ASCII is 0x20 to 0x5F: capitals; anything else of a file name a '?'.
            for (char& c : line) {
                c = char(std::toupper(static_cast<unsigned char>(c)));
                if (c < 0x20 || c > 0x5F) c = '?';
            }
            brf += line + "\r\n\f";
        }
        writeFileAtomically(brf_path, [&](std::ostream& out) { out << brf; });
        summary.outputs.push_back({text_path, "key in plain text for a screen reader"});
        summary.outputs.push_back({brf_path, "key in braille for an embosser: BRF 40 by 25 in " + scene.params.legend.table});
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
    if (o.json) {
        nlohmann::json j = summaryJson(summary);
        if (printed) j["print_check"] = toJson(*printed);
        if (json_out) *json_out = std::move(j);
        else std::cout << j.dump(2) << "\n";
    } else {
        std::cout << formatSummary(summary);
        if (printed) std::cout << "\n" << formatPrintCheck(*printed);
    }
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
    const std::string title = p.legend.title;
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
            one.gen.scene.legend.title = title.substr(0, at) + labels[k] + title.substr(at + 6);
        else if (!title.empty())
            one.gen.scene.legend.title = title + " " + labels[k];
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
