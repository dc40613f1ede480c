// Rendering .scad files with an OpenSCAD engine: STL (binary), 3MF, OFF, AMF
// or a PNG preview, with a time limit, progress, and OpenSCAD's own error
// lines in the result.
//
// ScadEngine is the seam for more than one OpenSCAD: the desktop binary
// (makeOpenScadEngine, OpenSCAD 2021.01 on Debian 12) today; a WebAssembly
// build run under node can implement the same interface later. An engine
// turns one ScadRenderRequest into one run of the program; renderScad() adds
// what every engine needs (checks on the inputs, an atomic output file, an
// output that is not empty).
//
// A run that prints an ERROR line is a failure even when OpenSCAD exits with
// status 0 (OpenSCAD 2025 exports what is left after a failed assert()).
//
// Never trust the engine's verdict on the mesh: OpenSCAD may report success
// for a broken union. Check the STL (runners/openscad/engine_output_check.h, tsf
// verify) before printing.
#pragma once

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "runners/openscad/openscad_messages.h"

namespace tsf {

enum class ScadExportFormat { Stl, ThreeMf, Off, Amf, Png };

/// The format for an output file by its extension (.stl, .3mf, .off, .amf,
/// .png; case-insensitive). Returns false for anything else.
bool scadFormatForPath(const std::string& path, ScadExportFormat& format);
const char* toString(ScadExportFormat format);  ///< "stl", "3mf", "off", "amf", "png"
/// OpenSCAD's --export-format name: as toString, but "binstl" (STL is always binary).
const char* exportFormatArg(ScadExportFormat format);

/// One -D override: OpenSCAD expression text assigned to a top-level variable.
struct ScadDefine {
    std::string name;
    std::string value;
};

/// Parses "name=value". name must be an OpenSCAD identifier; value is
/// OpenSCAD expression text (25, true, [1, 2], "log"). A bare word that is
/// not true, false or undef is taken as a string: transfer=log -> "log".
/// Throws InputError with the text when it is not of that form.
ScadDefine parseScadDefine(const std::string& text);

/// Camera for PNG previews (OpenSCAD --camera: translate x,y,z, rotate x,y,z
/// in degrees, distance; distance 0 lets --autocenter and --viewall frame
/// the model): seen from the south-south-west, 35 degrees above the horizon.
inline constexpr const char* kDefaultPngCamera = "0,0,0,55,0,25,0";

/// The OpenSCAD framing flags that go with `camera` (--camera text): seven
/// values with distance 0 -> {"--autocenter", "--viewall"} (OpenSCAD frames
/// the model); otherwise (a distance, or the six-value eye,centre form) none:
/// the camera is taken exactly as given.
std::vector<std::string> cameraFramingFlags(const std::string& camera);

/// `camera` with its translate set to (x, y, z) mm when it is the seven-value
/// form with translate 0,0,0 and a distance: the camera looks at that point
/// (the model's centre) from the distance given. Otherwise unchanged.
std::string cameraLookingAt(const std::string& camera, double x, double y, double z);

struct PngView {
    int width_px = 1024;
    int height_px = 768;
    std::string camera = kDefaultPngCamera;
};

struct ScadRenderRequest {
    std::string scad_path;
    std::string output_path;
    ScadExportFormat format = ScadExportFormat::Stl;  ///< STL is always binary
    std::vector<ScadDefine> defines;                   ///< -D, in order
    std::string parameter_file;                        ///< -p ("" = none)
    std::string parameter_set;                         ///< -P (needs parameter_file)
    double timeout_s = 0;                              ///< 0 = no limit
    double progress_interval_s = 5.0;
    PngView png;
};

struct ScadRenderResult {
    enum class Status { Ok, Failed, TimedOut, Interrupted };
    Status status = Status::Failed;
    std::string summary;               ///< one line for people: what happened
    double elapsed_s = 0;
    long peak_memory_kb = 0;           ///< the engine process's peak resident memory
    std::vector<std::string> command;  ///< the program and its arguments as run
    std::vector<ScadMessage> messages; ///< parsed from the engine's output
    std::string output;                ///< the engine's whole console output

    bool ok() const { return status == Status::Ok; }
    /// ERROR lines and the TRACE lines after them (what to show on failure).
    std::vector<ScadMessage> errors() const;
    std::vector<ScadMessage> warnings() const;
};

/// Called every progress_interval_s while the engine runs.
using ScadProgress = std::function<void(double elapsed_s, const std::string& last_line)>;

/// A program that renders .scad files.
class ScadEngine {
public:
    virtual ~ScadEngine() = default;
    virtual std::string name() const = 0;        ///< "openscad"
    virtual std::string version() const = 0;     ///< e.g. "OpenSCAD version 2021.01"
    virtual std::string executable() const = 0;  ///< what runs (a path)
    virtual bool supports(ScadExportFormat format) const = 0;
    /// One run writing request.output_path directly. Does not check inputs;
    /// use renderScad().
    virtual ScadRenderResult run(const ScadRenderRequest& request, const ScadProgress& progress) const = 0;
};

/// A program (or a helper it needs, such as xvfb-run) is not installed.
class ScadEngineMissing : public std::runtime_error {
public:
    using std::runtime_error::runtime_error;
};

/// The desktop OpenSCAD. binary: a path, or a name looked up in PATH
/// ("" = "openscad"). Runs `openscad --version` once. Throws ScadEngineMissing
/// with an install hint when it is not there or does not run.
std::unique_ptr<ScadEngine> makeOpenScadEngine(const std::string& binary = "");

struct ProcessResult;

/// For ScadEngine implementations: runs an engine's command line with the
/// request's timeout and progress reporting, and fills what every engine's
/// result shares (command, elapsed time, peak memory, output, parsed
/// messages). `process` receives how the process ended, which each engine
/// interprets itself (its own exit codes).
ScadRenderResult runEngineProcess(const std::vector<std::string>& argv, const ScadRenderRequest& request,
                                  const ScadProgress& progress, ProcessResult& process);

/// For ScadEngine implementations: sets r.status and r.summary (one line for
/// people) from how the engine process ended. An ERROR line fails the render
/// even with exit status 0 (OpenSCAD 2025 exports partial models). `engine`
/// names the engine in the summary; `explain_exit` may describe an
/// engine-specific non-zero exit code ("" = the generic message).
void finishEngineResult(ScadRenderResult& r, const ProcessResult& process, const ScadRenderRequest& request,
                        const std::string& engine, const std::function<std::string(int exit_code)>& explain_exit = {});

/// Renders request through engine:
///   - throws InputError when the .scad file cannot be read, the format is
///     not supported, or parameter_set is not a set in parameter_file (OpenSCAD
///     itself silently ignores an unknown set);
///   - runs the engine into a temporary file beside output_path and renames it
///     over output_path only on success (a failed run leaves an existing
///     file untouched and no partial file);
///   - an engine exit code 0 with no output file, or an empty one, is a failure.
ScadRenderResult renderScad(const ScadEngine& engine, const ScadRenderRequest& request,
                            const ScadProgress& progress = {});

/// Does this OpenSCAD binary have the Manifold backend, i.e. does
/// `executable --help` list --backend with a Manifold option? (OpenSCAD
/// 2021.01 rejects --backend=manifold; nightlies since late 2024 and the 2025
/// builds accept it.) False when it cannot be run. Runs the binary once.
bool openScadHasManifoldBackend(const std::string& executable);

}  // namespace tsf
