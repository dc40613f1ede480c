// tsf coupon: a small calibration piece for the chosen printer settings.
//
// A teacher prints it once and puts a student's hand on it to choose the
// settings of the models to come (docs/tactile.md, "The calibration
// coupon"). It is an ordinary tsf model, made by `tsf gen` from a field tsf
// writes beside it (MODEL.coupon.csv), so it is verified like any model and
// carries the same orientation tab and braille legend:
//   - north, four plateaus at height steps of whole layers near 0.2, 0.5, 1
//     and 2 mm above the floor (the smallest step the student tells apart
//     sets --height: the data's steps should be at least that);
//   - south, three rows of ridges 1 mm high: single cells (3 mm) one cell
//     apart, pairs (6 mm) and triples (9 mm) as far apart: the smallest that
//     still feel like separate pillars is the --cell to use;
//   - the tab's notch (6 mm) and triangle (14 x 8.4 mm) and the braille
//     legend naming the sections, at dots made whole layers.
#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "app/commands.h"
#include "gen/util/atomic_file.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf::cli {
namespace {

struct CouponOptions {
    std::string output;
    double layer_mm = 0.2;
    double nozzle_mm = 0.4;
    bool json = false;
    bool print_check = false;
    bool force = false;
    std::string scad, preview;
};

// Grid of the coupon, one value (mm above the floor) per cell.
constexpr int kCols = 20;
constexpr double kCellMm = 3.0;
constexpr double kRidgeMm = 1.0;

// Whole layers near 0.2, 0.5, 1 and 2 mm (at least one layer each, no two the same).
std::vector<double> couponSteps(double layer) {
    std::vector<double> steps;
    for (const double target : {0.2, 0.5, 1.0, 2.0}) {
        const double v = std::max(1.0, std::floor(target / layer + 0.5)) * layer;
        if (steps.empty() || v > steps.back() + 1e-9) steps.push_back(v);
    }
    return steps;
}

std::string number(double v) { return formatSignificant(v, 4); }

// Rows from the north: three rows of plateaus (four cells each, one cell
// at the floor between), then three rows of ridges with periods of 1, 2 and
// 3 cells, each after a row at the floor.
std::string couponField(const std::vector<double>& steps) {
    std::vector<std::vector<double>> rows;
    std::vector<double> plateaus(kCols, 0.0);
    for (size_t k = 0; k < steps.size(); ++k)
        for (int c = 0; c < 4; ++c) plateaus[size_t(int(k) * 5 + c)] = steps[k];
    for (int r = 0; r < 3; ++r) rows.push_back(plateaus);
    // One row per band between rows at the floor: on a hexagonal grid two
    // rows of ridges would touch diagonally and read as one zigzag.
    for (const int period : {1, 2, 3}) {
        rows.push_back(std::vector<double>(kCols, 0.0));
        std::vector<double> ridges(kCols, 0.0);
        for (int c = 0; c < kCols; ++c) ridges[size_t(c)] = (c / period) % 2 == 0 ? kRidgeMm : 0.0;
        rows.push_back(ridges);
    }
    std::string csv;
    for (const auto& r : rows) {
        for (size_t c = 0; c < r.size(); ++c) csv += (c ? "," : "") + number(r[c]);
        csv += "\n";
    }
    return csv;
}

void runCoupon(const CouponOptions& o) {
    if (o.output.empty()) throw InputError("tsf coupon: give the model file to write: -o coupon.stl");
    const std::vector<double> steps = couponSteps(o.layer_mm);
    // The base: two layers, at least 0.6 mm, in whole layers (the legend plate and tab are as thick).
    const double base = std::ceil(std::max(0.6, 2 * o.layer_mm) / o.layer_mm - 1e-9) * o.layer_mm;
    const std::string field = o.output + ".coupon.csv";
    writeFileAtomically(field, [&](std::ostream& out) { out << couponField(steps); });

    // The key's first paragraph: the sections, where each is, and the lesson
    // (the reader's part of a key names no option: the teacher reads the
    // options in docs/tactile.md).
    const std::string nb = "\u00A0";
    std::string about = "a calibration coupon, to find with the reader's fingers the settings of the models to come. "
                        "In the north, " + std::to_string(steps.size()) + " plateaus stand from west to east at";
    for (size_t k = 0; k < steps.size(); ++k)
        about += std::string(k == 0 ? " " : k + 1 == steps.size() ? " and " : ", ") + formatForReader(steps[k], 3) +
                 (k + 1 == steps.size() ? nb + "millimetres" : "");
    about += " above the floor. In the south, three rows of ridges " + formatForReader(kRidgeMm, 3) + nb +
             "millimetre high, from north to south: single hexagons " + formatForReader(kCellMm, 3) + nb +
             "millimetres wide, pairs " + formatForReader(2 * kCellMm, 3) + nb + "millimetres wide, and triples " +
             formatForReader(3 * kCellMm, 3) + nb + "millimetres wide, each as far from the next as it is wide. "
             "The lesson: the lowest plateau the reader tells apart from the floor is the smallest difference of height "
             "worth asking for between values; the narrowest ridges that still feel separate give the hexagon size to use";
    std::string title = "steps";
    for (const double s : steps) title += " " + number(s);
    title += " cells 3 6 9";
    std::vector<std::string> args = {"gen",      field,          "--cell",       number(kCellMm), "--height",
                                     number(steps.back()), "--value-max", number(steps.back()), "--baseline", "zero",
                                     "--base",   number(base),   "--layer",      number(o.layer_mm), "--nozzle",
                                     number(o.nozzle_mm), "--cull", "none", "--title", title, "--about", about,
                                     "-o",       o.output};
    if (o.json) args.push_back("--json");
    if (o.print_check) args.push_back("--print-check");
    if (o.force) args.push_back("--force");
    if (!o.scad.empty()) args.insert(args.end(), {"--scad", o.scad});
    if (!o.preview.empty()) args.insert(args.end(), {"--preview", o.preview});
    if (!o.json) {
        std::string line = "tsf coupon: " + std::to_string(steps.size()) + " plateaus at";
        for (const double s : steps) line += " " + number(s);
        line += " mm above the floor (north), ridges " + number(kRidgeMm) + " mm high 3, 6 and 9 mm wide (south), " +
                "the orientation tab and a braille legend; its field is " + field + ", made as:\n  tsf";
        for (size_t k = 0; k < args.size(); ++k)
            if (args[k] == "--about") ++k;  // the key's words: long, and in the key
            else line += args[k].find(' ') == std::string::npos ? " " + args[k] : " \"" + args[k] + "\"";
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    }
    CLI::App gen_app{"tsf"};
    addGenCommand(gen_app);
    std::reverse(args.begin(), args.end());  // CLI11 takes a vector of arguments last first
    gen_app.parse(args);
}

}  // namespace

