// tsf_scale.scad - the tactile scale: a staircase east of the pillars whose
// treads stand at the printed heights of round values, on a foot whose top is
// the floor, so a reader measures a pillar in value units.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Used by files of the CSG strategy; the polyhedron strategy joins the scale
// into the terrain's one polyhedron instead (tsf_joined.scad: no boolean).
//
// tsf chooses the step and places the staircase (gen/model/features/scale.h, docs/model.md);
// the generated file carries it as data,
//   tactile_scale = [[x0, xs, x1], [y0, y1], foot_top, [[y_south, y_north, top], ...],
//                    [[[x, y] x 4], ...]]
// in mm: the foot is the box [x0, x1] x [y0, y1] x [0, foot_top], its west
// face against the pillars' easternmost walls; each step is the box
// [xs, x1] x [y_south, y_north] x [0, top]; each quadrilateral (corners
// counter-clockwise) is a notch of the hexagon outline between two walls the
// foot touches, filled from 0 to foot_top. Every number is the one tsf's own
// mesh uses, so the union is the same solid.

// Module: tsf_with_scale()
// Usage:
//   tsf_with_scale(tactile_scale) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the scale. With show = false
//   (or an empty scale) only the children.
// Arguments:
//   scale = [[x0, xs, x1], [y0, y1], foot_top, steps, notches] as written by tsf gen --scale
//   show  = draw the scale (default true)
// Example:
//   tsf_with_scale([[10, 12, 20], [0, 9], 2, [[0, 3, 4], [3, 6, 6], [6, 9, 8]], []]) cube([10, 9, 5]);
module tsf_with_scale(scale, show = true) {
    assert(is_list(scale) && (len(scale) == 0 || len(scale) == 5),
           "tsf_with_scale: scale must be [[x0, xs, x1], [y0, y1], foot_top, steps, notches] (or [] for none)");
    union() {
        children();
        if (show && len(scale) == 5) {
            x = scale[0];
            y = scale[1];
            _tsf_box(x[0], y[0], 0, x[2], y[1], scale[2]);
            for (st = scale[3]) _tsf_box(x[1], st[0], 0, x[2], st[1], st[2]);
            for (q = scale[4])
                polyhedron(points = concat([for (p = q) [p[0], p[1], 0]], [for (p = q) [p[0], p[1], scale[2]]]),
                           faces = [[0, 1, 2, 3], [4, 7, 6, 5], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);
        }
    }
}

// The box [x0, x1] x [y0, y1] x [z0, z1] with exactly these coordinates
// (translate() + cube() would add and subtract them, which can round).
module _tsf_box(x0, y0, z0, x1, y1, z1) {
    polyhedron(points = [[x0, y0, z0], [x1, y0, z0], [x1, y1, z0], [x0, y1, z0],
                         [x0, y0, z1], [x1, y0, z1], [x1, y1, z1], [x0, y1, z1]],
               faces = [[0, 1, 2, 3], [4, 7, 6, 5], [0, 4, 5, 1], [1, 5, 6, 2], [2, 6, 7, 3], [3, 7, 4, 0]]);
}
