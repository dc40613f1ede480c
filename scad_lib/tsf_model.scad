// tsf_model.scad - the hex lattice, the value -> height mapping and the
// model record that every tsf terrain module reads.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: nothing else.
//
// The rules here are the same as in tsf's C++ code (gen/field/hex_grid.h,
// gen/model/scene.cpp); keep both in step, so that a model rendered by OpenSCAD is
// the same solid as the one tsf writes directly.
//
// Frame: x east, y north, z up, millimetres. The grid's bounding box starts
// at (0, 0); the lowest bottom is z = 0.
//
// Lattice: pointy-top hexagons in rows, row 0 is the NORTH row, column 0 the
// WEST column, odd rows shifted east by half a cell. Every centre and corner
// has integer lattice coordinates (i, j):
//     centre of (col, row):  i = 2 col + (row mod 2) + 1,  j = 3 (rows - 1 - row) + 2
//     corner k (0..5, counter-clockwise from the lower-right corner):
//         (i, j) + [(1,-1), (1,1), (0,2), (-1,1), (-1,-1), (0,-2)][k]
//     x = i * cell_mm / 2,   y = j * cell_mm / (2 sqrt 3)
// and x, y are rounded to 1 um, so a corner shared by three pillars has the
// same coordinates, to the last bit, in each of them.
//
// Heights are whole numbers of z steps ("units"): a height in mm is rounded
// to the nearest multiple of z_step_mm (halves away from zero) before it is
// compared or used, so two heights that print the same are equal.

// Function: tsf_snap_units()
// Usage:
//   n = tsf_snap_units(mm, z_step_mm);
// Description:
//   Rounds a length to a whole number of z steps (halves away from zero).
//   Every height in a tsf model is such a whole number; multiply by
//   z_step_mm to get millimetres back.
// Arguments:
//   mm = length in millimetres (finite number).
//   z_step_mm = the height grid in millimetres (> 0), e.g. 0.001 or a printer's layer height.
// Example(echo):
//   echo(tsf_snap_units(2.0004, 0.001), tsf_snap_units(0.25, 0.2));
//   // ECHO: 2000, 1
function tsf_snap_units(mm, z_step_mm) =
    assert(is_num(mm) && abs(mm) < 1e300, str("tsf_snap_units: mm must be a finite number, got ", mm))
    assert(is_num(z_step_mm) && z_step_mm > 0, str("tsf_snap_units: z_step_mm must be a number > 0, got ", z_step_mm))
    round(mm / z_step_mm);

// Function: tsf_height_mm()
// Usage:
//   h = tsf_height_mm(value, transfer, baseline, value_max, max_height_mm);
// Description:
//   The height of a pillar above the floor, in millimetres, before rounding to
//   the z step. With t = (value - baseline) / (value_max - baseline) clamped
//   to [0, 1]:
//     "linear": h = max_height_mm * t
//     "sqrt":   h = max_height_mm * sqrt(t)      (counts, areas)
//     "log":    h = max_height_mm * log10(1 + 99 t) / 2   (two decades)
//   A constant field (value_max <= baseline) gives max_height_mm for values
//   above the baseline and 0 otherwise. A missing value (undef or "nodata")
//   gives 0: the cell sits at the floor.
// Arguments:
//   value = the cell's value in data units, or undef / "nodata".
//   transfer = "linear", "sqrt" or "log".
//   baseline = value at height 0 (data units).
//   value_max = value at max_height_mm (data units); larger values are capped.
//   max_height_mm = height of value_max above the floor, mm (>= 0).
// Example(echo):
//   echo(tsf_height_mm(5, "linear", 0, 10, 20), tsf_height_mm(25, "sqrt", 0, 100, 20), tsf_height_mm(-3, "linear", 0, 10, 20));
//   // ECHO: 10, 10, 0
function tsf_height_mm(value, transfer, baseline, value_max, max_height_mm) =
    assert(is_string(transfer) && (transfer == "linear" || transfer == "sqrt" || transfer == "log"),
           str("tsf_height_mm: transfer must be \"linear\", \"sqrt\" or \"log\", got ", transfer))
    assert(_tsf_is_finite(baseline), str("tsf_height_mm: baseline must be a finite number, got ", baseline))
    assert(_tsf_is_finite(value_max), str("tsf_height_mm: value_max must be a finite number, got ", value_max))
    assert(_tsf_is_finite(max_height_mm) && max_height_mm >= 0,
           str("tsf_height_mm: max_height_mm must be a number >= 0, got ", max_height_mm))
    assert(is_undef(value) || value == "nodata" || _tsf_is_finite(value),
           str("tsf_height_mm: value must be a finite number, undef or \"nodata\", got ", value))
    _tsf_height_mm(value, transfer, baseline, value_max, max_height_mm);

