#include "gen/geometry/polygon_triangulation.h"

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_face_base_with_info_2.h>
#include <CGAL/Triangulation_vertex_base_with_info_2.h>

#include "gen/geometry/cdt_parity.h"

namespace tsf {
namespace {
using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Vb = CGAL::Triangulation_vertex_base_with_info_2<uint32_t, K>;
using Fb = CGAL::Constrained_triangulation_face_base_2<K, CGAL::Triangulation_face_base_with_info_2<int, K>>;
using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
// Rings never cross: exact predicates suffice and no point is constructed.
using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds, CGAL::Exact_predicates_tag>;
}  // namespace

std::vector<std::array<uint32_t, 3>> triangulateRings(const std::vector<Vec3>& positions,
                                                      const std::vector<std::vector<uint32_t>>& rings) {
    Cdt cdt;
    for (const auto& ring : rings) {
        std::vector<Cdt::Vertex_handle> h;
        for (const uint32_t v : ring) {
            h.push_back(cdt.insert(Cdt::Point(positions[v].x, positions[v].y)));
            h.back()->info() = v;
        }
        for (size_t n = 0; n < h.size(); ++n) cdt.insert_constraint(h[n], h[(n + 1) % h.size()]);
    }
    markInsideByParity(cdt);
    std::vector<std::array<uint32_t, 3>> out;
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f)
        if (f->info() % 2 == 1) out.push_back({f->vertex(0)->info(), f->vertex(1)->info(), f->vertex(2)->info()});
    return out;
}

}  // namespace tsf
