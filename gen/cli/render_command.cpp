// tsf render: a .scad file to STL / 3MF / OFF / AMF and a PNG preview through
// OpenSCAD, with progress, timing, a time limit and OpenSCAD's own error
// lines; the exported mesh is checked (closed, manifold, oriented) because
// OpenSCAD's own verdict cannot be trusted.
#include <stdlib.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <iterator>
#include <filesystem>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "gen/cli/commands.h"
#include "gen/error.h"
#include "gen/mesh.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/scad/openscad_runner.h"
#include "gen/scad/scad_variables.h"
#include "verify/mesh_topology.h"

namespace tsf::cli {
namespace {

namespace fs = std::filesystem;

struct RenderOptions {
    std::string scad;
    std::string output;
    std::string png;
    std::vector<std::string> defines;
    std::string params;
    std::string param_set;
    std::string openscad;
    std::string engine = "openscad";
    double timeout_s = 3600;
    std::vector<int> imgsize{1024, 768};
    std::string camera = kDefaultPngCamera;
    bool no_check = false;
    bool quiet = false;
    bool verbose = false;
};

std::string megabytes(long kb) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.0f MB", double(kb) / 1024.0);
    return buf;
}

std::string seconds(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, s < 10 ? "%.2f s" : "%.1f s", s);
    return buf;
}

// Prints what OpenSCAD said that a person needs: errors (with their trace)
// and warnings; everything when verbose.
void printMessages(const ScadRenderResult& r, bool verbose) {
    if (verbose) {
        std::fputs(r.output.c_str(), stderr);
        return;
    }
    for (const ScadMessage& m : r.errors()) std::fprintf(stderr, "  %s\n", formatScadMessage(m).c_str());
    for (const ScadMessage& m : r.warnings()) std::fprintf(stderr, "  %s\n", formatScadMessage(m).c_str());
}

// Exit code for a failed render: our library's assert() and parse errors are
// bad input (a parameter or a value); anything else is the tool failing.
int failureExitCode(const ScadRenderResult& r) {
    if (r.status == ScadRenderResult::Status::Interrupted) return kExitInterrupted;
    if (r.status == ScadRenderResult::Status::TimedOut) return kExitToolFailed;
    for (const ScadMessage& m : r.errors())
        if (!m.assert_message.empty() || m.text.rfind("Parser error", 0) == 0) return kExitBadInput;
    return kExitToolFailed;
}

// source_name: what to call the input in messages (the model, or the mesh a
// preview is drawn from).
ScadRenderResult renderOnce(const ScadEngine& engine, const ScadRenderRequest& rq, const RenderOptions& o,
                            const std::string& source_name) {
    const std::string what = fs::path(rq.output_path).filename().string();
    if (!o.quiet)
        std::fprintf(stderr, "tsf: rendering %s -> %s with %s\n", source_name.c_str(), what.c_str(),
                     engine.version().c_str());
    ScadProgress progress;
    if (!o.quiet) {
        progress = [&](double elapsed_s, const std::string& last_line) {
            std::string last = last_line.substr(0, 100);
            std::fprintf(stderr, "tsf: still rendering %s: %s%s%s\n", what.c_str(), seconds(elapsed_s).c_str(),
                         last.empty() ? "" : " - openscad: ", last.c_str());
        };
    }
    const ScadRenderResult r = renderScad(engine, rq, progress);
    if (!r.ok()) {
        std::fprintf(stderr, "tsf: error: %s: %s\n", source_name.c_str(), r.summary.c_str());
        printMessages(r, o.verbose);
        throw CLI::RuntimeError(failureExitCode(r));
    }
    if (o.verbose) printMessages(r, true);
    else if (!o.quiet) printMessages(r, false);
    return r;
}

// Reads the exported mesh back and says whether it is a closed, oriented
// solid. Returns false when it is not.
bool checkExport(const std::string& path, bool quiet) {
    MeshReadReport report;
    const Mesh mesh = readMesh(path, &report);
    const MeshTopology topo = analyzeTopology(mesh);
    const double volume = signedVolume(mesh);
    if (topo.isClosedOrientedManifold() && volume > 0) {
        if (!quiet)
            std::fprintf(stderr, "tsf: %s: %zu triangles, closed, manifold, outward; volume %.6g mm^3\n",
                         path.c_str(), mesh.triangleCount(), volume);
        return true;
    }
    std::fprintf(stderr,
                 "tsf: error: %s is not a closed solid: %zu open edges, %zu non-manifold edges, %zu flipped edges, "
                 "signed volume %.6g mm^3. Do not print it; run 'tsf verify %s' for details.\n",
                 path.c_str(), topo.border_edges.size(), topo.nonmanifold_edges.size(), topo.misoriented_edges.size(),
                 volume, path.c_str());
    return false;
}

