// MeshAssembler: the common back end of every mesh reader. Internal to
// gen/mesh_io/.
//
// A reader feeds it the file's vertices (exactly equal positions become one
// vertex, see exact_vertex_index.h) and triangles, then finish() returns the
// Mesh and fills the counts and notes of the MeshReadReport. Nothing is
// dropped: a triangle that repeats a vertex index is kept and counted, and
// vertices no triangle uses are kept and mentioned in a note.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/mesh_io/exact_vertex_index.h"
#include "gen/mesh_io/mesh_read_report.h"

namespace tsf::mesh_io {

class MeshAssembler {
public:
    /// path: named in errors. The expectations only size allocations.
    MeshAssembler(std::string path, size_t expected_vertices, size_t expected_triangles);

    /// Adds one input vertex with finite coordinates (the caller checks);
    /// returns its index in the output mesh. Throws tsf::InputError if the
    /// mesh would exceed 2^32 - 1 distinct vertices.
    uint32_t addVertex(const Vec3& p);
    /// addVertex(p[i]) for i = 0 .. n-1 in order, the indices in out[i]
    /// (ExactVertexIndex::insertBatch: faster on a large mesh).
    void addVertices(const Vec3* p, size_t n, uint32_t* out);
    /// Adds a triangle of output indices (each < vertex count so far).
    void addTriangle(uint32_t a, uint32_t b, uint32_t c);
    /// Adds a reader's own note to the report.
    void note(std::string text) { notes_.push_back(std::move(text)); }

    /// The notes so far, taken out (for a reader that finishes no mesh of its own).
    std::vector<std::string> takeNotes() { return std::move(notes_); }

    size_t vertexCount() const { return index_.size(); }
    size_t triangleCount() const { return triangles_.size(); }

    /// The mesh; report gets format, counts and notes (reader notes first).
    Mesh finish(const std::string& format, MeshReadReport* report);

private:
    std::string path_;
    ExactVertexIndex index_;
    std::vector<std::array<uint32_t, 3>> triangles_;
    std::vector<std::string> notes_;
    size_t input_vertices_ = 0;
    size_t degenerate_ = 0;
    size_t first_degenerate_ = 0;
};

}  // namespace tsf::mesh_io
