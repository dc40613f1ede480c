// tsf_polyhedron.scad - the whole terrain as ONE closed polyhedron().
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad.
//
// The surface is built from the data in OpenSCAD's own language, the same
// way tsf's direct mesher builds it:
//   - a top hexagon and a bottom hexagon for every present cell;
//   - a wall along an edge only where the neighbour's z span does not cover
//     this cell's span (where heights differ, and on the outer rim);
//   - every wall side is split at every height that meets its corner line,
//     so no vertex of one face lies inside an edge of another (no
//     T-junctions), and all faces are triangles with positive area.
// Corners are computed once per lattice point and rounded to 1 um, heights
// are whole z steps, so a point shared by several faces is the same number in
// each. No CGAL operation is needed, which is why this is fast: OpenSCAD
// 2021.01 renders a 100 x 100 grid in seconds, where a union of prisms takes
// minutes (docs/openscad.md).
//
// Face winding: OpenSCAD wants polyhedron faces CLOCKWISE seen from outside
// (the opposite of STL). The triangles below are made counter-clockwise from
// outside, like tsf's meshes, and reversed in one place when handed to
// polyhedron(); a wrong winding gives an inside-out STL without a warning.

// Module: tsf_terrain_polyhedron()
// Usage:
//   tsf_terrain_polyhedron(m);
// Description:
//   Draws the model made by tsf_model() as one closed polyhedron: the union
//   of all its pillars, with no internal faces. Fast, and exact: the
//   exported STL is the same solid as the one tsf writes directly. Adding
//   or subtracting other shapes still works (OpenSCAD then runs CGAL on the
//   result, which is slower).
// Arguments:
//   m      = a model from tsf_model().
//   joined = bodies tsf placed beside the pillars, each [walls, points,
//            corners, triangles] or [] (hidden), joined into the same
//            polyhedron through the pillars' own corners (tsf_joined.scad).
//            Default: none.
// Example:
//   m = tsf_model([[1, 3, 2], [2, 0, 1], [3, "nodata", 2]], cell_mm=10, max_height_mm=15, base_mm=2,
//                 value_max=3, z_step_mm=0.2);
//   tsf_terrain_polyhedron(m);
// Example: Mirrored bottom
//   m = tsf_model([[1, 3, 2], [2, 0, 1], [3, undef, 2]], cell_mm=10, max_height_mm=15, base_mm=2,
//                 value_max=3, mirrored=true);
//   tsf_terrain_polyhedron(m);
module tsf_terrain_polyhedron(m, joined = []) {
    model = _tsf_check_model(m, "tsf_terrain_polyhedron");
    assert(is_list(joined), str("tsf_terrain_polyhedron: joined must be a list of attachments written by tsf, got ", joined));
    _tsf_polyhedron(_tsf_model_points(model, model[5], model[10], model[11], joined));
}

// Module: tsf_hull_base()
// Usage:
//   tsf_hull_base(m);
// Description:
//   The slab under the model: every present cell from z = 0 up to the floor
//   (base_mm of the model), or to its top where that is lower (the pit of a
//   cell without data), as one closed polyhedron. Its outline is the
//   outline of the present cells, i.e. the hull that tsf kept. The CSG
//   strategy stands its pillars in this slab; on its own it is a base plate
//   to build on by hand.
// Arguments:
//   m = a model from tsf_model().
// Example:
//   m = tsf_model([[undef, 1, 1], [1, 1, 1], [undef, 1, undef]], cell_mm=10, max_height_mm=5, base_mm=2,
//                 value_max=1);
//   tsf_hull_base(m);
module tsf_hull_base(m) {
    model = _tsf_check_model(m, "tsf_hull_base");
    slab = [for (row = model[5]) [for (s = row) is_undef(s) ? undef : [0, min(s[1], model[6])]]];
    _tsf_polyhedron(_tsf_model_points(model, slab, 0, []));
}

// ---------------------------------------------------------------------------
// Private helpers.

// Triangles as a flat list of points, three per triangle, counter-clockwise
// from outside, handed to polyhedron(), whose faces must be clockwise from
// outside: reversed here. The faces are listed in chunks of
// _tsf_range_chunk(): OpenSCAD (2021.01 and 2025) refuses a range of more
// than a million elements ("too many elements"), and a 300 x 300 grid has
// 1.6 million triangles.
module _tsf_polyhedron(points) {
    assert(len(points) > 0, "tsf: the model has no present cell");
    n = len(points) / 3;
    chunk = _tsf_range_chunk();
    polyhedron(points = points,
               faces = [for (c = [0:chunk:n - 1])
                            for (k = [c:min(c + chunk, n) - 1]) [3 * k + 2, 3 * k + 1, 3 * k]],
               convexity = 10);
}

// Elements per range in long lists (see _tsf_polyhedron); a function, as
// the library defines no top-level variables.
function _tsf_range_chunk() = 500000;

