// tsf print-check: slice a model with PrusaSlicer's command line and report
// what a printer would make of it. See runners/prusa_slicer/print_check.h and
// docs/printing.md.
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "app/bed_size.h"
#include "app/commands.h"
#include "runners/prusa_slicer/print_check.h"

namespace tsf::cli {
namespace {

struct PrintCheckOptions {
    std::vector<std::string> models;
    SlicerSettings slicer;
    std::string bed;
    bool json = false;
};

void runPrintCheckCommand(const PrintCheckOptions& o) {
    SlicerSettings s = o.slicer;
    if (!o.bed.empty()) {
        const BedSize bed = parseBedSize(o.bed, "--bed", /*need_height=*/false);
        s.bed_width_mm = bed.width_mm;
        s.bed_depth_mm = bed.depth_mm;
    }
    std::vector<PrintCheckReport> reports;
    try {
        for (const std::string& model : o.models) reports.push_back(runPrintCheck(model, s));
    } catch (const SlicerError& e) {
        std::cerr << "tsf: error: " << e.what() << "\n";
        throw CLI::RuntimeError(kExitToolFailed);
    }
    if (reports.size() == 1) {
        if (o.json) std::cout << toJson(reports[0]).dump(2) << "\n";
        else std::cout << formatPrintCheck(reports[0]);
    } else {
        // The pieces of one model (tiles, halves and pins): each, and the sum.
        const PrintCheckTotal total = sumPrintChecks(reports);
        if (o.json) {
            nlohmann::json pieces = nlohmann::json::array();
            for (const PrintCheckReport& r : reports) pieces.push_back(toJson(r));
            std::cout << nlohmann::json{{"pieces", pieces}, {"total", toJson(total)}}.dump(2) << "\n";
        } else {
            for (const PrintCheckReport& r : reports) std::cout << formatPrintCheck(r);
            std::cout << formatPrintCheckTotal(total);
        }
    }
    std::cout.flush();
}

}  // namespace

void addPrintCheckCommand(CLI::App& app) {
    auto opts = std::make_shared<PrintCheckOptions>();
    CLI::App* cmd = app.add_subcommand("print-check", "Slice a model with PrusaSlicer (headless): repair needed?, "
                                                      "supports needed?, layers, print time, filament");
    cmd->footer(
        "PrusaSlicer's built-in profile is used, changed only by the options below; the first layer is as\n"
        "high as the others. The model is sliced twice, without and with automatic supports: supports are\n"
        "needed when the second slicing extrudes support material.\n"
        "Examples:\n"
        "  tsf print-check model.stl\n"
        "  tsf print-check model.3mf --layer 0.1 --nozzle 0.6 --bed 250x210 --json\n"
        "  tsf print-check europe-tile-*.stl           # each tile, and the sum\n"
        "Exit codes: 0 the report was made (read it: it does not judge), 2 bad input (unreadable model,\n"
        "larger than the bed, bad option), 3 PrusaSlicer is missing or failed.");
    cmd->add_option("models", opts->models,
                    "Model to slice: STL or 3MF (mm); several (the tiles of --tile, the halves and pins of --halves): "
                    "each is reported and their time and filament summed")
        ->required()->check(CLI::ExistingFile);
    cmd->add_option("--layer", opts->slicer.layer_mm, "Layer height, mm")
        ->check(CLI::Range(0.01, 2.0))->capture_default_str();
    cmd->add_option("--nozzle", opts->slicer.nozzle_mm, "Nozzle diameter, mm")
        ->check(CLI::Range(0.05, 3.0))->capture_default_str();
    cmd->add_option("--bed", opts->bed, "Bed WIDTHxDEPTH, mm (default: PrusaSlicer's 200x200)");
    cmd->add_option("--filament-density", opts->slicer.filament_density_g_cm3, "Filament density, g/cm3 (PLA 1.24)")
        ->check(CLI::Range(0.1, 20.0))->capture_default_str();
    cmd->add_option("--slicer", opts->slicer.executable, "PrusaSlicer executable (name in PATH or path)")
        ->capture_default_str();
    cmd->add_option("--timeout", opts->slicer.timeout_s, "Longest a slicing may take, s")
        ->check(CLI::PositiveNumber)->capture_default_str();
    cmd->add_flag("--json", opts->json, "Print every figure as JSON");
    cmd->callback([opts] { runPrintCheckCommand(*opts); });
}

}  // namespace tsf::cli
