// What a feature adds to a generated OpenSCAD file, in one shape the emitter
// (gen/scad/scad_emitter.h) writes without knowing which feature it is: the
// feature's data (its customizer switch and the solid tsf placed, for its
// scad_lib/ module), the library file that draws it, an argument to
// tsf_model() and either the attachment the terrain polyhedron joins
// (the polyhedron strategy: one polyhedron, no boolean) or the module call
// that wraps the terrain (the CSG strategy: a union; the halves: a cut).
#pragma once

#include <string>

namespace tsf {

struct ScadAttachment {
    std::string library_file;    ///< its scad_lib/ file: "tsf_scale.scad"
    std::string data;            ///< its customizer section and data, ending in a blank line
    std::string model_argument;  ///< appended to the tsf_model() call ("" none)
    std::string call_prefix;     ///< "tsf_with_half(...) ": wraps the terrain call ("" none)
    /// Joined into the terrain polyhedron instead (scad_lib/tsf_joined.scad):
    /// the expression handed to tsf_terrain_polyhedron(joined = [...]),
    /// "show_scale ? tactile_scale : []"; "" when it is not.
    std::string joined;
    /// The customizer switch that shows it, on in the "as generated"
    /// parameter set and off in the others (it stands where tsf placed it
    /// for the parameters as generated); "" when it has none to turn off.
    std::string placed_switch;
};

}  // namespace tsf
