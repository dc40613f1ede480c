#include "gen/mesh_io/mesh_assembler.h"

#include <cassert>
#include <limits>

#include "gen/util/error.h"

namespace tsf::mesh_io {

MeshAssembler::MeshAssembler(std::string path, size_t expected_vertices, size_t expected_triangles)
    : path_(std::move(path)), index_(expected_vertices) {
    triangles_.reserve(expected_triangles);
}

uint32_t MeshAssembler::addVertex(const Vec3& p) {
    ++input_vertices_;
    // One index value (UINT32_MAX) is the hash table's empty marker.
    if (index_.size() >= std::numeric_limits<uint32_t>::max() - 1) {
        throw InputError(path_, 0, 0, "too many vertices: tsf meshes hold at most 4294967294");
    }
    return index_.insert(p);
}

void MeshAssembler::addVertices(const Vec3* p, size_t n, uint32_t* out) {
    // Near the limit, one by one: the error then comes at the very vertex.
    if (index_.size() + n >= std::numeric_limits<uint32_t>::max() - 1) {
        for (size_t i = 0; i < n; ++i) out[i] = addVertex(p[i]);
        return;
    }
    input_vertices_ += n;
    index_.insertBatch(p, n, out);
}

void MeshAssembler::addTriangle(uint32_t a, uint32_t b, uint32_t c) {
    assert(a < index_.size() && b < index_.size() && c < index_.size());
    if (a == b || b == c || a == c) {
        if (degenerate_ == 0) first_degenerate_ = triangles_.size();
        ++degenerate_;
    }
    triangles_.push_back({a, b, c});
}

Mesh MeshAssembler::finish(const std::string& format, MeshReadReport* report) {
    Mesh mesh;
    mesh.positions = index_.takePositions();
    mesh.triangles = std::move(triangles_);
    if (report == nullptr) return mesh;

    report->format = format;
    report->input_triangles = mesh.triangles.size();
    report->input_vertices = input_vertices_;
    report->merged_vertices = input_vertices_ - mesh.positions.size();
    report->degenerate_index_triangles = degenerate_;
    report->notes = std::move(notes_);

    if (report->merged_vertices > 0) {
        report->notes.push_back(std::to_string(input_vertices_) + " input vertices became " +
                                std::to_string(mesh.positions.size()) + ": " + std::to_string(report->merged_vertices) +
                                " had exactly the same coordinates as an earlier vertex and were merged into it");
    }
    if (degenerate_ > 0) {
        report->notes.push_back(std::to_string(degenerate_) +
                                " triangles use the same vertex more than once (first: triangle " +
                                std::to_string(first_degenerate_) + "); kept in the mesh");
    }
    std::vector<bool> used(mesh.positions.size(), false);
    for (const auto& t : mesh.triangles) used[t[0]] = used[t[1]] = used[t[2]] = true;
    size_t unused = 0;
    for (bool u : used) unused += u ? 0 : 1;
    if (unused > 0) {
        report->notes.push_back(std::to_string(unused) + " vertices are not used by any triangle; kept in the mesh");
    }
    if (mesh.triangles.empty()) report->notes.push_back("the file contains no triangles");
    return mesh;
}

}  // namespace tsf::mesh_io
