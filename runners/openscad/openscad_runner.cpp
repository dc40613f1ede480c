#include "runners/openscad/openscad_runner.h"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include <nlohmann/json.hpp>

#include "gen/util/error.h"
#include "gen/util/atomic_file.h"
#include "runners/process_runner.h"

namespace tsf {
namespace fs = std::filesystem;

namespace {

// `openscad --version` prints one line and exits; anything slower is broken.
constexpr double kVersionTimeoutS = 30.0;
// `openscad --help` prints its options and exits at once.
constexpr double kHelpTimeoutS = 30.0;

const char* const kOpenScadInstallHint =
    "install OpenSCAD (Debian/Ubuntu: sudo apt install openscad; others: https://openscad.org/downloads.html) "
    "or give its path with --openscad PATH";

std::string lower(std::string s) {
    for (char& ch : s) ch = char(std::tolower(static_cast<unsigned char>(ch)));
    return s;
}

bool isIdentifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_' || s[0] == '$')) return false;
    return std::all_of(s.begin() + 1, s.end(), [](char ch) { return std::isalnum(static_cast<unsigned char>(ch)) || ch == '_'; });
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

class OpenScadEngine : public ScadEngine {
public:
    OpenScadEngine(std::string exe, std::string version, bool manifold)
        : exe_(std::move(exe)), version_(std::move(version)), manifold_(manifold) {}
    std::string name() const override { return "openscad"; }
    std::string version() const override { return version_; }
    std::string executable() const override { return exe_; }
    bool supports(ScadExportFormat) const override { return true; }

    ScadRenderResult run(const ScadRenderRequest& rq, const ScadProgress& progress) const override {
        std::vector<std::string> argv;
        if (rq.format == ScadExportFormat::Png) {
            // OpenSCAD 2021.01 draws PNGs with OpenGL and needs an X display;
            // without one it crashes. xvfb-run provides a virtual one.
            const char* display = std::getenv("DISPLAY");
            if (!display || !*display) {
                const std::string xvfb = findExecutable("xvfb-run");
                if (xvfb.empty())
                    throw ScadEngineMissing("a PNG preview needs an X display, and xvfb-run was not found: "
                                            "install it (Debian/Ubuntu: sudo apt install xvfb) or run with DISPLAY set");
                argv = {xvfb, "-a", "-s", "-screen 0 1280x1024x24"};
            }
        }
        argv.insert(argv.end(), {exe_, "-o", rq.output_path, "--export-format", exportFormatArg(rq.format)});
        // A binary that offers the Manifold backend renders CSG orders of
        // magnitude faster with it (docs/engines.md); 2021.01 rejects the flag.
        if (manifold_ && rq.format != ScadExportFormat::Png) argv.push_back("--backend=manifold");
        for (const ScadDefine& d : rq.defines) argv.insert(argv.end(), {"-D", d.name + "=" + d.value});
        if (!rq.parameter_file.empty()) argv.insert(argv.end(), {"-p", rq.parameter_file});
        if (!rq.parameter_set.empty()) argv.insert(argv.end(), {"-P", rq.parameter_set});
        if (rq.format == ScadExportFormat::Png) {
            argv.push_back("--imgsize=" + std::to_string(rq.png.width_px) + "," + std::to_string(rq.png.height_px));
            // A camera with its own distance (or an eye and centre) is taken as
            // given; only a distance of 0 asks OpenSCAD to frame the model.
            for (const std::string& flag : cameraFramingFlags(rq.png.camera)) argv.push_back(flag);
            argv.push_back("--camera=" + rq.png.camera);
        }
        argv.push_back(rq.scad_path);

        ProcessResult pr;
        ScadRenderResult r = runEngineProcess(argv, rq, progress, pr);
        finishEngineResult(r, pr, rq, "openscad");
        return r;
    }

private:
    std::string exe_;
    std::string version_;
    bool manifold_ = false;  ///< the binary offers --backend=manifold
};

// Names the -D override a parser error points into: OpenSCAD parses the
// overrides as lines appended to the file, from line (newlines + 3) on.
void annotateDefineErrors(ScadRenderResult& r, const ScadRenderRequest& rq, const std::string& scad_text) {
    if (rq.defines.empty()) return;
    const int newlines = int(std::count(scad_text.begin(), scad_text.end(), '\n'));
    const std::string base = fs::path(rq.scad_path).filename().string();
    for (ScadMessage& m : r.messages) {
        if (m.kind != ScadMessage::Kind::Error || m.line <= newlines || fs::path(m.file).filename().string() != base)
            continue;
        const int index = m.line - newlines - 3;
        if (index >= 0 && index < int(rq.defines.size()))
            m.text += " (that is the override -D " + rq.defines[size_t(index)].name + "=" +
                      rq.defines[size_t(index)].value + ")";
        else
            m.text += " (in a -D override)";
    }
}

void checkParameterSet(const ScadRenderRequest& rq) {
    if (rq.parameter_set.empty()) return;
    if (rq.parameter_file.empty())
        throw InputError("parameter set '" + rq.parameter_set + "' given without a parameter file (-p FILE.json)");
    std::ifstream in(rq.parameter_file, std::ios::binary);
    if (!in) throw InputError(rq.parameter_file, 0, 0, "cannot read the parameter file");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in);
    } catch (const nlohmann::json::parse_error& e) {
        throw InputError(rq.parameter_file, 0, 0, std::string("not valid JSON: ") + e.what());
    }
    const auto sets = doc.find("parameterSets");
    if (sets == doc.end() || !sets->is_object())
        throw InputError(rq.parameter_file, 0, 0, "not an OpenSCAD parameter file (no \"parameterSets\" object)");
    if (sets->contains(rq.parameter_set)) return;
    std::string names;
    for (auto it = sets->begin(); it != sets->end(); ++it) names += (names.empty() ? "\"" : ", \"") + it.key() + "\"";
    throw InputError(rq.parameter_file, 0, 0,
                     "has no parameter set \"" + rq.parameter_set + "\"; it has: " + (names.empty() ? "none" : names));
}

}  // namespace

