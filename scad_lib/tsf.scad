// tsf.scad - OpenSCAD library for tsf's hexagonal pillar models.
//
// Usage:
//   use <tsf.scad>          // or a path to it, e.g. use <tsf_lib/tsf.scad>
//   m = tsf_model(values, cell_mm=5, max_height_mm=20, base_mm=2, value_max=10);
//   tsf_terrain_polyhedron(m);     // fast, one closed polyhedron
//   // or: tsf_terrain_csg(m);     // union of prisms, rendered by CGAL (slow)
//
// Contents (each module and public function has a doc block where it is defined):
//   tsf_model.scad       tsf_model(), tsf_height_mm(), tsf_snap_units(), tsf_cell_corners(),
//                        tsf_flat_spans(), tsf_mirrored_spans(), tsf_model_spans(),
//                        tsf_model_z_step(), tsf_model_size(), tsf_marks_cells()
//   tsf_polyhedron.scad  tsf_terrain_polyhedron(), tsf_hull_base()
//   tsf_csg.scad         tsf_hex_pillar(), tsf_terrain_csg()
//   tsf_marks.scad       drawing of the orientation marks (notch, triangle) that tsf places
//   tsf_tilt.scad        drawing of tilted tops and dimpled structural cells that tsf resolves
//   tsf_legend.scad      tsf_with_legend(): the braille legend plate that tsf meshes
//   tsf_scale.scad       tsf_with_scale(): the tactile scale that tsf places
//   tsf_ruler.scad       tsf_with_ruler(): the edge ruler's teeth that tsf places
//   tsf_tab.scad         tsf_with_tab(): the orientation tab (notch and triangle) that tsf places
//   tsf_halves.scad      tsf_half(): a mirrored model's support-free halves with pin holes
//
// Names starting with _tsf are private. The library defines no variables, so
// it adds nothing to the OpenSCAD customizer. See docs/openscad.md in the tsf
// source tree for the model, the strategies and their measured cost.
include <tsf_model.scad>
include <tsf_polyhedron.scad>
include <tsf_csg.scad>
include <tsf_marks.scad>
include <tsf_tilt.scad>
include <tsf_legend.scad>
include <tsf_scale.scad>
include <tsf_ruler.scad>
include <tsf_tab.scad>
include <tsf_joined.scad>
include <tsf_halves.scad>
