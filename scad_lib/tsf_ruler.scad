// tsf_ruler.scad - the edge ruler: teeth at the foot of the model's south
// and west edges, every N columns and rows, so a reader counts them to say
// where a value is.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Used by files of the CSG strategy; the polyhedron strategy joins the teeth
// into the terrain's one polyhedron instead (tsf_joined.scad: no boolean).
//
// tsf places the teeth (gen/model/features/ruler/ruler.h, docs/model.md);
// the generated file carries them as data,
//   edge_ruler = [floor, top, [[footprint, ridge], ...]]
// in mm: each tooth is a collar over its footprint from 0 to floor (the
// base's top), its first corners the pillar's own corners it stands
// against, and a ridge over its ridge footprint from floor to top; every
// footprint is [[x, y], ...] counter-clockwise from above. Every number is
// the one tsf's own mesh uses, so the union is the same solid.

// Module: tsf_with_ruler()
// Usage:
//   tsf_with_ruler(edge_ruler, show_ruler) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the teeth. With show = false
//   (or no teeth) only the children.
// Arguments:
//   ruler = [floor, top, [[footprint, ridge], ...]] as written by tsf gen --ruler
//   show  = draw the teeth (default true)
// Example:
//   tsf_with_ruler([2, 3, [[[[0, 0], [0, 5], [-3, 5], [-3, 0]], [[-1, 5], [-3, 5], [-3, 0], [-1, 0]]]]])
//       cube([10, 10, 5]);
module tsf_with_ruler(ruler, show = true) {
    assert(is_list(ruler) && (len(ruler) == 0 || len(ruler) == 3),
           "tsf_with_ruler: ruler must be [floor, top, [[footprint, ridge], ...]] (or [] for none)");
    union() {
        children();
        if (show && len(ruler) == 3)
            for (t = ruler[2]) {
                _tsf_ruler_prism(t[0], 0, ruler[0]);
                _tsf_ruler_prism(t[1], ruler[0], ruler[1]);
            }
    }
}

// A prism over the footprint q (counter-clockwise from above) from z0 to z1,
// its top and bottom fanned from the second corner as tsf meshes them (it
// sees the whole footprint), every face a triangle so OpenSCAD keeps each
// corner as written.
module _tsf_ruler_prism(q, z0, z1) {
    n = len(q);
    polyhedron(points = concat([for (p = q) [p[0], p[1], z0]], [for (p = q) [p[0], p[1], z1]]),
               faces = concat([for (v = [2 : n - 1]) [1, v, (v + 1) % n]],
                              [for (v = [2 : n - 1]) [n + 1, n + (v + 1) % n, n + v]],
                              [for (v = [0 : n - 1]) each [[v, v + n, (v + 1) % n + n], [v, (v + 1) % n + n, (v + 1) % n]]]));
}