// Function: tsf_cell_corners()
// Usage:
//   pts = tsf_cell_corners(col, row, rows, cell_mm);
// Description:
//   The six corners [x, y] (mm, rounded to 1 um) of cell (col, row) of a grid
//   with `rows` rows, counter-clockwise seen from above, starting at the
//   lower-right corner. Row 0 is the north row; odd rows are shifted east.
// Arguments:
//   col = column, 0 = west (integer >= 0).
//   row = row, 0 = north (integer, 0 <= row < rows).
//   rows = number of rows in the grid (integer >= 1).
//   cell_mm = distance between neighbouring centres (width across flats), mm (> 0).
// Example:
//   linear_extrude(1) polygon(tsf_cell_corners(0, 0, 1, 10));
function tsf_cell_corners(col, row, rows, cell_mm) =
    assert(_tsf_is_count(rows) && rows >= 1, str("tsf_cell_corners: rows must be a whole number >= 1, got ", rows))
    assert(_tsf_is_count(col), str("tsf_cell_corners: col must be a whole number >= 0, got ", col))
    assert(_tsf_is_count(row) && row < rows, str("tsf_cell_corners: row must be a whole number in [0, rows), got ", row))
    assert(_tsf_is_finite(cell_mm) && cell_mm > 0, str("tsf_cell_corners: cell_mm must be a number > 0, got ", cell_mm))
    let(c = _tsf_centre_ij(col, row, rows))
    [for (d = _tsf_corner_offsets()) [_tsf_snap_xy(_tsf_lattice_x(c[0] + d[0], cell_mm)),
                                      _tsf_snap_xy(_tsf_lattice_y(c[1] + d[1], cell_mm))]];

// Function: tsf_flat_spans()
// Usage:
//   spans = tsf_flat_spans(heights, base_units);
// Description:
//   Pillars standing on a flat base: every present cell spans from z = 0 to
//   base + its height. Input and output are in z steps (see tsf_snap_units).
//   Absent cells (undef) stay undef.
// Arguments:
//   heights = rows x cols list of heights above the floor in z steps (whole numbers >= 0) or undef.
//   base_units = thickness under the floor in z steps (whole number >= 1).
// Example(echo):
//   echo(tsf_flat_spans([[3, undef], [0, 5]], 2));
//   // ECHO: [[[0, 5], undef], [[0, 2], [0, 7]]]
function tsf_flat_spans(heights, base_units) =
    assert(_tsf_is_height_grid(heights),
           "tsf_flat_spans: heights must be a list of rows, each a list of whole numbers >= 0 or undef")
    assert(_tsf_is_count(base_units) && base_units >= 1,
           str("tsf_flat_spans: base_units must be a whole number >= 1, got ", base_units))
    [for (row = heights) [for (h = row) is_undef(h) ? undef : [0, base_units + h]]];

// Function: tsf_mirrored_spans()
// Usage:
//   spans = tsf_mirrored_spans(heights, base_units);
// Description:
//   The mirrored bottom: every present cell has the same thickness T and its
//   bottom is raised by its own height, so the underside shows the data
//   negated (a mould of the top). T is the largest height difference between
//   two neighbouring present cells plus base_units, which keeps every pair of
//   neighbours overlapping by at least base_units, so the model is one solid.
//   Input and output are in z steps; absent cells (undef) stay undef.
// Arguments:
//   heights = rows x cols list of heights above the floor in z steps (whole numbers >= 0) or undef.
//   base_units = thinnest point of the slab in z steps (whole number >= 1).
// Example(echo):
//   echo(tsf_mirrored_spans([[3, undef], [0, 5]], 2));
//   // ECHO: [[[3, 10], undef], [[0, 7], [5, 12]]]
function tsf_mirrored_spans(heights, base_units) =
    assert(_tsf_is_height_grid(heights),
           "tsf_mirrored_spans: heights must be a list of rows, each a list of whole numbers >= 0 or undef")
    assert(_tsf_is_count(base_units) && base_units >= 1,
           str("tsf_mirrored_spans: base_units must be a whole number >= 1, got ", base_units))
    _tsf_mirrored_spans(heights, base_units, 0);

