// tsf_marks.scad - tactile orientation marks: a notch cut into a corner and
// a raised triangle pointing north.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
// Requires: tsf_model.scad.
//
// A reader who cannot see the model finds north by touch: the notch is a V
// cut into the model's north-east corner (a cut corner, as on tactile maps and
// heat maps), the triangle a small raised arrow. Files written by tsf do not
// call these modules yet; add them by hand as in the examples. A mark changes
// the solid, so a model with a mark no longer agrees with tsf's direct STL,
// and adding or cutting a shape makes OpenSCAD run CGAL (slower).

// Function: tsf_model_corner()
// Usage:
//   p = tsf_model_corner(m, [which]);
// Description:
//   The outermost corner [x, y] (mm) of the present cells towards one
//   diagonal: the corner of a present cell that lies furthest towards
//   "ne" (north-east), "nw", "se" or "sw". This is where a corner notch bites.
// Arguments:
//   m = a model from tsf_model().
//   which = "ne", "nw", "se" or "sw". Default: "ne".
// Example(echo):
//   m = tsf_model([[1, 1], [1, undef]], cell_mm=10, max_height_mm=2, base_mm=1, value_max=1);
//   echo(tsf_model_corner(m, "ne"));
//   // ECHO: [20, 17.321]
function tsf_model_corner(m, which = "ne") =
    let(model = _tsf_check_model(m, "tsf_model_corner"))
    assert(which == "ne" || which == "nw" || which == "se" || which == "sw",
           str("tsf_model_corner: which must be \"ne\", \"nw\", \"se\" or \"sw\", got ", which))
    let(sx = (which == "ne" || which == "se") ? 1 : -1,
        sy = (which == "ne" || which == "nw") ? 1 : -1,
        rows = model[1], cols = model[2], spans = model[5],
        pts = [for (r = [0:rows - 1]) for (c = [0:cols - 1]) if (!is_undef(spans[r][c]))
                   each tsf_cell_corners(c, r, rows, model[3])],
        score = [for (p = pts) sx * p[0] + sy * p[1]],
        best = max(score))
    [for (i = [0:len(pts) - 1]) if (score[i] == best) pts[i]][0];

// Module: tsf_orientation_notch()
// Usage:
//   difference() { <model>; tsf_orientation_notch(at, [size_mm], [height_mm], [direction]); }
// Description:
//   The shape to cut away for a V-shaped notch: a vertical triangular prism
//   whose apex points from `at` into the model along `direction`. With
//   at = tsf_model_corner(m, "ne") and direction = 225 it cuts the
//   north-east corner off, leaving a V that a finger finds at once.
// Arguments:
//   at = [x, y] of the notch's opening centre, mm (a corner of the model).
//   size_mm = width of the notch's opening, mm (> 0). Default: 8.
//   height_mm = how high the cut reaches from z = -1, mm (> 0); make it taller than the model. Default: 100.
//   direction = direction from `at` into the model, degrees counter-clockwise from east. Default: 225 (towards the south-west).
// Example:
//   tsf_orientation_notch(at = [0, 0], size_mm = 8, height_mm = 5);
// Example: Cut the north-east corner off a model
//   m = tsf_model([[1, 2, 3], [2, 3, 1], [3, 1, 2]], cell_mm=10, max_height_mm=10, base_mm=3, value_max=3);
//   difference() {
//       tsf_terrain_polyhedron(m);
//       tsf_orientation_notch(at = tsf_model_corner(m, "ne"), size_mm = 8);
//   }
module tsf_orientation_notch(at, size_mm = 8, height_mm = 100, direction = 225) {
    assert(is_list(at) && len(at) == 2 && _tsf_is_finite(at[0]) && _tsf_is_finite(at[1]),
           str("tsf_orientation_notch: at must be [x, y] in mm, got ", at));
    assert(_tsf_is_finite(size_mm) && size_mm > 0, str("tsf_orientation_notch: size_mm must be a number > 0, got ", size_mm));
    assert(_tsf_is_finite(height_mm) && height_mm > 0,
           str("tsf_orientation_notch: height_mm must be a number > 0, got ", height_mm));
    assert(_tsf_is_finite(direction), str("tsf_orientation_notch: direction must be a number (degrees), got ", direction));
    // A right-angled V: apex size_mm / 2 inside, opening size_mm wide, plus
    // a margin outside so the cut leaves no skin at the model's edge.
    margin = size_mm / 2;
    translate([at[0], at[1], -1]) rotate(direction) linear_extrude(height_mm + 1)
        polygon([[size_mm / 2, 0], [-margin, size_mm / 2 + margin], [-margin, -size_mm / 2 - margin]]);
}

// Module: tsf_orientation_triangle()
// Usage:
//   union() { <model>; tsf_orientation_triangle(at, [size_mm], [height_mm], [direction]); }
// Description:
//   A raised equilateral triangle pointing `direction` (default north), to be
//   placed on a flat part of the model, e.g. the base's floor next to the
//   pillars. It starts 0.5 mm below `at` so that it sinks into the surface
//   it stands on and unions cleanly.
// Arguments:
//   at = [x, y, z]: the triangle's centre on the surface, mm.
//   size_mm = side length, mm (> 0). Default: 8.
//   height_mm = how far it stands out of the surface, mm (> 0). Default: 1.5.
//   direction = where it points, degrees counter-clockwise from east. Default: 90 (north).
// Example:
//   tsf_orientation_triangle(at = [0, 0, 0]);
// Example: On the floor of a flat base, south of the pillars
//   m = tsf_model([[1, 2, 3], [2, "nodata", 1], ["nodata", "nodata", "nodata"]], cell_mm=10,
//                 max_height_mm=10, base_mm=3, value_max=3);
//   union() {
//       tsf_terrain_polyhedron(m);
//       tsf_orientation_triangle(at = [15, 6, 3], size_mm = 6);
//   }
module tsf_orientation_triangle(at, size_mm = 8, height_mm = 1.5, direction = 90) {
    assert(is_list(at) && len(at) == 3 && _tsf_is_finite(at[0]) && _tsf_is_finite(at[1]) && _tsf_is_finite(at[2]),
           str("tsf_orientation_triangle: at must be [x, y, z] in mm, got ", at));
    assert(_tsf_is_finite(size_mm) && size_mm > 0,
           str("tsf_orientation_triangle: size_mm must be a number > 0, got ", size_mm));
    assert(_tsf_is_finite(height_mm) && height_mm > 0,
           str("tsf_orientation_triangle: height_mm must be a number > 0, got ", height_mm));
    assert(_tsf_is_finite(direction), str("tsf_orientation_triangle: direction must be a number (degrees), got ", direction));
    sink_mm = 0.5;  // below the surface, so the union has volume overlap, not a touching face
    r = size_mm / sqrt(3);  // circumradius of the equilateral triangle
    translate([at[0], at[1], at[2] - sink_mm]) rotate(direction) linear_extrude(height_mm + sink_mm)
        polygon([for (a = [0, 120, 240]) [r * cos(a), r * sin(a)]]);
}