// An OpenSCAD string literal for a path.
std::string scadString(const std::string& s) {
    std::string out = "\"";
    for (char ch : s) {
        if (ch == '"' || ch == '\\') out += '\\';
        out += ch;
    }
    return out + "\"";
}

// A temporary .scad that imports an exported mesh, for the PNG preview (the
// picture then shows exactly the file that will be printed).
class ImportWrapper {
public:
    explicit ImportWrapper(const std::string& mesh_path) {
        const char* tmp = std::getenv("TMPDIR");
        std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/tsf-preview-XXXXXX.scad";
        std::vector<char> buf(pattern.begin(), pattern.end());
        buf.push_back('\0');
        const int fd = mkstemps(buf.data(), 5);
        if (fd < 0) throw std::runtime_error("cannot create a temporary file for the PNG preview in " + pattern);
        close(fd);
        path_ = buf.data();
        std::ofstream out(path_);
        // The same warm colour as tsf gen --preview: steps between pillars show clearly.
        out << "color(\"#e8a33d\") import(" << scadString(fs::absolute(mesh_path).string()) << ", convexity = 10);\n";
        if (!out) throw std::runtime_error("cannot write " + path_);
    }
    ~ImportWrapper() {
        std::error_code ec;
        fs::remove(path_, ec);
    }
    ImportWrapper(const ImportWrapper&) = delete;
    ImportWrapper& operator=(const ImportWrapper&) = delete;
    const std::string& path() const { return path_; }

private:
    std::string path_;
};

// A -D for a variable the file does not assign would be added silently and
// change nothing; refuse it (only warn when the file includes others, whose
// variables we do not read).
void checkDefineNames(const std::string& scad_path, const std::vector<ScadDefine>& defines) {
    if (defines.empty()) return;
    std::ifstream in(scad_path, std::ios::binary);
    if (!in) return;  // renderScad reports an unreadable file
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const std::vector<std::string> names = scadTopLevelVariables(text);
    const bool includes = scadHasInclude(text);
    for (const ScadDefine& d : defines) {
        if (std::find(names.begin(), names.end(), d.name) != names.end()) continue;
        std::string known;
        for (const std::string& n : names) known += (known.empty() ? "" : ", ") + n;
        const std::string what = "-D " + d.name + ": the file assigns no variable named '" + d.name +
                                 "'; its variables are: " + (known.empty() ? "none" : known);
        if (includes) {
            std::fprintf(stderr, "tsf: warning: %s: %s (it may come from an included file)\n", scad_path.c_str(),
                         what.c_str());
            continue;
        }
        throw InputError(scad_path, 0, 0, what);
    }
}

void runRender(const RenderOptions& o) {
    if (o.output.empty() && o.png.empty())
        throw InputError("nothing to write: give -o MODEL.stl|.3mf|.off|.amf and/or --png PREVIEW.png");
    if (o.imgsize.size() != 2 || o.imgsize[0] < 16 || o.imgsize[1] < 16 || o.imgsize[0] > 8192 || o.imgsize[1] > 8192)
        throw InputError("--imgsize expects WIDTH,HEIGHT in pixels, each 16..8192");
    ScadRenderRequest base;
    base.scad_path = o.scad;
    base.parameter_file = o.params;
    base.parameter_set = o.param_set;
    base.timeout_s = o.timeout_s;
    for (const std::string& d : o.defines) base.defines.push_back(parseScadDefine(d));
    base.png.width_px = o.imgsize[0];
    base.png.height_px = o.imgsize[1];
    base.png.camera = o.camera;

    checkDefineNames(o.scad, base.defines);

    ScadExportFormat format = ScadExportFormat::Stl;
    if (!o.output.empty() && !scadFormatForPath(o.output, format))
        throw InputError(o.output, 0, 0, "unknown output type: use .stl (binary), .3mf, .off, .amf or .png");
    if (!o.png.empty()) {
        ScadExportFormat png_format;
        if (!scadFormatForPath(o.png, png_format) || png_format != ScadExportFormat::Png)
            throw InputError(o.png, 0, 0, "--png needs a file name ending in .png");
    }

    std::unique_ptr<ScadEngine> engine;
    try {
        engine = makeOpenScadEngine(o.openscad);
    } catch (const ScadEngineMissing& e) {
        std::fprintf(stderr, "tsf: error: %s\n", e.what());
        throw CLI::RuntimeError(kExitToolFailed);
    }

    bool solid_ok = true;
    if (!o.output.empty()) {
        ScadRenderRequest rq = base;
        rq.output_path = o.output;
        rq.format = format;
        const ScadRenderResult r = renderOnce(*engine, rq, o, o.scad);
        if (!o.quiet)
            std::fprintf(stderr, "tsf: wrote %s (%s) in %s, peak memory %s\n", o.output.c_str(),
                         format == ScadExportFormat::Stl ? "binary STL" : toString(format), seconds(r.elapsed_s).c_str(),
                         megabytes(r.peak_memory_kb).c_str());
        if (!o.no_check && format != ScadExportFormat::Png && format != ScadExportFormat::Amf)
            solid_ok = checkExport(o.output, o.quiet);
    }
    if (!o.png.empty()) {
        ScadRenderRequest rq = base;
        rq.output_path = o.png;
        rq.format = ScadExportFormat::Png;
        std::unique_ptr<ImportWrapper> wrapper;
        std::string source_name = o.scad;
        if (!o.output.empty() && format != ScadExportFormat::Png) {
            // Picture the exported file itself; parameters are already applied.
            wrapper = std::make_unique<ImportWrapper>(o.output);
            rq.scad_path = wrapper->path();
            rq.defines.clear();
            rq.parameter_file.clear();
            rq.parameter_set.clear();
            source_name = "a picture of " + o.output;
        }
        const ScadRenderResult r = renderOnce(*engine, rq, o, source_name);
        if (!o.quiet) std::fprintf(stderr, "tsf: wrote %s in %s\n", o.png.c_str(), seconds(r.elapsed_s).c_str());
    }
    if (!solid_ok) throw CLI::RuntimeError(kExitCheckFailed);
}

}  // namespace