// Function: tsf_model()
// Usage:
//   m = tsf_model(values, cell_mm, max_height_mm, base_mm, transfer, baseline, value_max, z_step_mm, mirrored,
//                 faces, mark_height_mm);
// Description:
//   Checks the data and the parameters and computes every pillar's z span.
//   The result is what tsf_terrain_polyhedron(), tsf_terrain_csg() and
//   tsf_hull_base() draw. Read it with tsf_model_spans() etc.; its layout is
//   private.
//
//   values lists the grid row by row, NORTH row first, west to east; odd rows
//   are shifted half a cell east. Each entry is
//     a number  - a pillar whose height follows tsf_height_mm();
//     "nodata"  - a cell inside the model without data: a pit, half the base
//                 (at most 1 mm) below the floor (mirrored: also above the
//                 underside), so a finger never takes it for the lowest value;
//     undef     - no pillar (a cell outside the model).
//   Heights: flat bottom: z from 0 to base_mm + height; mirrored: see
//   tsf_mirrored_spans(), of the heights less the least height of a cell
//   with data, so the model stands on z = 0. All heights are rounded to
//   z_step_mm.
//   faces are the orientation marks tsf wrote (tsf_marks.scad); each replaces
//   the hexagons of the cells it covers, the triangle raised by mark_height_mm.
// Arguments:
//   values = rows x cols list of numbers, "nodata" or undef (at least one present cell).
//   cell_mm = distance between neighbouring centres (width across flats), mm (> 0).
//   max_height_mm = height of value_max above the floor, mm (>= 0).
//   base_mm = flat: thickness under the floor; mirrored: thinnest point of the slab; mm (>= z_step_mm).
//   transfer = "linear", "sqrt" or "log" (see tsf_height_mm()).
//   baseline = value at the floor (data units).
//   value_max = value at max_height_mm (data units); larger values are capped.
//   z_step_mm = height grid, mm (0.000001 .. 1); e.g. 0.001, or the printer's layer height.
//   mirrored = false: flat bottom; true: the bottom shows the data negated.
//   faces = the orientation marks written by tsf (`marks`), or [] for none. Default: [].
//   mark_height_mm = how far the orientation triangle stands above its region, mm (> 0). Default: 1.
//   shapes = tilted tops and dimpled structural cells written by tsf (`tops`, tsf_tilt.scad), or [] for
//            none: every top a level hexagon. Default: [].
//   min_thickness_units = mirrored: the slab is at least this many z steps thick (tsf writes the
//            thickness its tilted corners need). Default: 0.
//   mirror_room_units = mirrored: z steps kept below the lowest cell with data for shaped
//            tops (tsf writes what its tops need). Default: 0.
// Example(echo):
//   m = tsf_model([[1, 2], [undef, "nodata"]], cell_mm=10, max_height_mm=10, base_mm=2,
//                 transfer="linear", baseline=0, value_max=2, z_step_mm=0.5, mirrored=false);
//   echo(tsf_model_spans(m));
//   // ECHO: [[[0, 14], [0, 24]], [undef, [0, 2]]]
function tsf_model(values, cell_mm, max_height_mm, base_mm, transfer = "linear", baseline = 0, value_max,
                   z_step_mm = 0.001, mirrored = false, faces = [], mark_height_mm = 1, shapes = [],
                   min_thickness_units = 0, mirror_room_units = 0) =
    assert(is_list(values) && len(values) >= 1 && is_list(values[0]) && len(values[0]) >= 1,
           "tsf_model: values must be a list of rows (north row first), each a list of cell values")
    assert(_tsf_is_finite(cell_mm) && cell_mm > 0, str("tsf_model: cell_mm must be a number > 0 (mm), got ", cell_mm))
    assert(_tsf_is_finite(max_height_mm) && max_height_mm >= 0,
           str("tsf_model: max_height_mm must be a number >= 0 (mm), got ", max_height_mm))
    assert(_tsf_is_finite(z_step_mm) && z_step_mm >= 0.000001 && z_step_mm <= 1,
           str("tsf_model: z_step_mm must be a number between 0.000001 and 1 (mm), got ", z_step_mm))
    assert(_tsf_is_finite(base_mm) && base_mm >= z_step_mm,
           str("tsf_model: base_mm must be a number >= z_step_mm (", z_step_mm, " mm), got ", base_mm))
    assert(is_string(transfer) && (transfer == "linear" || transfer == "sqrt" || transfer == "log"),
           str("tsf_model: transfer must be \"linear\", \"sqrt\" or \"log\", got ", transfer))
    assert(_tsf_is_finite(baseline), str("tsf_model: baseline must be a finite number (data units), got ", baseline))
    assert(_tsf_is_finite(value_max), str("tsf_model: value_max must be a finite number (data units), got ", value_max))
    assert(is_bool(mirrored), str("tsf_model: mirrored must be true or false, got ", mirrored))
    assert(is_list(faces), str("tsf_model: faces must be a list (the marks written by tsf), got ", faces))
    assert(_tsf_is_finite(mark_height_mm) && mark_height_mm > 0,
           str("tsf_model: mark_height_mm must be a number > 0 (mm), got ", mark_height_mm))
    assert(is_list(shapes) && (len(shapes) == 0 || len(shapes) == len(values)),
           "tsf_model: shapes must be [] or one row per row of values (the tops written by tsf)")
    assert(_tsf_is_count(min_thickness_units),
           str("tsf_model: min_thickness_units must be a whole number >= 0, got ", min_thickness_units))
    assert(_tsf_is_count(mirror_room_units),
           str("tsf_model: mirror_room_units must be a whole number >= 0, got ", mirror_room_units))
    let(rows = len(values), cols = len(values[0]),
        bad_row = [for (r = [0:rows - 1]) if (!is_list(values[r]) || len(values[r]) != cols) r])
    assert(len(bad_row) == 0,
           str("tsf_model: every row of values must have ", cols, " entries like row 0; row ", bad_row[0],
               " has ", is_list(values[bad_row[0]]) ? len(values[bad_row[0]]) : values[bad_row[0]]))
    let(bad = [for (r = [0:rows - 1]) for (c = [0:cols - 1])
                   let(v = values[r][c]) if (!(is_undef(v) || v == "nodata" || _tsf_is_finite(v))) [r, c, v]])
    assert(len(bad) == 0,
           str("tsf_model: values[", bad[0][0], "][", bad[0][1], "] (row ", bad[0][0], ", column ", bad[0][1],
               ") must be a finite number, \"nodata\" or undef, got ", bad[0][2]))
    let(present = [for (r = [0:rows - 1]) for (c = [0:cols - 1]) if (!is_undef(values[r][c])) 1])
    assert(len(present) > 0, "tsf_model: values has no present cell (every entry is undef): nothing to model")
    let(raw = [for (row = values)
                   [for (v = row) is_undef(v) ? undef
                                  : round(_tsf_height_mm(v, transfer, baseline, value_max, max_height_mm) / z_step_mm)]],
        // Mirrored, the model stands on z = 0: every height less the least
        // height of a cell with data, but for the room shaped tops need
        // (tsf's Scene: floor_units).
        data_heights = [for (r = [0:rows - 1]) for (c = [0:cols - 1]) if (is_num(values[r][c])) raw[r][c]],
        shift = mirrored && len(data_heights) > 0 ? max(0, min(data_heights) - mirror_room_units) : 0,
        heights = [for (r = [0:rows - 1]) [for (c = [0:cols - 1])
                       is_undef(raw[r][c]) ? undef : is_num(values[r][c]) ? max(0, raw[r][c] - shift) : raw[r][c]]],
        base_units = round(base_mm / z_step_mm),
        plain = mirrored ? _tsf_mirrored_spans(heights, base_units, min_thickness_units) : tsf_flat_spans(heights, base_units),
        // Same rule as tsf's Scene (nodata_pit_units): half the base, at most 1 mm, at least one step;
        // mirrored, at most what leaves the pit cell one step of the slab.
        flat_pit = min(floor(base_units / 2), max(1, round(1 / z_step_mm))),
        some = [for (row = plain) for (span = row) if (!is_undef(span)) span][0],
        pit = mirrored ? min(flat_pit, floor((some[1] - some[0] - 1) / 2)) : flat_pit,
        spans = [for (r = [0:rows - 1]) [for (c = [0:cols - 1])
                     values[r][c] == "nodata" ? [plain[r][c][0] + (mirrored ? pit : 0), plain[r][c][1] - pit]
                                              : plain[r][c]]])
    ["tsf_model", rows, cols, cell_mm, z_step_mm, spans, base_units, mirrored,
     faces, tsf_marks_cells(faces, rows), max(1, round(mark_height_mm / z_step_mm)), shapes];

