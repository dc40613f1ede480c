// tsf_csg.scad - the terrain as a union of per-cell prisms (CGAL does the union).
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad, tsf_polyhedron.scad (for tsf_hull_base()).
//
// Every pillar is its own closed prism; OpenSCAD's CGAL union merges them.
// That is exact and tolerant of any shape added by hand, but slow: the union
// costs seconds per hundred cells in OpenSCAD 2021.01 (docs/openscad.md).
//
// Neighbouring prisms touch along whole wall faces. That is only safe because
// their shared corners are the same numbers to the last bit (rounded to 1 um
// from exact lattice coordinates, see tsf_model.scad): prisms whose corners
// differ by rounding noise (cylinder($fn = 6), rotate()) leave slivers and
// give an open, broken STL even when OpenSCAD reports "Simple: yes". On a flat
// base, pillars also sink into one shared slab (tsf_hull_base()).

// Module: tsf_hex_pillar()
// Usage:
//   tsf_hex_pillar(cell_mm, top_mm, [bottom_mm], [col], [row], [rows]);
// Description:
//   One hexagonal prism: cell (col, row) of a grid with `rows` rows, from
//   z = bottom_mm to z = top_mm. Its corners are the lattice corners rounded
//   to 1 um (tsf_cell_corners()), so pillars of neighbouring cells share
//   their corners exactly and union cleanly.
// Arguments:
//   cell_mm = distance between neighbouring centres (width across flats), mm (> 0).
//   top_mm = z of the top face, mm.
//   bottom_mm = z of the bottom face, mm (< top_mm). Default: 0.
//   col = column, 0 = west. Default: 0.
//   row = row, 0 = north. Default: 0.
//   rows = number of rows in the grid (row 0 is at the top). Default: 1.
// Example:
//   tsf_hex_pillar(cell_mm=10, top_mm=8);
// Example: Three neighbours of a two-row grid, touching exactly
//   for (cr = [[0, 0, 8], [1, 0, 4], [0, 1, 6]])
//       tsf_hex_pillar(cell_mm=10, top_mm=cr[2], col=cr[0], row=cr[1], rows=2);
module tsf_hex_pillar(cell_mm, top_mm, bottom_mm = 0, col = 0, row = 0, rows = 1) {
    assert(_tsf_is_finite(top_mm) && _tsf_is_finite(bottom_mm) && bottom_mm < top_mm,
           str("tsf_hex_pillar: need finite bottom_mm < top_mm (mm), got bottom_mm = ", bottom_mm, ", top_mm = ", top_mm));
    xy = tsf_cell_corners(col, row, rows, cell_mm);
    // Points 0..5: bottom ring, 6..11: top ring, both counter-clockwise from above.
    // Faces clockwise seen from outside, as polyhedron() requires.
    polyhedron(points = concat([for (p = xy) [p[0], p[1], bottom_mm]], [for (p = xy) [p[0], p[1], top_mm]]),
               faces = concat([[0, 1, 2, 3, 4, 5], [11, 10, 9, 8, 7, 6]],
                              [for (k = [0:5]) [k + 6, (k + 1) % 6 + 6, (k + 1) % 6, k]]));
}

// Module: tsf_terrain_csg()
// Usage:
//   tsf_terrain_csg(m);
// Description:
//   Draws the model made by tsf_model() as a union of one prism per present
//   cell (tsf_hex_pillar()). A flat-bottomed model is the slab
//   tsf_hull_base() plus a pillar from z = 0 for every cell that rises above
//   the floor; a mirrored model is the union of its pillars. The result is
//   the same solid as tsf_terrain_polyhedron() but takes CGAL time: use it
//   when you want to edit single pillars by hand (colour, move, replace).
// Arguments:
//   m = a model from tsf_model().
// Example:
//   m = tsf_model([[1, 3, 2], [2, 0, 1], [3, "nodata", 2]], cell_mm=10, max_height_mm=15, base_mm=2,
//                 value_max=3);
//   tsf_terrain_csg(m);
module tsf_terrain_csg(m) {
    model = _tsf_check_model(m, "tsf_terrain_csg");
    rows = model[1];
    cols = model[2];
    step = model[4];
    spans = model[5];
    floor_units = model[6];
    mirrored = model[7];
    union() {
        if (!mirrored) tsf_hull_base(model);
        for (r = [0:rows - 1], c = [0:cols - 1]) {
            s = spans[r][c];
            if (!is_undef(s) && !_tsf_is_marked(model[9], c, r) && (mirrored || s[1] > floor_units))
                tsf_hex_pillar(cell_mm = model[3], top_mm = s[1] * step, bottom_mm = s[0] * step,
                               col = c, row = r, rows = rows);
        }
        // The orientation marks: one closed prism per face (tsf_marks.scad).
        for (f = [0:1:len(model[8]) - 1])
            _tsf_polyhedron(_tsf_face_prism_points(model[8], f, spans, model[10], model[3], step));
    }
}
