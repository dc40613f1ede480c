// tsf_tilt.scad - shaped pillar tops: tilted tops and the dimples of
// structural cells, as tsf resolved them (docs/model.md, "Tilt" and
// "Structural cells").
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad, tsf_polyhedron.scad.
//
// tsf decides every tilt once (the regression plane or gradient, the
// steepness, the clamp at the floor, where neighbouring tops cross) and
// writes the result as data, `tops`, which tsf_model() takes as `shapes`.
// tsf_terrain_polyhedron() then draws every cell the way tsf's direct mesher
// does, so the rendered solid is the same as tsf's own:
//   - a shaped top is a fan of triangles from its centre over its corners
//     and the crossing points on its edges;
//   - a wall is the part of a cell's span that its neighbour's span does not
//     cover, taken at both ends of the edge (tops are straight along an
//     edge); where two tops cross, the wall is a triangle on each side of
//     the crossing point, which is a vertex of both tops.
// The data hold for the values and parameters tsf wrote: run tsf gen again
// to change them (the generated file asserts this).
//
// shapes[row][col] = undef (a level hexagon) or
//   [top_dz, top_centre_dz, bottom_dz, bottom_centre_dz, cross_top, cross_bottom]
//   top_dz           = 6 numbers: z of corner k of the top minus the cell's top (z steps);
//   top_centre_dz    = z of the top's centre minus the cell's top (< 0: a dimple);
//   bottom_dz, bottom_centre_dz = the same for a mirrored bottom ([] and 0 for a flat bottom);
//   cross_top[k]     = undef, or [i, j, z]: where this top crosses its
//                      neighbour's along edge k (lattice units, z steps);
//   cross_bottom[k]  = the same for mirrored bottoms.
// Corners k and edges k as in tsf_model.scad (edge k joins corners k and k + 1).

// ---------------------------------------------------------------------------
// Private helpers.

// Span [bottom, top] (z steps) of cell (c, r) at its corner e; undef when absent.
function _tsf_corner_span(spans, shapes, c, r, e) =
    let(s = _tsf_at(spans, c, r))
    is_undef(s) ? undef
    : let(sh = _tsf_at(shapes, c, r))
      is_undef(sh) ? s : [s[0] + (len(sh[2]) > 0 ? sh[2][e] : 0), s[1] + sh[0][e]];

// [x, y] (mm, rounded to 1 um) of a crossing [i, j, z].
function _tsf_cross_xy(x, cell_mm) = [_tsf_snap_xy(x[0] * cell_mm * 0.5), _tsf_snap_xy(x[1] * cell_mm / (2 * sqrt(3)) * _tsf_y_scale())];

// A vertical wall from pl to pr (counter-clockwise around its owner) from
// zl0 to zl1 at pl and zr0 to zr1 at pr (z steps; a side may be one point);
// each side carries the heights of lh / rh that lie strictly inside it.
// Two fans, as _tsf_wall_triangles_at().
function _tsf_sloped_wall(pl, pr, zl0, zl1, zr0, zr1, lh, rh, step_mm) =
    let(zl = zl0 == zl1 ? [zl0] : concat([zl0], _tsf_sorted_unique([for (z = lh) if (z > zl0 && z < zl1) z]), [zl1]),
        zr = zr0 == zr1 ? [zr0] : concat([zr0], _tsf_sorted_unique([for (z = rh) if (z > zr0 && z < zr1) z]), [zr1]),
        L = [for (z = zl) [pl[0], pl[1], z * step_mm]],
        R = [for (z = zr) [pr[0], pr[1], z * step_mm]],
        nl = len(L), nr = len(R))
    concat([for (i = [0:1:nr - 2]) [L[0], R[i], R[i + 1]]],
           [for (j = [0:1:nl - 2]) [R[nr - 1], L[j + 1], L[j]]]);

// The walls of an edge pv -> pw whose owner spans av, aw at its ends and
// whose neighbour spans bv, bw (undef: no neighbour); xt, xb = the crossing
// of the tops / bottoms on this edge or undef; hv, hw = every height at each end.
function _tsf_edge_walls(pv, pw, av, aw, bv, bw, xt, xb, hv, hw, cell_mm, step_mm) =
    is_undef(bv) ? _tsf_sloped_wall(pv, pw, av[0], av[1], aw[0], aw[1], hv, hw, step_mm)
    : let(dv = av[1] - bv[1], dw = aw[1] - bw[1], ev = bv[0] - av[0], ew = bw[0] - aw[0])
      concat(dv >= 0 && dw >= 0 ? (dv > 0 || dw > 0 ? _tsf_sloped_wall(pv, pw, bv[1], av[1], bw[1], aw[1], hv, hw, step_mm) : [])
             : dv > 0 ? _tsf_sloped_wall(pv, _tsf_cross_xy(xt, cell_mm), bv[1], av[1], xt[2], xt[2], hv, [], step_mm)
             : dw > 0 ? _tsf_sloped_wall(_tsf_cross_xy(xt, cell_mm), pw, xt[2], xt[2], bw[1], aw[1], [], hw, step_mm)
             : [],
             ev >= 0 && ew >= 0 ? (ev > 0 || ew > 0 ? _tsf_sloped_wall(pv, pw, av[0], bv[0], aw[0], bw[0], hv, hw, step_mm) : [])
             : ev > 0 ? _tsf_sloped_wall(pv, _tsf_cross_xy(xb, cell_mm), av[0], bv[0], xb[2], xb[2], hv, [], step_mm)
             : ew > 0 ? _tsf_sloped_wall(_tsf_cross_xy(xb, cell_mm), pw, xb[2], xb[2], aw[0], bw[0], [], hw, step_mm)
             : []);

