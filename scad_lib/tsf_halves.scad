// tsf_halves.scad - a mirrored model cut into two halves that print without
// supports, with the pin holes that join them one way only.
//
// Part of the tsf OpenSCAD library (use <tsf.scad> to get all of it).
//
// tsf decides the cut (the middle of the slab every pillar crosses) and the
// holes (three, in a scalene triangle, clear of the edge and the marks;
// docs/printing.md) and writes them as data, `halves = [cut_z, depth_y,
// holes, hole_depth, hole_tip]` (mm): each hole is [[x, y] of its centre,
// its 16 corners [x, y]] as tsf's own mesh has them, so OpenSCAD cuts exactly
// tsf's holes.
// The pins are in the STL tsf writes beside the halves (MODEL-pins.stl).

// Module: tsf_half()
// Usage:
//   tsf_half("upper", halves) tsf_terrain_polyhedron(model);
// Description:
//   One piece of the children (the whole mirrored model) as it prints:
//   "whole" draws the children as they are; "upper" the part above the cut,
//   moved down so the cut lies on z = 0; "lower" the part below the cut,
//   turned over about the x axis ((x, y, z) -> (x, depth_y - y, cut_z - z))
//   so its cut lies on z = 0 and the underside relief faces up. Both halves
//   have the pin holes in their cut face: a prism hole_depth deep closed by a
//   cone to hole_tip, steeper than 45 degrees (no supports).
// Arguments:
//   piece  = "whole", "upper" or "lower"
//   halves = [cut_z, depth_y, holes, hole_depth, hole_tip] as written by tsf gen --halves
// Example:
//   ring = [for (a = [11.25 : 22.5 : 360]) [5 + 1.7 * cos(a), 5 + 1.7 * sin(a)]];
//   tsf_half("upper", [5, 10, [[[5, 5], ring]], 2, 3.5]) cube([10, 10, 10]);
module tsf_half(piece, halves) {
    assert(piece == "whole" || piece == "upper" || piece == "lower",
           "tsf_half: piece must be \"whole\", \"upper\" or \"lower\"");
    assert(is_list(halves) && len(halves) == 5, "tsf_half: halves must be [cut_z, depth_y, holes, hole_depth, hole_tip]");
    cut = halves[0];
    if (piece == "whole") children();
    else if (piece == "upper")
        translate([0, 0, -cut]) difference() {
            intersection() {
                children();
                _tsf_half_space(cut, +1);
            }
            for (hole = halves[2]) _tsf_pin_hole(hole, cut, +1, halves[3], halves[4]);
        }
    else
        translate([0, halves[1], cut]) rotate([180, 0, 0]) difference() {
            intersection() {
                children();
                _tsf_half_space(cut, -1);
            }
            for (hole = halves[2]) _tsf_pin_hole(hole, cut, -1, halves[3], halves[4]);
        }
}

// The half-space above (side = +1) or below (-1) z = cut, as a box far larger than any model.
module _tsf_half_space(cut, side) {
    big = 1e5;
    translate([-big / 2, -big / 2, side > 0 ? cut : cut - big]) cube([big, big, big]);
}

// A pin hole from the cut into one side: the ring as a prism from 1 mm
// beyond the cut to `depth`, then a cone to its tip at `tip` (mm from the cut).
module _tsf_pin_hole(hole, cut, side, depth, tip) {
    ring = hole[1];
    n = len(ring);
    cx = hole[0][0];
    cy = hole[0][1];
    points = concat([for (p = ring) [p[0], p[1], cut - side]],
                    [for (p = ring) [p[0], p[1], cut + side * depth]],
                    [[cx, cy, cut + side * tip]]);
    // Faces clockwise from outside; the ring runs counter-clockwise from above.
    start = side > 0 ? [[for (k = [0 : n - 1]) k]] : [[for (k = [n - 1 : -1 : 0]) k]];
    walls = [for (k = [0 : n - 1]) side > 0 ? [k, k + n, (k + 1) % n + n, (k + 1) % n]
                                           : [k, (k + 1) % n, (k + 1) % n + n, k + n]];
    cone = [for (k = [0 : n - 1]) side > 0 ? [k + n, 2 * n, (k + 1) % n + n] : [k + n, (k + 1) % n + n, 2 * n]];
    polyhedron(points = points, faces = concat(start, walls, cone), convexity = 2);
}
