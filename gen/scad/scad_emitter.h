// ScadEmitter: a Scene as a parametric, hand-editable OpenSCAD file.
//
// The file holds the model's parameters in customizer sections (Model size,
// Heights, Base, Mirror) with // [min:step:max] ranges, the cell values as a
// readable array (one row per line, north row first; undef = no pillar,
// nodata = a pillar at the floor) and one call into the tsf OpenSCAD library
// (scad_lib/, see gen/scad/scad_library.h). OpenSCAD recomputes every height
// from the values with the same rules as buildScene, so editing a value or a
// parameter and rendering again changes the model accordingly, and an
// unedited file renders to the same solid as meshScene(scene) (docs/openscad.md).
//
// Which cells are present is decided by tsf (hull culling) and written as
// data; the library never re-runs the hull.
//
// Files written by writeScad(scene, opts, "dir/name.scad"):
//   dir/name.scad   the model;
//   dir/name.json   OpenSCAD parameter sets ("as generated", "layer steps 0.2 mm",
//                   "mirrored bottom", "half size"), used by the GUI's customizer and by
//                   openscad -p dir/name.json -P "<set>";
//   dir/tsf_lib/    a copy of the library, only when inline_library is false.
// Every file is written atomically (gen/util/atomic_file.h).
#pragma once

#include <string>
#include <vector>

#include "gen/model/scene.h"

namespace tsf {

struct ScadOptions {
    /// How the library draws the terrain (docs/openscad.md has the measured trade).
    enum class Strategy {
        Polyhedron,  ///< one closed polyhedron() built from the values: seconds for 10^4 cells (default)
        Csg,         ///< union of one prism per cell, done by CGAL: exact, editable per pillar, minutes
    };
    Strategy strategy = Strategy::Polyhedron;
    /// true: paste the library parts the strategy needs at the end of the file
    /// (one self-contained file); false: copy the library to dir/tsf_lib/ and
    /// use<> it.
    bool inline_library = true;
    /// Write dir/name.json with parameter sets beside the file.
    bool write_parameter_sets = true;
    std::string source;       ///< input file named in the header ("" = not named)
    std::string command;      ///< the tsf command line that made the file, for the header ("" = none)
    std::string library_dir;  ///< folder of scad_lib; "" = scadLibraryDir()
};

/// Name of the folder the library is copied to when it is not inlined.
inline constexpr const char* kScadLibraryCopyDir = "tsf_lib";

/// Text of the .scad file for `scene`. A Scene with tilted or dimpled tops (gen/model/features/top_shapes.h)
/// is written with its resolved tops (`tops`, scad_lib/tsf_tilt.scad) and
/// drawn as one polyhedron whatever the strategy. file_name (e.g. "model.scad") is used in
/// the header's render commands and to name the parameter-set file. Reads the
/// library text when inline_library is set. Throws InputError for an empty
/// Scene (no kept cell) and std::runtime_error when the library is missing.
std::string emitScad(const Scene& scene, const ScadOptions& opts, const std::string& file_name);

/// Text of the parameter-set JSON for `scene` (OpenSCAD's format: every value a string).
std::string emitScadParameterSets(const Scene& scene);

/// Writes path (.scad) and the files beside it listed in the file comment,
/// each atomically. Throws InputError when path does not end in .scad, for an
/// unusable folder or an empty Scene, std::runtime_error for I/O failures.
void writeScad(const Scene& scene, const ScadOptions& opts, const std::string& path);

/// True when `json_text` is a parameter-set file holding only sets tsf
/// writes (emitScadParameterSets), so replacing it loses nothing the user
/// saved: no set added in OpenSCAD's customizer, no other kind of JSON.
bool isTsfParameterSetFile(const std::string& json_text);

/// The paths writeScad(scene, opts, path) writes, the .scad first.
std::vector<std::string> scadOutputPaths(const ScadOptions& opts, const std::string& path);

/// Names of the parameters in the customizer, in file order. They are the
/// names of tsf gen's options (cell, height, transfer, baseline, value_max,
/// snap, base, mirror), so `tsf gen --height 25` and `-D height=25` mean the same.
std::vector<std::string> scadParameterNames();

/// "polyhedron" / "csg" (also the CLI spellings).
const char* toString(ScadOptions::Strategy strategy);
/// Parses "polyhedron" or "csg"; false for anything else.
bool parseScadStrategy(const std::string& text, ScadOptions::Strategy& strategy);

}  // namespace tsf