void addRenderCommand(CLI::App& app) {
    auto o = std::make_shared<RenderOptions>();
    CLI::App* cmd = app.add_subcommand("render", "Render an OpenSCAD file (e.g. from tsf gen --scad) to STL/3MF and a PNG preview");
    cmd->footer(
        "Examples:\n"
        "  tsf render model.scad -o model.stl\n"
        "  tsf render model.scad -o model.stl -D height=25 -D transfer=sqrt --png model.png\n"
        "  tsf render model.scad -o model.3mf -p model.json -P \"mirrored bottom\"\n"
        "STL is always binary (OpenSCAD's ASCII STL keeps only 6 significant digits). The exported\n"
        "mesh is read back and checked: a mesh that is not a closed, outward solid fails (exit 1).\n"
        "A PNG preview needs an X display; without one tsf runs OpenSCAD under xvfb-run.\n"
        "Exit codes: 0 ok, 1 the exported mesh is not a closed solid, 2 bad input (a parameter\n"
        "the model's asserts reject, a bad -D), 3 OpenSCAD missing, failed or timed out, 130 interrupted.");
    cmd->add_option("model", o->scad, "OpenSCAD file to render")->required();
    cmd->add_option("-o,--output", o->output, "Output: .stl (binary), .3mf, .off, .amf or .png");
    cmd->add_option("--png", o->png, "Also write a preview picture of the result (.png)");
    cmd->add_option("-D", o->defines,
                    "Override a parameter: NAME=VALUE, e.g. -D height=25 (repeatable; a bare word is a "
                    "string: -D transfer=log; NAME must be a variable the file assigns)");
    cmd->add_option("-p,--params", o->params, "OpenSCAD parameter-set file (.json, e.g. written by tsf gen --scad)");
    cmd->add_option("-P,--param-set", o->param_set, "Name of the parameter set to apply from --params");
    cmd->add_option("--openscad", o->openscad, "Path of the openscad program (default: openscad in PATH)");
    cmd->add_option("--engine", o->engine, "Rendering engine")->check(CLI::IsMember({"openscad"}))->capture_default_str();
    cmd->add_option("--timeout", o->timeout_s, "Stop OpenSCAD after this many seconds (0 = no limit)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--imgsize", o->imgsize, "PNG size in pixels: WIDTH,HEIGHT")->delimiter(',')->expected(2)->capture_default_str();
    cmd->add_option("--camera", o->camera,
                    "PNG camera as OpenSCAD --camera: translate x,y,z, rotate x,y,z (degrees), distance")
        ->capture_default_str();
    cmd->add_flag("--no-check", o->no_check, "Do not read the exported mesh back to check it is a closed solid");
    cmd->add_flag("-q,--quiet", o->quiet, "Print only errors");
    cmd->add_flag("-v,--verbose", o->verbose, "Print everything OpenSCAD prints");
    cmd->callback([o] { runRender(*o); });
}

}  // namespace tsf::cli