bool scadFormatForPath(const std::string& path, ScadExportFormat& format) {
    const std::string ext = lower(fs::path(path).extension().string());
    if (ext == ".stl") format = ScadExportFormat::Stl;
    else if (ext == ".3mf") format = ScadExportFormat::ThreeMf;
    else if (ext == ".off") format = ScadExportFormat::Off;
    else if (ext == ".amf") format = ScadExportFormat::Amf;
    else if (ext == ".png") format = ScadExportFormat::Png;
    else return false;
    return true;
}

const char* toString(ScadExportFormat f) {
    switch (f) {
        case ScadExportFormat::ThreeMf: return "3mf";
        case ScadExportFormat::Off: return "off";
        case ScadExportFormat::Amf: return "amf";
        case ScadExportFormat::Png: return "png";
        default: return "stl";
    }
}

const char* exportFormatArg(ScadExportFormat f) { return f == ScadExportFormat::Stl ? "binstl" : toString(f); }

namespace {
// The numbers of a --camera text; empty when one is not a number.
std::vector<double> cameraValues(const std::string& camera) {
    std::vector<double> v;
    size_t start = 0;
    for (;;) {
        const size_t comma = camera.find(',', start);
        const std::string part = camera.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
        char* end = nullptr;
        v.push_back(std::strtod(part.c_str(), &end));
        if (end == part.c_str()) return {};  // not a number: OpenSCAD will say so
        if (comma == std::string::npos) break;
        start = comma + 1;
    }
    return v;
}
}  // namespace

std::vector<std::string> cameraFramingFlags(const std::string& camera) {
    const std::vector<double> v = cameraValues(camera);
    if (v.size() == 7 && v[6] == 0) return {"--autocenter", "--viewall"};
    return {};
}