// The boundary of a model whose cells have the given spans: plain cells as
// hexagons, the cells of the marks' faces (model[8], tsf_marks.scad) through
// those faces, the triangle raised by raise_units; with shapes (tsf_tilt.scad)
// tilted and dimpled tops as tsf resolved them; with joined bodies
// (tsf_joined.scad) the cells they touch and the bodies.
function _tsf_model_points(model, spans, raise_units, shapes, joined = []) =
    let(mask = len(joined) > 0 ? _tsf_joined_mask(model, spans, joined) : model[9])
    concat(len(shapes) > 0 ? _tsf_shaped_span_points(model[1], model[2], model[3], model[4], spans, shapes, mask)
                           : _tsf_span_points(model[1], model[2], model[3], model[4], spans, mask),
           len(joined) > 0 ? _tsf_joined_points(model, spans, shapes, joined) : [],
           [for (f = [0:1:len(model[8]) - 1])
               each _tsf_face_points(model[8], f, spans, raise_units, model[3], model[4], shapes, model[1])]);

// The boundary of the union of the prisms spans[row][col] = [bottom, top]
// (z steps) or undef, as triangles counter-clockwise from outside, in a flat
// list of points [x, y, z], three per triangle (no list per triangle: a
// 100 x 100 grid has 160 000 of them). Neighbouring spans must overlap by at
// least one step. Cells listed in mask (tsf_marks_cells) are left to their faces.
function _tsf_span_points(rows, cols, cell_mm, step_mm, spans, mask) =
    let(xs = [for (i = [0:2 * cols + 1]) _tsf_snap_xy(_tsf_lattice_x(i, cell_mm))],
        ys = [for (j = [0:3 * rows + 1]) _tsf_snap_xy(_tsf_lattice_y(j, cell_mm))],
        offsets = _tsf_corner_offsets())
    [for (r = [0:rows - 1]) let(cj = 3 * (rows - 1 - r) + 2, odd = r % 2)
        for (c = [0:cols - 1]) let(s = spans[r][c]) if (!is_undef(s) && !_tsf_is_marked(mask, c, r))
            let(ci = 2 * c + odd + 1,
                xy = [for (d = offsets) [xs[ci + d[0]], ys[cj + d[1]]]],
                nb = [for (k = [0:5]) let(n = _tsf_neighbour(c, r, k)) _tsf_at(spans, n[0], n[1])])
            for (t = _tsf_cell_triangles(xy, s, nb, step_mm)) each t];

// Faces owned by one cell: top, bottom and its outward walls.
//   xy = its 6 corners [x, y] (mm); s = [bottom, top] (steps);
//   nb = spans of its 6 neighbours (undef = absent).
function _tsf_cell_triangles(xy, s, nb, step_mm) =
    let(zb = s[0] * step_mm, zt = s[1] * step_mm,
        t = [for (p = xy) [p[0], p[1], zt]],
        b = [for (p = xy) [p[0], p[1], zb]])
    concat([for (e = [2:5]) [t[0], t[e - 1], t[e]]],   // top, counter-clockwise from above
           [for (e = [2:5]) [b[0], b[e], b[e - 1]]],   // bottom, counter-clockwise from below
           [for (k = [0:5]) let(n = nb[k])
               for (piece = is_undef(n) ? [s] : concat(n[1] < s[1] ? [[n[1], s[1]]] : [],
                                                        s[0] < n[0] ? [[s[0], n[0]]] : []))
                   each _tsf_wall_triangles(xy[k], xy[(k + 1) % 6], piece[0], piece[1],
                                            nb[(k + 5) % 6], nb[(k + 1) % 6], step_mm)]);

// A vertical wall from corner pl to corner pr (counter-clockwise around the
// cell that owns it, so its outward normal is (pr - pl) x up), from z0 to z1
// (steps). Its sides carry every height of the third cell at that corner
// (left_third, right_third: a span or undef) that lies strictly inside.
// Two fans: from the lower-left point over the right side, then from the
// upper-right point over the left side; no triangle has three collinear points.
function _tsf_wall_triangles(pl, pr, z0, z1, left_third, right_third, step_mm) =
    _tsf_wall_triangles_at(pl, pr, z0, z1, is_undef(left_third) ? [] : left_third,
                           is_undef(right_third) ? [] : right_third, step_mm);

// The same with every height that meets each corner line given as a list
// (duplicates and heights outside (z0, z1) are ignored).
function _tsf_wall_triangles_at(pl, pr, z0, z1, left_heights, right_heights, step_mm) =
    let(zl = concat([z0], _tsf_sorted_unique([for (z = left_heights) if (z > z0 && z < z1) z]), [z1]),
        zr = concat([z0], _tsf_sorted_unique([for (z = right_heights) if (z > z0 && z < z1) z]), [z1]),
        L = [for (z = zl) [pl[0], pl[1], z * step_mm]],
        R = [for (z = zr) [pr[0], pr[1], z * step_mm]],
        nl = len(L), nr = len(R))
    concat([for (i = [0:nr - 2]) [L[0], R[i], R[i + 1]]],
           [for (j = [0:nl - 2]) [R[nr - 1], L[j + 1], L[j]]]);

// Ascending list of the distinct numbers of a short list.
function _tsf_sorted_unique(v) =
    len(v) == 0 ? []
    : let(m = min(v)) concat([m], _tsf_sorted_unique([for (x = v) if (x > m) x]));
