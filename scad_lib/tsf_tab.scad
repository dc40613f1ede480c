// tsf_tab.scad - the orientation tab: a flat plate west of the pillars, from
// the bed to the floor, whose south-west corner is cut by the orientation
// notch and whose top carries the handedness triangle, so every model can be
// oriented by touch whatever its data (docs/model.md, "Orientation marks").
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
//
// tsf places the tab (gen/model/features/orientation_tab.h); the generated
// file carries it as data,
//   orientation_tab = [[[x, y], ...], top, [[x, y] x 3], triangle_top,
//                      bottom, triangle_bottom]
// in mm: the plate is the outline (counter-clockwise, the notch's V part of
// it) extruded from bottom to top (a flat model: 0 to the floor; a mirrored
// one: the band its pillars share); its east edge follows the westernmost
// hexagon walls of the pillars it stands against, so the union with the
// pillars is one solid; the triangle (right angle first, then its east and
// north ends; [] when the model has none) stands from top to triangle_top
// and, when triangle_bottom < bottom (mirrored), hangs from bottom to
// triangle_bottom. Every number is the one tsf's own mesh uses, so the union
// is the same solid.

// Module: tsf_with_tab()
// Usage:
//   tsf_with_tab(orientation_tab) tsf_terrain_polyhedron(model);
// Description:
//   The union of the children (the pillars) and the tab. With show = false
//   (or an empty tab) only the children.
// Arguments:
//   tab  = [outline, top, triangle, triangle_top, bottom, triangle_bottom] as
//          written by tsf gen (the last two may be left out: 0 and 0)
//   show = draw the tab (default true)
// Example:
//   tsf_with_tab([[[-20, 0], [0, 0], [0, 15], [-20, 15]], 2, [[-17, 3], [-5, 3], [-17, 10]], 3]) cube([10, 15, 5]);
module tsf_with_tab(tab, show = true) {
    assert(is_list(tab) && (len(tab) == 0 || len(tab) == 4 || len(tab) == 6),
           "tsf_with_tab: tab must be [outline, top, triangle, triangle_top, bottom, triangle_bottom] (or [] for none)");
    bottom = len(tab) == 6 ? tab[4] : 0;
    union() {
        children();
        if (show && len(tab) >= 4) {
            _tsf_prism(tab[0], bottom, tab[1]);
            if (len(tab[2]) == 3) {
                _tsf_prism(tab[2], tab[1], tab[3]);
                if (len(tab) == 6 && tab[5] < bottom) _tsf_prism(tab[2], tab[5], bottom);
            }
        }
    }
}

// The polygon `outline` ([x, y] counter-clockwise) from z0 to z1, with
// exactly these coordinates (linear_extrude() would add z0 to them, which can
// round). Faces run clockwise seen from outside, as polyhedron() wants.
module _tsf_prism(outline, z0, z1) {
    n = len(outline);
    polyhedron(points = concat([for (p = outline) [p[0], p[1], z0]], [for (p = outline) [p[0], p[1], z1]]),
               faces = concat([[for (k = [0:n - 1]) k]], [[for (k = [n - 1:-1:0]) n + k]],
                              [for (k = [0:n - 1]) [k, n + k, n + (k + 1) % n, (k + 1) % n]]));
}