std::string cameraLookingAt(const std::string& camera, double x, double y, double z) {
    const std::vector<double> v = cameraValues(camera);
    if (v.size() != 7 || v[6] == 0 || v[0] != 0 || v[1] != 0 || v[2] != 0) return camera;
    std::ostringstream s;
    s << x << "," << y << "," << z;
    for (size_t k = 3; k < 7; ++k) s << "," << v[k];
    return s.str();
}

ScadDefine parseScadDefine(const std::string& text) {
    const size_t eq = text.find('=');
    ScadDefine d;
    if (eq != std::string::npos) {
        d.name = text.substr(0, eq);
        d.value = text.substr(eq + 1);
    }
    auto trim = [](std::string& s) {
        const auto not_space = [](char ch) { return !std::isspace(static_cast<unsigned char>(ch)); };
        s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
        s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
    };
    trim(d.name);
    trim(d.value);
    if (eq == std::string::npos || !isIdentifier(d.name) || d.value.empty())
        throw InputError("-D expects NAME=VALUE with an OpenSCAD variable name and a value, e.g. -D height=25 "
                         "or -D 'transfer=\"log\"' (got '" + text + "')");
    if (isIdentifier(d.value) && d.value != "true" && d.value != "false" && d.value != "undef")
        d.value = "\"" + d.value + "\"";
    return d;
}

std::vector<ScadMessage> ScadRenderResult::errors() const {
    std::vector<ScadMessage> out;
    bool after_error = false;
    for (const ScadMessage& m : messages) {
        if (m.kind == ScadMessage::Kind::Error) after_error = true;
        else if (m.kind != ScadMessage::Kind::Trace) after_error = false;
        if (m.kind == ScadMessage::Kind::Error || (m.kind == ScadMessage::Kind::Trace && after_error)) out.push_back(m);
    }
    return out;
}

std::vector<ScadMessage> ScadRenderResult::warnings() const {
    std::vector<ScadMessage> out;
    for (const ScadMessage& m : messages)
        if (m.kind == ScadMessage::Kind::Warning || m.kind == ScadMessage::Kind::Deprecated) out.push_back(m);
    return out;
}

ScadRenderResult runEngineProcess(const std::vector<std::string>& argv, const ScadRenderRequest& rq,
                                  const ScadProgress& progress, ProcessResult& process) {
    ProcessOptions po;
    po.timeout_s = rq.timeout_s;
    po.progress_interval_s = rq.progress_interval_s;
    po.on_progress = progress;
    process = runProcess(argv, po);
    ScadRenderResult r;
    r.command = argv;
    r.elapsed_s = process.elapsed_s;
    r.peak_memory_kb = process.peak_memory_kb;
    r.output = process.output;
    r.messages = parseOpenScadOutput(process.output);
    return r;
}

void finishEngineResult(ScadRenderResult& r, const ProcessResult& pr, const ScadRenderRequest& rq,
                        const std::string& engine, const std::function<std::string(int)>& explain_exit) {
    std::ostringstream why;
    switch (pr.end) {
        case ProcessResult::End::Exited:
            if (pr.exit_code == 0 && !r.errors().empty()) {
                // OpenSCAD 2025 goes on after an ERROR (a failed assert() drops
                // only the module it is in) and exports what is left with exit
                // status 0; 2021.01 stops. Same rule for every engine.
                why << engine << " reported an error but exported the rest of the model anyway: "
                    << formatScadMessage(r.errors().front()) << "; treated as a failure";
            } else if (pr.exit_code == 0) {
                r.status = ScadRenderResult::Status::Ok;
                why << "rendered in " << std::fixed << std::setprecision(2) << pr.elapsed_s << " s";
            } else if (const std::string special = explain_exit ? explain_exit(pr.exit_code) : ""; !special.empty()) {
                why << special;
            } else {
                why << engine << " failed (exit code " << pr.exit_code << ")";
                if (pr.output.find("Current top level object is empty") != std::string::npos)
                    why << ": the model is empty, nothing to export";
            }
            break;
        case ProcessResult::End::Signalled: why << engine << " crashed (signal " << pr.signal << ")"; break;
        case ProcessResult::End::TimedOut:
            r.status = ScadRenderResult::Status::TimedOut;
            why << engine << " was stopped after the time limit of " << rq.timeout_s << " s";
            break;
        case ProcessResult::End::Interrupted:
            r.status = ScadRenderResult::Status::Interrupted;
            why << "interrupted; " << engine << " was stopped";
            break;
        case ProcessResult::End::NotStarted: why << pr.start_error; break;
    }
    r.summary = why.str();
}