// Function: tsf_model_spans()
// Usage:
//   spans = tsf_model_spans(m);
// Description:
//   The pillars of a model: a rows x cols list whose entries are
//   [bottom, top] in z steps, or undef for an absent cell. Multiply by
//   tsf_model_z_step(m) for millimetres.
// Arguments:
//   m = a model from tsf_model().
// Example(echo):
//   m = tsf_model([[4]], cell_mm=10, max_height_mm=4, base_mm=1, value_max=4, z_step_mm=1);
//   echo(tsf_model_spans(m), tsf_model_z_step(m), tsf_model_size(m));
//   // ECHO: [[[0, 5]]], 1, [10, 11.547]
function tsf_model_spans(m) = _tsf_check_model(m, "tsf_model_spans") [5];

// Function: tsf_model_z_step()
// Usage:
//   step_mm = tsf_model_z_step(m);
// Description:
//   The height grid of a model in millimetres (the size of one z step).
// Arguments:
//   m = a model from tsf_model().
// Example(echo):
//   echo(tsf_model_z_step(tsf_model([[1]], cell_mm=5, max_height_mm=2, base_mm=1, value_max=1, z_step_mm=0.2)));
//   // ECHO: 0.2
function tsf_model_z_step(m) = _tsf_check_model(m, "tsf_model_z_step") [4];

