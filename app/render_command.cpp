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

#include "app/commands.h"
#include "gen/util/error.h"
#include "runners/openscad/engine_output_check.h"
#include "runners/openscad/engine_select.h"
#include "runners/openscad/openscad_runner.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/mesh/mesh_picture.h"
#include "gen/scad/scad_variables.h"
#include "gen/util/rgb_image.h"
#include "gen/util/output_paths.h"
#include "gen/util/temp_files.h"
#include "gen/util/number_format.h"

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
    std::string engine = "auto";
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

std::string seconds(double s) { return formatFixed(s, s < 10 ? 2 : 1) + " s"; }

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

// One render. source_name: what to call the input in messages (the model, or
// the mesh a preview is drawn from). check (may be null): read the output
// back and refuse a mesh that is not a solid (renderScadChecked). Prints the
// failure and returns the result; the caller decides what a failure means.
ScadRenderResult renderOnce(const ScadEngine& engine, const ScadRenderRequest& rq, const RenderOptions& o,
                            const std::string& source_name, EngineOutputCheck* check) {
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
    EngineOutputExpectation expect;
    expect.solid_checks = true;
    const ScadRenderResult r =
        check ? renderScadChecked(engine, rq, progress, expect, check) : renderScad(engine, rq, progress);
    if (!r.ok()) {
        std::fprintf(stderr, "tsf: error: %s: %s\n", source_name.c_str(), r.summary.c_str());
        printMessages(r, o.verbose);
    } else if (o.verbose) {
        printMessages(r, true);
    } else if (!o.quiet) {
        printMessages(r, false);
    }
    return r;
}

// A failure another engine might not have: the engine crashed, failed
// without saying why in an assert or a syntax error, or wrote a broken mesh.
bool worthAnotherEngine(const ScadRenderResult& r) {
    return r.status == ScadRenderResult::Status::Failed && failureExitCode(r) == kExitToolFailed;
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
    explicit ImportWrapper(const std::string& mesh_path) : file_("tsf-preview-", ".scad") {
        std::ofstream out(file_.path());
        // The same warm colour as tsf gen --preview: steps between pillars show clearly.
        out << "color(\"#e8a33d\") import(" << scadString(fs::absolute(mesh_path).string()) << ", convexity = 10);\n";
        if (!out) throw std::runtime_error("cannot write " + file_.path());
    }
    ImportWrapper(const ImportWrapper&) = delete;
    ImportWrapper& operator=(const ImportWrapper&) = delete;
    const std::string& path() const { return file_.path(); }

private:
    ScopedTempFile file_;  // removed on every exit, signals included
};

