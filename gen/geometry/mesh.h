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

inline Vec3 sub(const Vec3& a, const Vec3& b) { return {a.x - b.x, a.y - b.y, a.z - b.z}; }
inline Vec3 cross(const Vec3& a, const Vec3& b) { return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x}; }
inline double dot(const Vec3& a, const Vec3& b) { return a.x * b.x + a.y * b.y + a.z * b.z; }

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

/// `b` widened to hold `p` with plain comparisons, not std::fmin/fmax (a
/// call into libm per coordinate) and with the same bits, as long as the
/// bound is never NaN (it starts at +-infinity): a NaN coordinate fails
/// both tests and is skipped as fmin skips it, and on a tie the coordinate
/// is taken as glibc's fmin/fmax take their second argument (which decides
/// between -0 and +0).
inline void extendBounds(Bounds& b, const Vec3& p) {
    const auto lower = [](double m, double q) { return q <= m ? q : m; };
    const auto upper = [](double m, double q) { return q >= m ? q : m; };
    b.min = {lower(b.min.x, p.x), lower(b.min.y, p.y), lower(b.min.z, p.z)};
    b.max = {upper(b.max.x, p.x), upper(b.max.y, p.y), upper(b.max.z, p.z)};
}

/// Area (mm^2) of triangle t (indices into mesh.positions).
double triangleArea(const Mesh& mesh, const std::array<uint32_t, 3>& t);

/// Signed volume (mm^3) by the divergence theorem; positive for a closed,
/// outward-oriented mesh. Meaningless for an open mesh.
double signedVolume(const Mesh& mesh);

}  // namespace tsf
