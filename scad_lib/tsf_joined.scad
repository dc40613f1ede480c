// tsf_joined.scad - bodies beside the pillars (the orientation tab, the
// braille legend's plate, the tactile scale) joined into the terrain's one
// polyhedron, the way tsf's direct mesher joins them: no union, so OpenSCAD
// runs no CGAL operation and keeps every corner as written.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad, tsf_polyhedron.scad, tsf_tilt.scad.
//
// tsf places each body and writes it as data (docs/openscad.md, "Attachments"):
//   attachment = [walls, points, corners, triangles]
//   walls     = [[col, row, edge, bottom, top], ...]: the body stands against
//               edge `edge` (0..5, as in tsf_model.scad) of pillar (col, row)
//               from z step `bottom` to `top`; the pillar's wall is not drawn
//               there, and the wall's corner lines are split at both heights;
//   points    = [[x, y, z], ...] in mm: the body's own vertices;
//   corners   = [[i, j, z], ...]: the body's vertices on a contact's corner,
//               in lattice units and z steps, computed here exactly like the
//               pillars' corners, so the two share these vertices to the bit;
//   triangles = [[a, b, c], ...] counter-clockwise seen from outside; an
//               index below len(points) is a point, the others are corners
//               (index - len(points)).
// The body is open where it meets the pillars: the pillars' walls around a
// contact and the body's faces close the surface together. [] is no body
// (an attachment hidden with its customizer switch).
//
// The contacts are data: a pillar whose value is edited keeps its wall above
// and below a body it touches, at its new height. A pillar must still span
// the contact (and the cell across it stay absent); the library checks that
// and says which cell it is.

// ---------------------------------------------------------------------------
// Private helpers.

// The triangles of the cells that touch a contact's corner and of the joined
// bodies, as a flat list of points (three per triangle, counter-clockwise
// from outside). `mask` (per row, the columns) is what the other passes
// draw: faces; the cells listed by _tsf_joined_cells() are drawn here.
function _tsf_joined_points(model, spans, shapes, joined) =
    let(rows = model[1], cols = model[2], cell_mm = model[3], step_mm = model[4],
        bodies = [for (a = joined) if (len(a) == 4) a],
        feet = [for (a = bodies) each a[0]],
        offsets = _tsf_corner_offsets(),
        // The lattice corners of every contact, each with its z span.
        foot_corners = [for (f = feet) let(c = _tsf_centre_ij(f[0], f[1], rows))
                           for (e = [f[2], (f[2] + 1) % 6]) [c[0] + offsets[e][0], c[1] + offsets[e][1], f[3], f[4]]],
        // Keys for search() (the built-in, fast): a lattice corner, a cell's edge.
        corner_keys = [for (q = foot_corners) _tsf_corner_key(q, cols)],
        edge_keys = [for (f = feet) (f[1] * cols + f[0]) * 6 + f[2]],
        bad = [for (f = feet) if (!_tsf_foot_holds(f, model, spans, shapes)) f],
        cells = _tsf_joined_cells(feet, rows, cols, spans, model[9]))
    assert(len(bad) == 0,
           str("tsf_terrain_polyhedron: an attachment stands against edge ", bad[0][2], " of the pillar in row ",
               bad[0][1], ", column ", bad[0][0], " from z step ", bad[0][3], " to ", bad[0][4],
               ", which that pillar no longer holds (or the cell beside it is no longer empty):",
               " hide the attachment with its customizer switch, or run tsf gen again"))
    concat([for (p = cells) let(c = p[0], r = p[1], s = spans[r][c], cc = _tsf_centre_ij(c, r, rows),
                                ij = [for (d = offsets) [cc[0] + d[0], cc[1] + d[1]]],
                                xy = [for (q = ij) _tsf_lattice_xy(q, cell_mm)],
                                own = [for (e = [0:5]) _tsf_corner_span(spans, shapes, c, r, e)],
                                real = [for (k = [0:5]) let(n = _tsf_neighbour(c, r, k))
                                           [_tsf_corner_span(spans, shapes, n[0], n[1], (k + 4) % 6),
                                            _tsf_corner_span(spans, shapes, n[0], n[1], (k + 3) % 6)]],
                                // Where nothing stands across an edge, a body may: its span covers the wall there.
                                nb = [for (k = [0:5]) let(at_k = is_undef(real[k][0]) ? search((r * cols + c) * 6 + k, edge_keys, 0) : [])
                                         len(at_k) == 0 ? real[k] : [[feet[at_k[0]][3], feet[at_k[0]][4]], [feet[at_k[0]][3], feet[at_k[0]][4]]]],
                                at = [for (e = [0:5]) [each own[e], each (is_undef(real[e][0]) ? [] : real[e][0]),
                                                       each (is_undef(real[(e + 5) % 6][1]) ? [] : real[(e + 5) % 6][1]),
                                                       for (n = search(_tsf_corner_key(ij[e], cols), corner_keys, 0))
                                                           each [foot_corners[n][2], foot_corners[n][3]]]])
                   for (t = _tsf_shaped_cell_triangles(xy, _tsf_lattice_xy(cc, cell_mm), s, own, nb, at, _tsf_at(shapes, c, r),
                                                       cell_mm, step_mm))
                       each t],
           [for (a = bodies) let(at = concat(a[1], [for (q = a[2]) let(p = _tsf_lattice_xy(q, cell_mm)) [p[0], p[1], q[2] * step_mm]]))
               for (t = a[3]) each [at[t[0]], at[t[1]], at[t[2]]]]);