std::string readText(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A -D for a variable the file does not assign would be added silently and
// change nothing; refuse it (only warn when the file includes others, whose
// variables we do not read).
void checkDefineNames(const std::string& scad_path, const std::vector<ScadDefine>& defines) {
    if (defines.empty()) return;
    const std::string text = readText(scad_path);  // unreadable: renderScad reports it
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
    checkOutputPaths({{o.scad, "the model to render"}, {o.params, "the parameter file (-p)"}},
                     {{o.output, "-o"}, {o.png, "--png"}});
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

    if (!o.output.empty()) {
        EngineChoice choice = EngineChoice::Auto;
        parseEngineChoice(o.engine, choice);
        const ScadFileFacts facts = scadFileFacts(readText(o.scad));
        std::string why;
        std::unique_ptr<ScadEngine> engine;
        try {
            engine = selectEngine(choice, facts.strategy, o.openscad, &why, facts.cells);
        } catch (const ScadEngineMissing& e) {
            std::fprintf(stderr, "tsf: error: %s\n", e.what());
            throw CLI::RuntimeError(kExitToolFailed);
        }
        if (!o.quiet && choice == EngineChoice::Auto) std::fprintf(stderr, "tsf: engine %s\n", why.c_str());
        if (!engine->supports(format)) {
            // The WebAssembly engine cannot write 3MF or PNG; the desktop one can.
            std::unique_ptr<ScadEngine> other =
                choice == EngineChoice::Auto ? otherEngine(*engine, o.openscad, &why) : nullptr;
            if (!other || !other->supports(format))
                throw InputError(o.output, 0, 0, engine->name() + " cannot export " + toString(format) + " files");
            engine = std::move(other);
        }
        ScadRenderRequest rq = base;
        rq.output_path = o.output;
        rq.format = format;
        EngineOutputCheck check;
        EngineOutputCheck* checking = o.no_check ? nullptr : &check;
        ScadRenderResult r = renderOnce(*engine, rq, o, o.scad, checking);
        if (!r.ok() && worthAnotherEngine(r) && choice == EngineChoice::Auto) {
            if (std::unique_ptr<ScadEngine> other = otherEngine(*engine, o.openscad, &why);
                other && other->supports(format)) {
                if (!o.quiet) std::fprintf(stderr, "tsf: trying the other engine: %s\n", why.c_str());
                engine = std::move(other);
                r = renderOnce(*engine, rq, o, o.scad, checking);
            }
        }
        if (!r.ok()) {
            if (!o.no_check && check.checked && !check.ok)
                std::fprintf(stderr, "tsf: nothing was written to %s; render with --no-check to keep the mesh for "
                                     "'tsf verify'\n", o.output.c_str());
            throw CLI::RuntimeError(failureExitCode(r));
        }
        if (!o.quiet) {
            std::fprintf(stderr, "tsf: wrote %s (%s) in %s, peak memory %s\n", o.output.c_str(),
                         format == ScadExportFormat::Stl ? "binary STL" : toString(format), seconds(r.elapsed_s).c_str(),
                         megabytes(r.peak_memory_kb).c_str());
            if (check.checked)
                std::fprintf(stderr,
                             "tsf: %s: %zu triangles, closed, manifold, outward, one piece, no self-intersections; "
                             "volume %.6g mm^3\n",
                             o.output.c_str(), check.triangles, check.volume_mm3);
        }
    }
    const std::string out_ext = lowerCaseExtension(o.output);
    if (!o.png.empty() && o.camera == kDefaultPngCamera &&
        (out_ext == ".stl" || out_ext == ".3mf" || out_ext == ".off")) {
        // The exported file, drawn by tsf as tsf gen --preview draws it:
        // framed, coloured by height, north and scale, the underside too.
        const Mesh mesh = readMesh(o.output);
        MeshPictureOptions po;
        po.width_px = o.imgsize[0];
        po.height_px = o.imgsize[1];
        po.underside = hasRaisedUnderside(mesh);
        writePng(o.png, drawMeshPicture(mesh, po));
        if (!o.quiet) std::fprintf(stderr, "tsf: wrote %s\n", o.png.c_str());
    } else if (!o.png.empty()) {
        // A camera of the user's (or no exported mesh): OpenSCAD draws it; only
        // the desktop OpenSCAD can (pictures need OpenGL).
        std::unique_ptr<ScadEngine> engine;
        try {
            engine = makeOpenScadEngine(o.openscad);
        } catch (const ScadEngineMissing& e) {
            std::fprintf(stderr, "tsf: error: %s\n", e.what());
            throw CLI::RuntimeError(kExitToolFailed);
        }
        ScadRenderRequest rq = base;
        rq.output_path = o.png;
        rq.format = ScadExportFormat::Png;
        std::unique_ptr<ImportWrapper> wrapper;
        std::string source_name = o.scad;
        if (!o.output.empty() && format != ScadExportFormat::Png) {
            // Picture the exported file itself; parameters are already applied.
            wrapper = std::make_unique<ImportWrapper>(o.output);
            rq.scad_path = wrapper->path();
            if (out_ext == ".stl" || out_ext == ".3mf" || out_ext == ".off") {
                const Bounds b = meshBounds(readMesh(o.output));
                rq.png.camera = cameraLookingAt(rq.png.camera, (b.min.x + b.max.x) / 2, (b.min.y + b.max.y) / 2,
                                                (b.min.z + b.max.z) / 2);
            }
            rq.defines.clear();
            rq.parameter_file.clear();
            rq.parameter_set.clear();
            source_name = "a picture of " + o.output;
        }
        const ScadRenderResult r = renderOnce(*engine, rq, o, source_name, nullptr);
        if (!r.ok()) throw CLI::RuntimeError(failureExitCode(r));
        if (!o.quiet) std::fprintf(stderr, "tsf: wrote %s in %s\n", o.png.c_str(), seconds(r.elapsed_s).c_str());
    }
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
        "mesh is read back and checked: a mesh that is not a closed, outward solid is not written.\n"
        "A PNG preview needs an X display; without one tsf runs OpenSCAD under xvfb-run.\n"
        "Exit codes: 0 ok, 2 bad input (a parameter the model's asserts reject, a bad -D),\n"
        "3 OpenSCAD missing, failed, timed out or wrote a broken mesh, 130 interrupted.");
    cmd->add_option("model", o->scad, "OpenSCAD file to render")->required();
    cmd->add_option("-o,--output", o->output, "Output: .stl (binary), .3mf, .off, .amf or .png");
    cmd->add_option("--png", o->png,
                    "Also write a preview picture of the result (.png): framed, coloured by height, north arrow, "
                    "scale bar, and the underside of a mirrored model");
    cmd->add_option("-D", o->defines,
                    "Override a parameter: NAME=VALUE, e.g. -D height=25 (repeatable; a bare word is a "
                    "string: -D transfer=log; NAME must be a variable the file assigns)");
    cmd->add_option("-p,--params", o->params, "OpenSCAD parameter-set file (.json, e.g. written by tsf gen --scad)");
    cmd->add_option("-P,--param-set", o->param_set, "Name of the parameter set to apply from --params");
    cmd->add_option("--openscad", o->openscad, "Path of the openscad program (default: openscad in PATH)");
    cmd->add_option("--engine", o->engine,
                    "auto: the fastest installed engine for the model (see docs/engines.md) | openscad: the desktop "
                    "OpenSCAD | wasm: OpenSCAD 2025 (Manifold) under Node.js; PNG previews always use the desktop one")
        ->check(CLI::IsMember({"auto", "openscad", "wasm"}))
        ->capture_default_str();
    cmd->add_option("--timeout", o->timeout_s, "Stop OpenSCAD after this many seconds (0 = no limit)")
        ->check(CLI::NonNegativeNumber)
        ->capture_default_str();
    cmd->add_option("--imgsize", o->imgsize, "PNG size in pixels: WIDTH,HEIGHT")->delimiter(',')->expected(2)->capture_default_str();
    cmd->add_option("--camera", o->camera,
                    "PNG camera as OpenSCAD --camera: translate x,y,z, rotate x,y,z (degrees), distance (mm; "
                    "0 = frame the model), or eye x,y,z, centre x,y,z. Given, OpenSCAD draws the picture; by "
                    "default tsf draws the exported model like tsf gen --preview")
        ->capture_default_str();
    cmd->add_flag("--no-check", o->no_check,
                  "Do not read the exported mesh back to check it is a closed solid (keeps a broken mesh for tsf verify)");
    cmd->add_flag("-q,--quiet", o->quiet, "Print only errors");
    cmd->add_flag("-v,--verbose", o->verbose, "Print everything OpenSCAD prints");
    cmd->callback([o] { runRender(*o); });
}

}  // namespace tsf::cli
