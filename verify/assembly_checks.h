// checkAssembly: do the parts of a multi-part model touch without
// overlapping? (verify/verify_parts.h runs it after each part's own checks.)
//
// [parts_overlap] For every two parts whose bounding boxes meet, the volume
// of their intersection is computed exactly: CGAL corefinement of the two
// closed meshes with the exact-construction kernel (Epeck), then the
// intersection's volume. Parts that only touch (share a face or part of one,
// an edge, a point) have an intersection of volume 0; any positive volume
// is an offender, placed at the centre of the shared region's box, its
// amount in mm^3. The test needs every part closed, manifold, outward and
// free of self-intersections; when one is not, the check is skipped and the
// note says which part's checks made it impossible.
// Millimetres, model frame (x east, y north, z up).
#pragma once

#include <vector>

#include "gen/geometry/mesh_parts.h"
#include "verify/report.h"

namespace tsf {

struct PartOverlap {
    size_t a = 0, b = 0;       ///< indices of the two parts
    double volume_mm3 = 0;     ///< volume both parts fill
    Vec3 at_mm;                ///< centre of the overlap's bounding box
};

struct AssemblyResult {
    std::vector<Check> checks;
    std::vector<Stage> stages;
    std::vector<PartOverlap> overlaps;  ///< every pair that overlaps, largest first
    size_t pairs_tested = 0;            ///< pairs whose boxes meet (the others cannot overlap)
};

/// solid[k]: part k passed its solid checks (closed, manifold, outward, no self-intersections).
AssemblyResult checkAssembly(const std::vector<MeshPart>& parts, const std::vector<bool>& solid, size_t max_offenders);

}  // namespace tsf
