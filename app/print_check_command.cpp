// tsf print-check: slice a model with PrusaSlicer's command line and report
// what a printer would make of it. See runners/prusa_slicer/print_check.h and
// docs/printing.md.
#include <iostream>
#include <memory>
#include <string>

#include "app/bed_size.h"
#include "app/commands.h"
#include "runners/prusa_slicer/print_check.h"

namespace tsf::cli {
namespace {

struct PrintCheckOptions {
    std::string model;
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
    PrintCheckReport report;
    try {
        report = runPrintCheck(o.model, s);
    } catch (const SlicerError& e) {
        std::cerr << "tsf: error: " << e.what() << "\n";
        throw CLI::RuntimeError(kExitToolFailed);
    }
    if (o.json)
        std::cout << toJson(report).dump(2) << "\n";
    else
        std::cout << formatPrintCheck(report);
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
        "Exit codes: 0 the report was made (read it: it does not judge), 2 bad input (unreadable model,\n"
        "larger than the bed, bad option), 3 PrusaSlicer is missing or failed.");
    cmd->add_option("model", opts->model, "Model to slice: STL or 3MF (mm)")->required()->check(CLI::ExistingFile);
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
