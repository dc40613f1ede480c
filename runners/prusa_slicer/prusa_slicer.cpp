#include "runners/prusa_slicer/prusa_slicer.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "gen/util/temp_files.h"
#include "runners/process_runner.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace fs = std::filesystem;

namespace {

// --help and --info answer in well under a second; slicing has its own limit.
constexpr double kQuickCommandTimeoutS = 60.0;

const char* const kInstallHint =
    "install PrusaSlicer (Debian/Ubuntu: sudo apt install prusa-slicer; others: https://www.prusa3d.com/prusaslicer/) "
    "or give its path with --slicer PATH";

// The slicer's output without its "[trace]"-style log lines: what it says to a person.
std::string messages(const std::string& output) {
    std::istringstream in(output);
    std::string line, out;
    while (std::getline(in, line)) {
        if (line.rfind("[20", 0) == 0) continue;  // "[2026-11-23 14:39:12.40] [0x..] [trace] ..."
        if (!out.empty()) out += "\n";
        out += line;
    }
    return out.size() > 2000 ? out.substr(out.size() - 2000) : out;
}

std::string executableOrThrow(const SlicerSettings& s) {
    const std::string exe = findExecutable(s.executable);
    if (exe.empty()) throw SlicerError("PrusaSlicer ('" + s.executable + "') was not found: " + kInstallHint);
    return exe;
}

// A fresh, empty data folder, so the user's own profiles are never read; removed when it goes.
class ScratchDir {
public:
    ScratchDir() {
        const char* tmp = std::getenv("TMPDIR");
        std::string templ = std::string(tmp && *tmp ? tmp : "/tmp") + "/tsf-slicer-XXXXXX";
        if (!mkdtemp(templ.data())) throw SlicerError("cannot create a temporary folder for PrusaSlicer in " + templ);
        path_ = templ;
    }
    ~ScratchDir() {
        std::error_code ec;
        fs::remove_all(path_, ec);
    }
    ScratchDir(const ScratchDir&) = delete;
    ScratchDir& operator=(const ScratchDir&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

ProcessResult run(std::vector<std::string> argv, double timeout_s) {
    ProcessOptions po;
    po.timeout_s = timeout_s;
    ProcessResult r = runProcess(argv, po);
    switch (r.end) {
        case ProcessResult::End::NotStarted:
            throw SlicerError("PrusaSlicer (" + argv[0] + ") could not be started: " + r.start_error);
        case ProcessResult::End::TimedOut:
            throw SlicerError("PrusaSlicer did not finish within " + formatSignificant(timeout_s, 10) + " s");
        case ProcessResult::End::Interrupted: throw SlicerError("PrusaSlicer was interrupted");
        case ProcessResult::End::Signalled:
            throw SlicerError("PrusaSlicer crashed (signal " + std::to_string(r.signal) + "): " + messages(r.output));
        case ProcessResult::End::Exited: break;
    }
    return r;
}

}  // namespace

std::string prusaSlicerVersion(const SlicerSettings& s) {
    const ProcessResult r = run({executableOrThrow(s), "--loglevel", "1", "--help"}, kQuickCommandTimeoutS);
    std::istringstream in(r.output);
    std::string line;
    while (std::getline(in, line))
        if (line.rfind("PrusaSlicer-", 0) == 0) return line.substr(0, line.find(' '));
    throw SlicerError("'" + s.executable + " --help' does not say it is PrusaSlicer: " + messages(r.output));
}

SlicerModelInfo prusaSlicerInfo(const std::string& model_path, const SlicerSettings& s) {
    ScratchDir data;
    const ProcessResult r =
        run({executableOrThrow(s), "--loglevel", "1", "--datadir", data.path(), "--info", model_path}, kQuickCommandTimeoutS);
    if (!r.succeeded()) throw SlicerError("PrusaSlicer could not read the model: " + messages(r.output));
    SlicerModelInfo info;
    bool manifold_seen = false;
    std::istringstream in(r.output);
    std::string line;
    while (std::getline(in, line)) {
        const size_t eq = line.find(" = ");
        if (eq == std::string::npos) continue;
        std::string key = line.substr(0, eq);
        while (!key.empty() && key.back() == ' ') key.pop_back();
        const std::string value = line.substr(eq + 3);
        const double v = std::strtod(value.c_str(), nullptr);
        if (key == "manifold") {
            // One block per object: the model is manifold when every object is.
            info.manifold = (info.objects == 0 || info.manifold) && value.rfind("yes", 0) == 0;
            ++info.objects;
            manifold_seen = true;
        } else if (key == "open_edges") info.open_edges = long(v);
        else if (key == "number_of_facets") info.facets = long(v);
        else if (key == "number_of_parts") info.parts = long(v);
        else if (key == "volume") info.volume_mm3 = v;
        else if (key == "size_x") info.size_mm[0] = v;
        else if (key == "size_y") info.size_mm[1] = v;
        else if (key == "size_z") info.size_mm[2] = v;
    }
    if (!manifold_seen) throw SlicerError("PrusaSlicer's --info says nothing of the model: " + messages(r.output));
    return info;
}

std::vector<std::string> prusaSliceArguments(const SlicerSettings& s, bool with_support) {
    const std::string w = formatSignificant(s.bed_width_mm, 10), d = formatSignificant(s.bed_depth_mm, 10);
    std::vector<std::string> a = {
        "--layer-height", formatSignificant(s.layer_mm, 10),
        "--first-layer-height", formatSignificant(s.layer_mm, 10),
        "--nozzle-diameter", formatSignificant(s.nozzle_mm, 10),
        "--filament-density", formatSignificant(s.filament_density_g_cm3, 10),
        "--bed-shape", "0x0," + w + "x0," + w + "x" + d + ",0x" + d,
        "--center", formatSignificant(s.bed_width_mm / 2, 10) + "," + formatSignificant(s.bed_depth_mm / 2, 10),
    };
    if (with_support) a.push_back("--support-material");
    return a;
}

GcodeSummary prusaSlice(const std::string& model_path, const SlicerSettings& s, bool with_support) {
    ScratchDir data;
    const std::string gcode = data.path() + "/model.gcode";
    std::vector<std::string> argv = {executableOrThrow(s), "--loglevel", "1", "--datadir", data.path(), "--export-gcode"};
    for (const std::string& a : prusaSliceArguments(s, with_support)) argv.push_back(a);
    argv.insert(argv.end(), {"-o", gcode, model_path});
    const int slot = registerTempFile(gcode);
    const ProcessResult r = run(argv, s.timeout_s);
    if (!r.succeeded() || !fs::exists(gcode)) {
        unregisterTempFile(slot);
        throw SlicerError("PrusaSlicer could not slice the model (exit " + std::to_string(r.exit_code) +
                          "): " + messages(r.output));
    }
    std::ifstream in(gcode);
    GcodeSummary g = summarizeGcode(in);
    unregisterTempFile(slot);
    if (g.layers == 0 || std::isnan(g.filament_mm) || std::isnan(g.print_time_s))
        throw SlicerError("PrusaSlicer's G-code has no layers, filament or time estimate in its comments");
    return g;
}

}  // namespace tsf
