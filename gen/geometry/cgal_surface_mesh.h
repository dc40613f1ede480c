#pragma once
// A tsf Mesh as a CGAL Surface_mesh, for CGAL's exact Boolean operations
// (the legend plate's join in gen/model/features/legend/legend_scene.cpp, the parts' overlap test
// in verify/assembly_checks.cpp). Vertices keep their indices; a triangle
// CGAL cannot add (it would make the mesh non-manifold) is left out, so
// callers check the result with CGAL's own tests before they rely on it.
#include <vector>

#include <CGAL/Surface_mesh.h>

#include "gen/geometry/mesh.h"

namespace tsf {

template <class Kernel>
CGAL::Surface_mesh<typename Kernel::Point_3> toSurfaceMesh(const Mesh& m) {
    using SurfaceMesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
    SurfaceMesh sm;
    std::vector<typename SurfaceMesh::Vertex_index> v;
    v.reserve(m.positions.size());
    for (const Vec3& p : m.positions) v.push_back(sm.add_vertex(typename Kernel::Point_3(p.x, p.y, p.z)));
    for (const auto& t : m.triangles) sm.add_face(v[t[0]], v[t[1]], v[t[2]]);
    return sm;
}

}  // namespace tsf
