// Mesh: an indexed triangle mesh in millimetres.
//
// Frame: x east, y north, z up (the model stands on z = 0). Triangles are
// counter-clockwise seen from outside (right-hand normal points outward).
// Produced by the direct mesher (gen/mesh/direct_mesher.h) and the mesh readers
// (gen/mesh_io/), consumed by the writers and by the verifier.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tsf {

struct Vec3 {
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vec3&, const Vec3&) = default;
};

struct Mesh {
    std::vector<Vec3> positions;                  ///< mm
    std::vector<std::array<uint32_t, 3>> triangles;  ///< indices into positions, CCW from outside

    size_t vertexCount() const { return positions.size(); }
    size_t triangleCount() const { return triangles.size(); }
};

/// Axis-aligned bounds of all positions (mm). Empty mesh: min = +inf, max = -inf.
struct Bounds {
    Vec3 min, max;
};
Bounds meshBounds(const Mesh& mesh);

/// Area (mm^2) of triangle t (indices into mesh.positions).
double triangleArea(const Mesh& mesh, const std::array<uint32_t, 3>& t);

/// Signed volume (mm^3) by the divergence theorem; positive for a closed,
/// outward-oriented mesh. Meaningless for an open mesh.
double signedVolume(const Mesh& mesh);

}  // namespace tsf
