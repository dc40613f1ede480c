// MeshTopology: what the indexed triangles say about a mesh, before any
// geometry is looked at.
//
// analyzeTopology reads only the index triples (and, for two figures, exact
// position equality); it never welds, re-orients or drops anything. It is the
// independent first opinion the verifier forms before handing the triangles to
// CGAL (verify/solid_checks.h), so that a defect is reported as what it is in
// the file ("this edge has one triangle") rather than as whatever a repair
// step made of it.
//
// Terms (an "edge" is an unordered pair of distinct vertex indices used by a
// triangle side; a triangle with a repeated index contributes no edges):
//   - border edge:          used by exactly one triangle (the mesh is open there);
//   - non-manifold edge:    used by three or more triangles;
//   - misoriented edge:     used by exactly two triangles that traverse it in the
//                           same direction (one of them is flipped);
//   - non-manifold vertex:  the triangles around the vertex form more than one
//                           fan when joined across its two-triangle edges
//                           (two shells touching at a point, an hourglass);
//   - index-degenerate:     a triangle that uses one vertex index twice or more;
//   - component:            a maximal set of triangles connected through shared
//                           edges (any edge, manifold or not).
//
// Sizes: every per-item list is complete (not truncated); callers choose what
// to show. Empty mesh: all counts 0, no components.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf {

/// An undirected edge (a < b) and the triangles that use it.
struct EdgeUse {
    uint32_t a = 0, b = 0;            ///< vertex indices, a < b
    std::vector<uint32_t> triangles;  ///< every triangle using the edge, ascending
};

/// One edge-connected piece of the mesh.
struct MeshComponent {
    std::vector<uint32_t> triangles;  ///< ascending
    Bounds bounds;                    ///< of the component's vertices, mm
    double signed_volume_mm3 = 0.0;   ///< divergence theorem over its triangles (double precision)
};

struct MeshTopology {
    size_t vertex_count = 0;
    size_t triangle_count = 0;
    size_t edge_count = 0;  ///< distinct undirected edges

    std::vector<EdgeUse> border_edges;        ///< used by exactly one triangle
    std::vector<EdgeUse> nonmanifold_edges;   ///< used by three or more triangles
    std::vector<EdgeUse> misoriented_edges;   ///< two triangles, same direction
    std::vector<uint32_t> nonmanifold_vertices;  ///< ascending
    std::vector<uint32_t> index_degenerate_triangles;  ///< ascending
    std::vector<uint32_t> out_of_range_triangles;      ///< an index >= vertex_count; ascending
    std::vector<uint32_t> nonfinite_vertices;          ///< a NaN or infinite coordinate; ascending
    std::vector<MeshComponent> components;    ///< largest (most triangles) first
    size_t unreferenced_vertices = 0;         ///< vertices no triangle uses
    /// Vertices whose position is exactly equal to a lower-indexed vertex's
    /// (a file whose vertices were not merged); each such vertex counted once.
    size_t duplicate_position_vertices = 0;

    /// Closed, every edge manifold and consistently oriented, no pinched vertex,
    /// no index-degenerate or out-of-range triangle, every position finite: the
    /// triangles describe an oriented closed 2-manifold combinatorially.
    bool isClosedOrientedManifold() const {
        return border_edges.empty() && nonmanifold_edges.empty() && misoriented_edges.empty() &&
               nonmanifold_vertices.empty() && index_degenerate_triangles.empty() && out_of_range_triangles.empty() &&
               nonfinite_vertices.empty();
    }
};

/// Combinatorial analysis of mesh; see the file comment for the terms.
/// Triangles with an out-of-range index are listed and otherwise ignored.
/// From 20 000 triangles the edges and fans are found on every core; every
/// list comes out the same, in the same order, as on one thread.
MeshTopology analyzeTopology(const Mesh& mesh);

/// Midpoint (mm) of an edge's two vertices; for locating offenders.
Vec3 edgeMidpoint(const Mesh& mesh, const EdgeUse& edge);
/// Centroid (mm) of triangle t.
Vec3 triangleCentroid(const Mesh& mesh, uint32_t t);

/// The triangles' corners grouped by vertex (a counting sort, linear; 4 bytes
/// a corner): vertex v's corners are list[start[v]] .. list[start[v + 1] - 1],
/// each 3 * triangle + its place in the triangle, by ascending triangle.
/// Triangles whose `usable` entry is 0 are left out (all are used when
/// `usable` is null); every index of a used triangle must be in range.
struct VertexCorners {
    std::vector<uint32_t> start;  ///< vertex count + 1 entries
    std::vector<uint32_t> list;
};
VertexCorners cornersByVertex(const Mesh& mesh, const std::vector<uint8_t>* usable = nullptr);
/// The same for the vertices first .. last - 1 only (start has last - first
/// + 1 entries, start[0] for vertex first): a large mesh's corners a block
/// of vertices at a time, in a fraction of the memory.
VertexCorners cornersByVertex(const Mesh& mesh, const std::vector<uint8_t>* usable, uint32_t first, uint32_t last);

}  // namespace tsf
