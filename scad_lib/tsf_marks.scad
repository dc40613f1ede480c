// tsf_marks.scad - the orientation marks: pieces of the footprint ("faces")
// that replace the plain hexagons of the cells a mark touches.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad.
//
// tsf places two marks (docs/model.md, "Orientation marks"):
//   - a V NOTCH cut through the whole height at the model's origin (south-
//     west) corner: where x and y start;
//   - a raised right TRIANGLE on the largest flat region: its right angle is
//     its south-west corner, the longer leg runs east (+x), the shorter north
//     (+y), so a reader can tell x from y and the model's handedness.
// Where they go is decided once by tsf and written into the generated file as
// `marks`, a list of faces. tsf_model() takes them (faces = marks), and
// tsf_terrain_polyhedron() / tsf_terrain_csg() draw each face instead of the
// hexagons it covers, with the heights of the current values and parameters.
// So the marks follow the customizer (cell, height, snap, mirror, ...) and
// the rendered solid is the same as tsf's own mesh. `marks = []` leaves them out.
//
// A face is
//   [anchor, raised, points, triangles, rings, across, at, cells]
//   anchor    = [col, row]: the cell whose z span the face has;
//   raised    = true for the triangle: its top is raised by mark_height_mm;
//   points    = [[i, j], ...] in lattice units (x = i * cell / 2,
//               y = j * cell / (2 sqrt 3)), rounded to 1 um like every corner;
//   triangles = [[a, b, c], ...] indices into points, counter-clockwise from above;
//   rings     = boundary loops (indices into points), the face on the left;
//   across    = per ring, per edge: what lies across it: undef (nothing),
//               [col, row] (a plain cell) or [f] (face number f of the list);
//   at        = per point: every cell [col, row] and face [f] that has that
//               point as a corner (their heights split the walls there);
//   cells     = the cells [col, row] this face replaces.

// ---------------------------------------------------------------------------
// Private helpers.

// z span [bottom, top] (steps) of face f of `faces` for the given spans.
function _tsf_face_span(faces, f, spans, raise_units) =
    let(face = faces[f], s = spans[face[0][1]][face[0][0]])
    face[1] ? [s[0], s[1] + raise_units] : s;

// The span of a reference: [col, row] = a cell, [f] = a face, undef = nothing.
function _tsf_ref_span(ref, faces, spans, raise_units) =
    is_undef(ref) ? undef : len(ref) == 1 ? _tsf_face_span(faces, ref[0], spans, raise_units) : spans[ref[1]][ref[0]];

// The span of a reference at face point p ([i, j], lattice units): a plain
// cell's span at its corner there when its top is shaped (tsf_tilt.scad).
function _tsf_ref_span_at(ref, p, faces, spans, raise_units, shapes, rows) =
    is_undef(ref) || len(ref) == 1 || len(shapes) == 0 ? _tsf_ref_span(ref, faces, spans, raise_units)
    : let(c = _tsf_centre_ij(ref[0], ref[1], rows), d = [p[0] - c[0], p[1] - c[1]],
          e = [for (k = [0:5]) if (_tsf_corner_offsets()[k] == d) k])
      len(e) == 1 ? _tsf_corner_span(spans, shapes, ref[0], ref[1], e[0]) : _tsf_ref_span(ref, faces, spans, raise_units);

// [x, y] (mm, rounded to 1 um) of a point in lattice units.
function _tsf_face_xy(p, cell_mm) = [_tsf_snap_xy(p[0] * cell_mm * 0.5), _tsf_snap_xy(p[1] * cell_mm / (2 * sqrt(3)) * _tsf_y_scale())];

// Every triangle of face f (top, bottom, walls), counter-clockwise from
// outside, as a flat list of points (three per triangle). shapes: the
// model's shaped tops or [] (rows: the grid's rows, to find their corners).
function _tsf_face_points(faces, f, spans, raise_units, cell_mm, step_mm, shapes = [], rows = 0) =
    let(face = faces[f],
        s = _tsf_face_span(faces, f, spans, raise_units),
        zb = s[0] * step_mm, zt = s[1] * step_mm,
        xy = [for (p = face[2]) _tsf_face_xy(p, cell_mm)],
        heights = [for (i = [0:len(face[6]) - 1])
                      [for (ref = face[6][i]) each _tsf_ref_span_at(ref, face[2][i], faces, spans, raise_units, shapes, rows)]])
    concat([for (t = face[3]) each [[xy[t[0]][0], xy[t[0]][1], zt], [xy[t[1]][0], xy[t[1]][1], zt],
                                    [xy[t[2]][0], xy[t[2]][1], zt]]],
           [for (t = face[3]) each [[xy[t[0]][0], xy[t[0]][1], zb], [xy[t[2]][0], xy[t[2]][1], zb],
                                    [xy[t[1]][0], xy[t[1]][1], zb]]],
           [for (r = [0:len(face[4]) - 1]) let(ring = face[4][r], n = len(ring))
               for (k = [0:n - 1]) let(a = ring[k], b = ring[(k + 1) % n], ref = face[5][r][k])
                   each (len(shapes) == 0
                         ? [let(o = _tsf_ref_span(ref, faces, spans, raise_units))
                            for (piece = is_undef(o) ? [s] : concat(o[1] < s[1] ? [[o[1], s[1]]] : [],
                                                                    s[0] < o[0] ? [[s[0], o[0]]] : []))
                                for (t = _tsf_wall_triangles_at(xy[a], xy[b], piece[0], piece[1], heights[a], heights[b],
                                                                step_mm))
                                    each t]
                         // A tilted neighbour never crosses a face (tsf clamps it): no crossing points.
                         : [for (t = _tsf_edge_walls(xy[a], xy[b], s, s,
                                                     _tsf_ref_span_at(ref, face[2][a], faces, spans, raise_units, shapes, rows),
                                                     _tsf_ref_span_at(ref, face[2][b], faces, spans, raise_units, shapes, rows),
                                                     undef, undef, heights[a], heights[b], cell_mm, step_mm))
                                each t])]);

// Face f as a closed prism on its own (for the CSG strategy): its top and
// bottom triangles and one plain wall per ring edge over its whole span.
function _tsf_face_prism_points(faces, f, spans, raise_units, cell_mm, step_mm) =
    let(face = faces[f],
        s = _tsf_face_span(faces, f, spans, raise_units),
        xy = [for (p = face[2]) _tsf_face_xy(p, cell_mm)],
        solo = [for (r = face[4]) [for (k = r) undef]])
    _tsf_face_points([[face[0], face[1], face[2], face[3], face[4], solo, [for (p = face[2]) []], face[7]]], 0,
                     [for (r = [0:len(spans) - 1]) [for (c = [0:len(spans[r]) - 1]) r == face[0][1] && c == face[0][0] ? s : undef]],
                     0, cell_mm, step_mm);