void addCouponCommand(CLI::App& app) {
    auto opts = std::make_shared<CouponOptions>();
    CLI::App* cmd = app.add_subcommand("coupon", "Make a small calibration piece: height steps, cell sizes, "
                                                 "orientation marks and braille at your printer's settings");
    cmd->footer(
        "Print it once and let the reader's fingers choose the settings (docs/tactile.md):\n"
        "  the smallest step told apart -> the height between values (--height),\n"
        "  the ridges that still feel like separate pillars -> --cell.\n"
        "Examples:\n"
        "  tsf coupon -o coupon.stl\n"
        "  tsf coupon --layer 0.1 --nozzle 0.4 --print-check -o coupon.3mf\n"
        "It writes MODEL, MODEL.scene.json and MODEL.coupon.csv (its field, for tsf gen).");
    cmd->add_option("-o,--output", opts->output, "Model file: .stl (binary), .3mf, .off or .obj")->required();
    cmd->add_option("--layer", opts->layer_mm, "Layer height, mm: steps and braille dots are whole layers")
        ->check(CLI::Range(0.05, 0.4))->capture_default_str();
    cmd->add_option("--nozzle", opts->nozzle_mm, "Nozzle diameter, mm")->check(CLI::Range(0.1, 1.0))->capture_default_str();
    cmd->add_option("--scad", opts->scad, "Also write a parametric OpenSCAD file");
    cmd->add_option("--preview", opts->preview, "Also draw the coupon to this PNG");
    cmd->add_flag("--json", opts->json, "Print the summary as JSON (that of tsf gen)");
    cmd->add_flag("--print-check", opts->print_check, "Slice it with PrusaSlicer and report time and filament");
    cmd->add_flag("--force", opts->force, "Replace MODEL.scene.json even when it was not written by tsf");
    cmd->callback([opts] { runCoupon(*opts); });
}

}  // namespace tsf::cli
