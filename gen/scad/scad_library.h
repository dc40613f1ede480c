// The tsf OpenSCAD library (scad_lib/ in the source tree, share/tsf/scad_lib
// when installed): where it is and how to read it.
//
// Generated .scad files either paste the parts of the library they need or
// use<> a copy of it written beside them (gen/scad/scad_emitter.h); either
// way the text comes from this folder, so a model always matches the
// library version of the tsf that wrote it.
#pragma once

#include <string>
#include <vector>

namespace tsf {

/// Entry file of the library: include<>s every part (tsf_model.scad, ...).
inline constexpr const char* kScadLibraryEntry = "tsf.scad";

/// The folder holding tsf.scad. Looked up, first match wins:
///   1. $TSF_SCAD_LIB (must hold tsf.scad, else an error: the user asked for it);
///   2. <folder of the tsf executable>/../share/tsf/scad_lib (installed);
///   3. <source tree>/scad_lib (the build tree's TSF_SOURCE_DIR).
/// Throws std::runtime_error naming the places looked in when none holds it.
std::string scadLibraryDir();

/// Every file of the library folder (names, not paths; *.scad, sorted).
/// Throws std::runtime_error when the folder cannot be read.
std::vector<std::string> scadLibraryFiles(const std::string& library_dir);

/// Text of one library file. Throws std::runtime_error when it cannot be read.
std::string readScadLibraryFile(const std::string& library_dir, const std::string& name);

}  // namespace tsf
