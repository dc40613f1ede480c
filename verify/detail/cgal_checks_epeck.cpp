// Geometric checks with the exact-construction kernel (--exact).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "verify/detail/cgal_checks_impl.h"

namespace tsf::detail {

GeometricFindings geometricChecksEpeck(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs,
                                        bool self_intersections) {
    return geometricChecks<CGAL::Exact_predicates_exact_constructions_kernel>(mesh, topo, max_pairs, self_intersections);
}

}  // namespace tsf::detail
