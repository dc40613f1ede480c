#include "gen/geometry/polygon_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include <unordered_map>

#include "gen/geometry/cdt_parity.h"

namespace tsf {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Rings never cross: exact predicates suffice and no point is constructed.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;

std::vector<std::array<uint32_t, 3>> insideFaces(Cdt& cdt) {
    markInsideByParity(cdt);
    std::vector<std::array<uint32_t, 3>> out;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        if (f->info() % 2 == 1) out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    return out;
}
}  // namespace

std::vector<std::array<uint32_t, 3>> triangulateRings(const std::vector<Vec3>& positions,
                                                      const std::vector<std::vector<uint32_t>>& rings) {
    std::vector<std::array<uint32_t, 2>> segments;
    for (const auto& ring : rings)
        for (size_t n = 0; n < ring.size(); ++n) segments.push_back({ring[n], ring[(n + 1) % ring.size()]});
    return triangulateSegments(positions, segments);
}

std::vector<std::array<uint32_t, 3>> triangulateSegments(const std::vector<Vec3>& positions,
                                                         const std::vector<std::array<uint32_t, 2>>& segments) {
    Cdt cdt;
    std::unordered_map<uint32_t, Cdt::Vertex_handle> handle;
    auto vertex = [&](uint32_t v) {
        const auto [it, fresh] = handle.try_emplace(v);
        if (fresh) {
            it->second = cdt.insert(Cdt::Point(positions[v].x, positions[v].y));
            it->second->info() = v;
        }
        return it->second;
    };
    for (const auto& [a, b] : segments) cdt.insert_constraint(vertex(a), vertex(b));
    return insideFaces(cdt);
}

}  // namespace tsf
