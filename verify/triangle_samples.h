// Points on a triangle such that every point of it is within a given radius
// of one of them.
//
// Layout: the longest edge is the base, at row 0, and the opposite corner the
// apex. Rows run parallel to the base, m + 1 of them at equal spacing from the
// base to the apex, m = ceil(height / (r sqrt(3) / 2)); each row spans the
// triangle (from edge to edge) and holds ceil(length / r) + 1 points at equal
// spacing, its ends included. So the corners, the edges and the inside are all
// sampled, and a sliver (a long, thin triangle) gets about length / r points,
// not (length / r)^2.
//
// Covering radius, exactly (before rounding): because the base is the longest
// edge, both base angles are at most 90 degrees, so each row's span contains
// every span above it. A point p between rows j and j + 1 therefore has the
// point straight below it on row j inside the triangle, at most
// r sqrt(3) / 2 away, and that point is at most r / 2 from a sample of its
// row: |p - sample| <= sqrt(3/4 + 1/4) r = r.
//
// Hence, for any function f with |f(p) - f(q)| <= |p - q| (the distance to a
// surface is one), max over the triangle of f <= max over the samples + r.
//
// A triangle without area (collinear corners) is sampled along its longest
// edge, which contains the third corner; a triangle whose corners coincide
// gets one sample. A radius at least as long as the longest edge leaves the
// corners alone (one row of two points and the apex): every point of a
// triangle is within its longest edge of a corner.
// Units: millimetres; `radius_mm` must be positive and finite.
#pragma once

#include <cstddef>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

/// Whether the triangle's own corners are among the samples. A caller that
/// measures every vertex of a mesh once leaves them out of each triangle;
/// the covering radius holds for the samples and the corners together.
enum class Corners { Include, Omit };

/// The number of points sampleTriangle() appends for these arguments.
size_t triangleSampleCount(const Vec3& a, const Vec3& b, const Vec3& c, double radius_mm,
                           Corners corners = Corners::Include);

/// Appends the samples (see above) to `out`.
void sampleTriangle(const Vec3& a, const Vec3& b, const Vec3& c, double radius_mm, std::vector<Vec3>& out,
                    Corners corners = Corners::Include);

}  // namespace tsf