// The cells drawn by _tsf_joined_points(): every present cell with a corner
// on a contact (the cell itself and its neighbours across the contact's edge
// and the two edges beside it), not drawn by a face; [[col, row], ...].
function _tsf_joined_cells(feet, rows, cols, spans, faces_mask) =
    let(near = [for (f = feet) for (k = [5, 0, 1]) _tsf_neighbour(f[0], f[1], (f[2] + k) % 6)],
        all = concat([for (f = feet) [f[0], f[1]]], near),
        all_rows = [for (p = all) p[1]])
    [for (r = [0:rows - 1]) let(in_row = search(r, all_rows, 0)) if (len(in_row) > 0)
        for (c = _tsf_sorted_unique([for (n = in_row) let(p = all[n]) if (p[0] >= 0 && p[0] < cols) p[0]]))
            if (!is_undef(spans[r][c]) && !_tsf_is_marked(faces_mask, c, r)) [c, r]];

// The same cells as a mask (per row, the columns), for the other passes to leave out.
function _tsf_joined_mask(model, spans, joined) =
    let(feet = [for (a = joined) if (len(a) == 4) each a[0]],
        cells = _tsf_joined_cells(feet, model[1], model[2], spans, model[9]))
    [for (r = [0:model[1] - 1]) concat(len(model[9]) > r ? model[9][r] : [], [for (p = cells) if (p[1] == r) p[0]])];

// A number for lattice corner [i, j] of a grid `cols` wide (i < 2 cols + 2).
function _tsf_corner_key(q, cols) = q[1] * (2 * cols + 2) + q[0];

// True when contact f = [col, row, edge, bottom, top] still holds: its
// pillar is present, not drawn by a face, spans [bottom, top] at both ends of
// the edge, and the cell across the edge is empty.
function _tsf_foot_holds(f, model, spans, shapes) =
    let(n = _tsf_neighbour(f[0], f[1], f[2]))
    !is_undef(_tsf_at(spans, f[0], f[1])) && !_tsf_is_marked(model[9], f[0], f[1]) &&
    is_undef(_tsf_at(spans, n[0], n[1])) &&
    _tsf_covers(_tsf_corner_span(spans, shapes, f[0], f[1], f[2]), f[3], f[4]) &&
    _tsf_covers(_tsf_corner_span(spans, shapes, f[0], f[1], (f[2] + 1) % 6), f[3], f[4]);

// True when span s (z steps) holds [bottom, top].
function _tsf_covers(s, bottom, top) = !is_undef(s) && s[0] <= bottom && top <= s[1];

// [x, y] (mm, rounded to 1 um) of lattice point [i, j]: the same expression as every pillar corner.
function _tsf_lattice_xy(p, cell_mm) = [_tsf_snap_xy(_tsf_lattice_x(p[0], cell_mm)), _tsf_snap_xy(_tsf_lattice_y(p[1], cell_mm))];
