// The top of a mesh over a regular grid of sample points: at each point,
// the highest z of the mesh there, which is where a ray straight down from
// above meets it first; -inf where the mesh is not over the point.
//
// Rasterised, not ray cast: every triangle visits the samples its shadow on
// x, y covers, and keeps the highest z. A sample is covered when it is inside
// or on the triangle's shadow, decided by edge functions that are computed
// the same way for both triangles of a shared edge (from its end that comes
// first in x, then y), so their signs are exact negations: a sample on a
// shared edge or vertex is covered by every triangle there, one beside it by
// exactly one of the two, and no sample falls between the triangles of a
// closed surface. A triangle whose shadow has no area (a vertical wall) is
// left out, as a vertical ray lying in its plane does not meet it; its top
// edge is the edge of the face beside it. The z of a sample is the plane's,
// kept within the triangle's own range of z (a flat top reads its exact z).
// Units: millimetres, model frame.
#pragma once

#include <cstddef>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

struct TopHeightField {
    double x0 = 0, y0 = 0;  ///< the first sample (mm)
    double step = 1;        ///< between samples, in x and in y (mm)
    int nx = 0, ny = 0;     ///< samples along x and y
    std::vector<double> z;  ///< nx * ny, row by row from y0; -inf where nothing is above the table
    double at(int i, int j) const { return z[size_t(j) * size_t(nx) + size_t(i)]; }
};

/// Fills `field.z` for the sample points x0 + i * step, y0 + j * step (the
/// other fields as given). Triangles with an out-of-range index or a
/// non-finite corner are left out.
void rasteriseTop(const Mesh& mesh, TopHeightField& field);

}  // namespace tsf
