// tsf_tab.scad - the orientation tab: a flat plate west of the pillars whose
// south-west corner is cut by the orientation notch and whose top carries the
// handedness triangle (on a mirrored model its underside too), so every model
// can be oriented by touch whatever its data (docs/model.md, "Orientation marks").
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
//
// tsf places the tab (gen/model/features/tab/orientation_tab.h) against the
// westernmost hexagon walls of the pillars. A file of the polyhedron strategy
// joins it into the terrain's one polyhedron (tsf_joined.scad: no boolean);
// a file of the CSG strategy writes it as data,
//   orientation_tab = [points, triangles]
// the closed body tsf's own mesh has (mm; each triangle counter-clockwise
// seen from outside, as tsf's meshes are): every corner is the one tsf's mesh
// uses, and every face a triangle, so OpenSCAD takes each corner as written
// (a polygon face it tessellated itself would have its corners moved to its
// 2^-20 mm grid) and the union with the pillars is the same solid.

// Module: tsf_with_tab()
// Usage:
//   tsf_with_tab(orientation_tab) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the tab. With show = false
//   (or an empty tab) only the children.
// Arguments:
//   tab  = [points, triangles] as written by tsf gen
//   show = draw the tab (default true)
// Example:
//   box = [[-20, 0, 0], [0, 0, 0], [0, 15, 0], [-20, 15, 0], [-20, 0, 2], [0, 0, 2], [0, 15, 2], [-20, 15, 2]];
//   tris = [[0, 2, 1], [0, 3, 2], [4, 5, 6], [4, 6, 7], [0, 1, 5], [0, 5, 4],
//           [1, 2, 6], [1, 6, 5], [2, 3, 7], [2, 7, 6], [3, 0, 4], [3, 4, 7]];
//   tsf_with_tab([box, tris]) cube([10, 15, 5]);
module tsf_with_tab(tab, show = true) {
    assert(is_list(tab) && (len(tab) == 0 || len(tab) == 2),
           "tsf_with_tab: tab must be [points, triangles] (or [] for none)");
    union() {
        children();
        // polyhedron() wants each face clockwise seen from outside.
        if (show && len(tab) == 2) polyhedron(points = tab[0], faces = [for (t = tab[1]) [t[0], t[2], t[1]]]);
    }
}