// Function: tsf_model_size()
// Usage:
//   wd = tsf_model_size(m);
// Description:
//   [width, depth] in mm of the bounding box of the whole grid (present or
//   not), rounded to 1 um; the model lies in [0, width] x [0, depth].
// Arguments:
//   m = a model from tsf_model().
// Example(echo):
//   echo(tsf_model_size(tsf_model([[1, 1], [1, 1]], cell_mm=10, max_height_mm=2, base_mm=1, value_max=1)));
//   // ECHO: [25, 20.207]
function tsf_model_size(m) =
    let(m = _tsf_check_model(m, "tsf_model_size"), rows = m[1], cols = m[2], cell = m[3])
    [_tsf_snap_xy(_tsf_lattice_x(2 * cols + (rows > 1 ? 1 : 0), cell)), _tsf_snap_xy(_tsf_lattice_y(3 * rows + 1, cell))];

// Function: tsf_marks_cells()
// Usage:
//   mask = tsf_marks_cells(faces, rows);
// Description:
//   The cells that faces replace, as a list with one entry per row: the
//   columns of that row that are drawn by a face rather than as a hexagon.
// Arguments:
//   faces = the `marks` list written by tsf (or []).
//   rows = number of rows of the grid.
// Example(echo):
//   echo(tsf_marks_cells([[[0, 1], false, [], [], [], [], [], [[0, 1], [1, 1]]]], 2));
//   // ECHO: [[], [0, 1]]
function tsf_marks_cells(faces, rows) =
    assert(is_list(faces), str("tsf_marks_cells: faces must be a list (the marks written by tsf), got ", faces))
    [for (r = [0:rows - 1]) [for (f = faces) for (c = f[7]) if (c[1] == r) c[0]]];

// ---------------------------------------------------------------------------
// Private helpers (names start with _tsf; not part of the interface).

// Corner offsets [di, dj] in lattice units, counter-clockwise from the
// lower-right corner. (Functions, not variables: a library read with use<>
// or pasted after a customizer's [Hidden] section must not add variables.)
function _tsf_corner_offsets() = [[1, -1], [1, 1], [0, 2], [-1, 1], [-1, -1], [0, -2]];

