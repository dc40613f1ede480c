// Geometric solid checks done with CGAL, behind a CGAL-free interface.
//
// Internal to verify/: solid_checks.cpp calls one of the two instantiations
// (filtered kernel Epick, or exact-construction kernel Epeck); the CGAL code
// lives in cgal_checks_impl.h, which only the two instantiation files include,
// so no other translation unit pays CGAL's compile time.
#pragma once

#include <cstdint>
#include <utility>
#include <vector>

#include "gen/geometry/mesh.h"
#include "verify/mesh_topology.h"

namespace tsf {
class ColumnGrid;
}

namespace tsf::detail {

struct GeometricFindings {
    /// The triangles handed to CGAL needed orient_polygon_soup (flipped
    /// triangles, non-manifold edges or vertices) before a Surface_mesh could be
    /// built; the self-intersection test ran on that repaired copy.
    bool soup_repaired = false;
    size_t points_duplicated = 0;  ///< by orient_polygon_soup, to split non-manifold places
    /// Self-intersections were tested: on the triangles as given (a valid
    /// soup, with the verifier's tree) or on a CGAL Surface_mesh that could be
    /// built from them. False: not tested.
    bool mesh_built = false;
    bool cgal_mesh_used = false;   ///< the test ran on a CGAL Surface_mesh (build_ms is its build time)
    bool self_intersections_requested = true;  ///< false: the caller skipped the test on purpose

    std::vector<uint32_t> zero_area_triangles;  ///< three collinear points (exact predicate); ascending
    size_t intersecting_pair_count = 0;
    /// Intersecting triangle pairs (original triangle ids, first < second),
    /// ascending, at most `max_pairs` of them; with a point on each pair's intersection (mm).
    std::vector<std::pair<uint32_t, uint32_t>> intersecting_pairs;
    std::vector<Vec3> intersection_points;

    bool volumes_computed = false;          ///< only for a closed oriented manifold
    double volume_mm3 = 0;                  ///< sum of component volumes, in the kernel's arithmetic
    std::vector<double> component_volume_mm3;  ///< same order as MeshTopology::components
    std::vector<int> component_volume_sign;    ///< -1, 0, +1, decided in the kernel's arithmetic

    double degenerate_ms = 0, build_ms = 0, self_intersection_ms = 0, volume_ms = 0;
};

/// Runs the geometric checks on the usable triangles of `mesh` (those not in
/// topo's out-of-range or index-degenerate lists). Requires every position to
/// be finite (topo.nonfinite_vertices empty).
/// self_intersections = false skips the self-intersection test (the slowest
/// part); mesh_built stays false. With the mesh's column grid (`grid`,
/// built from the same mesh) a closed, manifold, consistently oriented soup
/// is tested directly: the grid's candidate pairs, then CGAL's exact
/// predicates on those pairs only, on every core with the filtered kernel (the lazy exact
/// numbers of Epeck are not shared across threads). Otherwise, or without a
/// grid, CGAL's PMP::self_intersections runs on a Surface_mesh of the soup,
/// repaired by orient_polygon_soup when needed. Both find the same pairs.
/// A point (mm) on the intersection of mesh triangles a and b, to locate a
/// pair that intersects; always constructed with the exact kernel (the
/// filtered one can construct a NaN point for nearly parallel edges, which
/// its exact fallback then cannot convert).
Vec3 intersectionPoint(const Mesh& mesh, uint32_t a, uint32_t b);

GeometricFindings geometricChecksEpick(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs,
                                       bool self_intersections = true, const ColumnGrid* grid = nullptr);
GeometricFindings geometricChecksEpeck(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs,
                                       bool self_intersections = true, const ColumnGrid* grid = nullptr);

}  // namespace tsf::detail
