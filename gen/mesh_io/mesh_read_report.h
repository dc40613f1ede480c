// MeshReadReport: what a mesh reader found and changed, for people and for
// the verifier. Filled by readMesh and the per-format readers.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tsf {

/// Largest mesh file any mesh reader reads (bytes): a binary STL of 80
/// million triangles; the cap keeps a pipe that never ends from filling
/// memory (devices such as /dev/zero are refused outright, file_bytes.h).
inline constexpr int64_t kMaxMeshFileBytes = int64_t(4) << 30;  // 4 GiB

struct MeshReadReport {
    /// "stl-binary", "stl-ascii", "3mf", "off" or "obj".
    std::string format;
    /// Triangles in the mesh returned (polygons count after triangulation).
    size_t input_triangles = 0;
    /// Vertices as the file stores them: corners for STL (3 per facet), vertex
    /// records for 3MF/OFF/OBJ (3MF: per build item / component instance).
    size_t input_vertices = 0;
    /// Input vertices that were the same position as an earlier one, bit for
    /// bit, and became that vertex: input_vertices - mesh.vertexCount().
    size_t merged_vertices = 0;
    /// Triangles that use one vertex index twice or three times (in the file,
    /// or after exact merging). They are kept in the mesh, only counted here.
    size_t degenerate_index_triangles = 0;
    /// 3MF read as parts of a model written in parts (gen/mesh_io/three_mf_writer.h):
    /// the components of the package's one build item, or an object split
    /// into the volumes its slicer config names.
    bool written_in_parts = false;
    /// One sentence per thing worth knowing: merges, repairs, ignored data.
    std::vector<std::string> notes;
};

}  // namespace tsf