std::unique_ptr<ScadEngine> makeOpenScadEngine(const std::string& binary) {
    const std::string wanted = binary.empty() ? "openscad" : binary;
    const std::string exe = findExecutable(wanted);
    if (exe.empty()) {
        if (binary.empty()) throw ScadEngineMissing(std::string("openscad was not found in PATH: ") + kOpenScadInstallHint);
        throw ScadEngineMissing("'" + binary + "' is not an executable file: " + kOpenScadInstallHint);
    }
    ProcessOptions po;
    po.timeout_s = kVersionTimeoutS;
    const ProcessResult pr = runProcess({exe, "--version"}, po);
    if (!pr.succeeded())
        throw ScadEngineMissing("'" + exe + "' does not run as OpenSCAD (`" + exe + " --version` failed: " +
                                (pr.start_error.empty() ? firstLine(pr.output) : pr.start_error) + "): " +
                                kOpenScadInstallHint);
    std::string version;
    std::istringstream lines(pr.output);
    for (std::string line; std::getline(lines, line);)
        if (line.find("OpenSCAD") != std::string::npos) version = line;
    if (version.empty()) version = firstLine(pr.output);
    return std::make_unique<OpenScadEngine>(exe, version, openScadHasManifoldBackend(exe));
}

ScadRenderResult renderScad(const ScadEngine& engine, const ScadRenderRequest& request, const ScadProgress& progress) {
    std::string scad_text;
    {
        std::ifstream in(request.scad_path, std::ios::binary);
        struct stat st {};
        if (!in.is_open() || stat(request.scad_path.c_str(), &st) != 0 || !S_ISREG(st.st_mode))
            throw InputError(request.scad_path, 0, 0, "cannot read this OpenSCAD file");
        std::ostringstream text;
        text << in.rdbuf();
        scad_text = text.str();
    }
    if (!engine.supports(request.format))
        throw InputError(request.output_path, 0, 0,
                         engine.name() + " cannot export " + toString(request.format) + " files");
    checkParameterSet(request);
    if (!request.parameter_file.empty() && request.parameter_set.empty())
        throw InputError(request.parameter_file, 0, 0, "a parameter file needs a set to apply (-P NAME)");

    AtomicFile out(request.output_path);
    ScadRenderRequest rq = request;
    rq.output_path = out.tempPath();
    ScadRenderResult r = engine.run(rq, progress);
    annotateDefineErrors(r, request, scad_text);
    if (r.ok()) {
        std::error_code ec;
        const auto size = fs::file_size(out.tempPath(), ec);
        if (ec || size == 0) {
            r.status = ScadRenderResult::Status::Failed;
            r.summary = engine.name() + " reported success but wrote nothing (is the model empty?)";
        } else {
            out.commit();
        }
    }
    return r;
}

bool openScadHasManifoldBackend(const std::string& executable) {
    ProcessOptions po;
    po.timeout_s = kHelpTimeoutS;
    const ProcessResult pr = runProcess({executable, "--help"}, po);
    if (pr.end != ProcessResult::End::Exited) return false;
    const std::string help = lower(pr.output);
    const size_t at = help.find("--backend");
    return at != std::string::npos && help.find("manifold", at) != std::string::npos;
}

}  // namespace tsf