// The xy grid: 1 um. Every x and y is rounded to it (same expression as tsf's Scene::point).
function _tsf_snap_xy(mm) = round(mm / 0.001) * 0.001;
function _tsf_lattice_x(i, cell_mm) = i * cell_mm * 0.5;
function _tsf_lattice_y(j, cell_mm) = j * cell_mm / (2 * sqrt(3)) * _tsf_y_scale();
// The lattice's north-south stretch (tsf's Scene::y_scale): $tsf_y_scale where
// the model's file sets it (true aspect: rows one cell apart), else 1.
function _tsf_y_scale() = is_undef($tsf_y_scale) ? 1 : $tsf_y_scale;
function _tsf_centre_ij(col, row, rows) = [2 * col + row % 2 + 1, 3 * (rows - 1 - row) + 2];

// A finite number: at most the largest double (OpenSCAD has no isfinite();
// inf and nan fail the comparison).
function _tsf_is_finite(v) = is_num(v) && abs(v) <= 1.7976931348623157e308;
function _tsf_is_count(v) = is_num(v) && v >= 0 && v == floor(v) && v < 1e15;

// ValueMapping::heightMm of tsf (gen/model/scene.cpp), without argument checks.
// OpenSCAD's log(x) is ln(x) / ln(10); see docs/openscad.md on the last bit.
function _tsf_height_mm(v, transfer, baseline, value_max, h_max) =
    !is_num(v) ? 0
    : !(value_max > baseline) ? (v > baseline ? h_max : 0)
    : let(t = min(max(_tsf_span_fraction(v, baseline, value_max), 0), 1))
      transfer == "sqrt" ? h_max * sqrt(t)
    : transfer == "log" ? h_max * log(1 + 99 * t) / 2
    : h_max * t;

// spanFraction of tsf (gen/model/scene.cpp): (v - lo) / (hi - lo), on the halves
// when hi - lo is beyond the largest double (1e308 and -1e308).
function _tsf_span_fraction(v, lo, hi) =
    let(span = hi - lo)
    _tsf_is_finite(span) ? (v - lo) / span : (v / 2 - lo / 2) / (hi / 2 - lo / 2);

// Neighbour k (0 east, 1 north-east, 2 north-west, 3 west, 4 south-west,
// 5 south-east) of (col, row) as [col, row]; may lie outside the grid.
function _tsf_neighbour(col, row, k) =
    let(odd = row % 2)
    k == 0 ? [col + 1, row]
    : k == 1 ? [col + odd, row - 1]
    : k == 2 ? [col - 1 + odd, row - 1]
    : k == 3 ? [col - 1, row]
    : k == 4 ? [col - 1 + odd, row + 1]
    : [col + odd, row + 1];

// Entry (col, row) of a rows x cols grid list, undef outside the grid.
function _tsf_at(grid, col, row) =
    row < 0 || row >= len(grid) || col < 0 || col >= len(grid[row]) ? undef : grid[row][col];

// Largest |difference| between neighbouring present heights (0 if none).
// Each pair is visited once, through edges 0..2 (east, north-east, north-west).
function _tsf_max_step(heights) =
    max(concat([0], [for (r = [0:len(heights) - 1]) for (c = [0:len(heights[r]) - 1])
                         let(h = heights[r][c]) if (!is_undef(h)) for (k = [0:2])
                             let(n = _tsf_neighbour(c, r, k), hn = _tsf_at(heights, n[0], n[1]))
                             if (!is_undef(hn)) abs(h - hn)]));

// tsf_mirrored_spans() with a slab at least min_t steps thick.
function _tsf_mirrored_spans(heights, base_units, min_t) =
    let(t = max(_tsf_max_step(heights) + base_units, min_t))
    [for (row = heights) [for (h = row) is_undef(h) ? undef : [h, h + t]]];

function _tsf_is_height_grid(h) =
    is_list(h) && len([for (row = h) if (!is_list(row) || len([for (v = row) if (!is_undef(v) && !_tsf_is_count(v)) 1]) > 0) 1]) == 0;

// search() is OpenSCAD's own loop: the check runs for every cell of a model.
function _tsf_is_marked(mask, col, row) = let(m = mask[row]) is_list(m) && len(m) > 0 && len(search(col, m)) > 0;

function _tsf_check_model(m, who) =
    assert(is_list(m) && len(m) == 12 && m[0] == "tsf_model", str(who, ": expected a model made by tsf_model()"))
    m;
