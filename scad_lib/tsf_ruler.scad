// tsf_ruler.scad - the edge ruler: teeth on the bed along the model's south
// and west edges, every N columns and rows, so a reader counts them to say
// where a value is.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Used by files of the CSG strategy; the polyhedron strategy joins the teeth
// into the terrain's one polyhedron instead (tsf_joined.scad: no boolean).
//
// tsf places the teeth (gen/model/features/ruler/ruler.h, docs/model.md);
// the generated file carries them as data,
//   edge_ruler = [top, [[[x, y], ...], ...]]
// in mm: each tooth is its footprint, counter-clockwise from above, raised
// from 0 to top (the floor). Its first corners are the pillar's own corners
// it stands against; every number is the one tsf's own mesh uses, so the
// union is the same solid.

// Module: tsf_with_ruler()
// Usage:
//   tsf_with_ruler(edge_ruler, show_ruler) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the teeth. With show = false
//   (or no teeth) only the children.
// Arguments:
//   ruler = [top, footprints] as written by tsf gen --ruler
//   show  = draw the teeth (default true)
// Example:
//   tsf_with_ruler([2, [[[0, 0], [0, 5], [-2, 5], [-2, 0]]]]) cube([10, 10, 5]);
module tsf_with_ruler(ruler, show = true) {
    assert(is_list(ruler) && (len(ruler) == 0 || len(ruler) == 2),
           "tsf_with_ruler: ruler must be [top, [[[x, y], ...], ...]] (or [] for none)");
    union() {
        children();
        if (show && len(ruler) == 2)
            for (t = ruler[1]) _tsf_ruler_tooth(t, ruler[0]);
    }
}

// A prism over the footprint q (counter-clockwise from above) from 0 to top,
// its top and bottom fanned from the second corner as tsf meshes them (it
// sees the whole footprint), every face a triangle so OpenSCAD keeps each
// corner as written.
module _tsf_ruler_tooth(q, top) {
    n = len(q);
    polyhedron(points = concat([for (p = q) [p[0], p[1], 0]], [for (p = q) [p[0], p[1], top]]),
               faces = concat([for (v = [2 : n - 1]) [1, v, (v + 1) % n]],
                              [for (v = [2 : n - 1]) [n + 1, n + (v + 1) % n, n + v]],
                              [for (v = [0 : n - 1]) each [[v, v + n, (v + 1) % n + n], [v, (v + 1) % n + n, (v + 1) % n]]]));
}
