// Geometric checks with the filtered kernel (exact predicates, double constructions).
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include "verify/detail/cgal_checks_impl.h"

namespace tsf::detail {

GeometricFindings geometricChecksEpick(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs,
                                        bool self_intersections, const ColumnGrid* grid) {
    return geometricChecks<CGAL::Exact_predicates_inexact_constructions_kernel>(mesh, topo, max_pairs, self_intersections, grid, 0);
}

}  // namespace tsf::detail