// The boundary of a model with shapes, like _tsf_span_points() (same
// arguments, and shapes): every present cell not left to a face.
function _tsf_shaped_span_points(rows, cols, cell_mm, step_mm, spans, shapes, mask) =
    let(xs = [for (i = [0:2 * cols + 1]) _tsf_snap_xy(_tsf_lattice_x(i, cell_mm))],
        ys = [for (j = [0:3 * rows + 1]) _tsf_snap_xy(_tsf_lattice_y(j, cell_mm))],
        offsets = _tsf_corner_offsets())
    [for (r = [0:rows - 1]) let(cj = 3 * (rows - 1 - r) + 2, odd = r % 2)
        for (c = [0:cols - 1]) let(s = spans[r][c]) if (!is_undef(s) && !_tsf_is_marked(mask, c, r))
            let(ci = 2 * c + odd + 1,
                xy = [for (d = offsets) [xs[ci + d[0]], ys[cj + d[1]]]],
                own = [for (e = [0:5]) _tsf_corner_span(spans, shapes, c, r, e)],
                // The neighbour across edge k at this cell's corners k and k + 1.
                nb = [for (k = [0:5]) let(n = _tsf_neighbour(c, r, k))
                         [_tsf_corner_span(spans, shapes, n[0], n[1], (k + 4) % 6),
                          _tsf_corner_span(spans, shapes, n[0], n[1], (k + 3) % 6)]],
                // Every height at corner e: this cell's and the two neighbours' that share it.
                at = [for (e = [0:5]) [each own[e], each (is_undef(nb[e][0]) ? [] : nb[e][0]),
                                       each (is_undef(nb[(e + 5) % 6][1]) ? [] : nb[(e + 5) % 6][1])]])
            for (t = _tsf_shaped_cell_triangles(xy, [xs[ci], ys[cj]], s, own, nb, at, shapes[r][c], cell_mm, step_mm))
                each t];

// Top, bottom and outward walls of one cell (see _tsf_shaped_span_points()).
function _tsf_shaped_cell_triangles(xy, centre, s, own, nb, at, sh, cell_mm, step_mm) =
    let(top = is_undef(sh)
            ? let(t = [for (p = xy) [p[0], p[1], s[1] * step_mm]]) [for (e = [2:5]) [t[0], t[e - 1], t[e]]]
            : _tsf_fan([centre[0], centre[1], (s[1] + sh[1]) * step_mm],
                       _tsf_ring(xy, [for (e = [0:5]) own[e][1]], sh[4], cell_mm, step_mm), true),
        bottom = is_undef(sh) || len(sh[2]) == 0
            ? let(b = [for (p = xy) [p[0], p[1], s[0] * step_mm]]) [for (e = [2:5]) [b[0], b[e], b[e - 1]]]
            : _tsf_fan([centre[0], centre[1], (s[0] + sh[3]) * step_mm],
                       _tsf_ring(xy, [for (e = [0:5]) own[e][0]], sh[5], cell_mm, step_mm), false))
    concat(top, bottom,
           [for (k = [0:5]) each _tsf_edge_walls(xy[k], xy[(k + 1) % 6], own[k], own[(k + 1) % 6], nb[k][0], nb[k][1],
                                                 is_undef(sh) ? undef : sh[4][k],
                                                 is_undef(sh) || len(sh[5]) == 0 ? undef : sh[5][k],
                                                 at[k], at[(k + 1) % 6], cell_mm, step_mm)]);

// The ring of a fan, counter-clockwise from above: each corner at its
// height z[e] (steps), then the crossing on edge e if there is one.
function _tsf_ring(xy, z, crossings, cell_mm, step_mm) =
    [for (e = [0:5]) each concat([[xy[e][0], xy[e][1], z[e] * step_mm]],
                                 is_undef(crossings[e]) ? []
                                 : let(p = _tsf_cross_xy(crossings[e], cell_mm)) [[p[0], p[1], crossings[e][2] * step_mm]])];

// Triangles from the centre point over a ring, counter-clockwise seen from
// above (up = true) or from below.
function _tsf_fan(centre, ring, up) =
    let(n = len(ring))
    [for (i = [0:n - 1]) up ? [centre, ring[i], ring[(i + 1) % n]] : [centre, ring[(i + 1) % n], ring[i]]];
