// Geometric checks with the exact-construction kernel (--exact).
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>

#include "verify/detail/cgal_checks_impl.h"

namespace tsf::detail {

Vec3 intersectionPoint(const Mesh& mesh, uint32_t ta, uint32_t tb) {
    using K = CGAL::Exact_predicates_exact_constructions_kernel;
    using P = K::Point_3;
    auto triangle = [&](uint32_t t) {
        const auto& tri = mesh.triangles[t];
        const Vec3 &a = mesh.positions[tri[0]], &b = mesh.positions[tri[1]], &c = mesh.positions[tri[2]];
        return K::Triangle_3(P(a.x, a.y, a.z), P(b.x, b.y, b.z), P(c.x, c.y, c.z));
    };
    const K::Triangle_3 a = triangle(ta), b = triangle(tb);
    auto toVec = [](const P& p) { return Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}; };
    auto mean = [&](const std::vector<P>& pts) {
        Vec3 c;
        for (const P& p : pts) {
            const Vec3 v = toVec(p);
            c = {c.x + v.x, c.y + v.y, c.z + v.z};
        }
        const double n = double(pts.size());
        return Vec3{c.x / n, c.y / n, c.z / n};
    };
    const auto result = CGAL::intersection(a, b);
    if (result) {
        if (const P* p = boost::get<P>(&*result)) return toVec(*p);
        if (const auto* s = boost::get<K::Segment_3>(&*result)) return mean({s->source(), s->target()});
        if (const auto* t = boost::get<K::Triangle_3>(&*result)) return mean({t->vertex(0), t->vertex(1), t->vertex(2)});
        if (const auto* poly = boost::get<std::vector<P>>(&*result)) return mean(*poly);
    }
    // Touching at a vertex or edge that the two triangles do not share by
    // index: the intersection is degenerate; fall back to the centroids' midpoint.
    return mean({a.vertex(0), a.vertex(1), a.vertex(2), b.vertex(0), b.vertex(1), b.vertex(2)});
}

GeometricFindings geometricChecksEpeck(const Mesh& mesh, const MeshTopology& topo, size_t max_pairs,
                                        bool self_intersections, const ColumnGrid* grid) {
    // One thread: Epeck's lazy exact numbers are reference-counted objects
    // that the self-intersection workers would share.
    return geometricChecks<CGAL::Exact_predicates_exact_constructions_kernel>(mesh, topo, max_pairs, self_intersections, grid, 1);
}

}  // namespace tsf::detail
