// tsf_legend.scad - the braille legend: a plate grown north of the pillars
// with the title and the value range embossed in domed braille dots.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Used by files of the CSG strategy; the polyhedron strategy joins the legend plate
// into the terrain's one polyhedron instead (tsf_joined.scad: no boolean).
//
// tsf lays the legend out (liblouis braille, NLS Specification 800 dot
// sizes; docs/printing.md) and meshes the plate with its dots; the generated
// file carries that solid as data, `legend_plate = [points, faces]` (mm,
// faces clockwise seen from outside, as polyhedron() wants them), so OpenSCAD
// draws exactly the dots tsf's own mesh has. The plate's top is the floor of
// a flat model (base_mm); it fills the culled corners and the notches of the
// outline north of the pillars and stands against their walls (it never
// overlaps them), and the union joins it to them.

// Module: tsf_with_legend()
// Usage:
//   tsf_with_legend(legend_plate) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the legend plate. With
//   show = false (or an empty plate) only the children.
// Arguments:
//   plate = [points, faces] as written by tsf gen --title/--units
//   show  = draw the legend (default true)
// Example:
//   plate = [[[0, 0, 0], [10, 0, 0], [10, 5, 0], [0, 5, 0], [0, 0, 2], [10, 0, 2], [10, 5, 2], [0, 5, 2]],
//            [[0, 1, 2, 3], [4, 5, 1, 0], [7, 6, 5, 4], [5, 6, 2, 1], [6, 7, 3, 2], [7, 4, 0, 3]]];
//   tsf_with_legend(plate) translate([0, -8, 0]) cube([10, 10, 4]);
module tsf_with_legend(plate, show = true) {
    assert(is_list(plate) && (len(plate) == 0 || len(plate) == 2),
           "tsf_with_legend: plate must be [points, faces] (or [] for none)");
    union() {
        children();
        if (show && len(plate) == 2) polyhedron(points = plate[0], faces = plate[1], convexity = 4);
    }
}
