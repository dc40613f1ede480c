// Hand-drawn meshes for tests, counter-clockwise seen from outside. Part of
// the shared test support (tests/support/).
#pragma once

#include <cstdint>

#include "gen/geometry/mesh.h"

namespace tsf::test {

// Axis-aligned box from lo to hi.
//
//        7-------6
//       /|      /|          z
//      4-------5 |          |  y
//      | 3-----|-2          | /
//      |/      |/           |/
//      0-------1            +---- x
//
// 0 = lo, 6 = hi; 4..7 are 0..3 raised to hi.z.
inline Mesh box(Vec3 lo, Vec3 hi) {
    Mesh m;
    for (int i = 0; i < 8; ++i) {
        const bool x = i == 1 || i == 2 || i == 5 || i == 6;
        const bool y = i == 2 || i == 3 || i == 6 || i == 7;
        const bool z = i >= 4;
        m.positions.push_back({x ? hi.x : lo.x, y ? hi.y : lo.y, z ? hi.z : lo.z});
    }
    m.triangles = {{0, 3, 2}, {0, 2, 1},   // bottom, -z
                   {4, 5, 6}, {4, 6, 7},   // top, +z
                   {0, 1, 5}, {0, 5, 4},   // front, -y
                   {1, 2, 6}, {1, 6, 5},   // right, +x
                   {2, 3, 7}, {2, 7, 6},   // back, +y
                   {3, 0, 4}, {3, 4, 7}};  // left, -x
    return m;
}

/// Cube of side s with its lowest corner at o (vertices numbered as in box()).
inline Mesh cube(double s = 1.0, Vec3 o = {}) { return box(o, {o.x + s, o.y + s, o.z + s}); }

// Right-angled tetrahedron, volume 4*3*5/6 = 10: corner 0 = (0,0,0), 1 =
// (4,0,0) on x, 2 = (0,3,0) on y, 3 = (0,0,5) on z.
//
// Faces: {0,2,1} base (normal -z), {0,1,3} (normal -y), {0,3,2} (normal -x),
// {1,2,3} slanted (normal (15,20,12)/sqrt(769)).
inline Mesh tetrahedron() {
    Mesh m;
    m.positions = {{0, 0, 0}, {4, 0, 0}, {0, 3, 0}, {0, 0, 5}};
    m.triangles = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
    return m;
}

/// a and b in one mesh (b's indices shifted); no vertex is shared.
inline Mesh append(Mesh a, const Mesh& b) {
    const uint32_t off = uint32_t(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles) a.triangles.push_back({t[0] + off, t[1] + off, t[2] + off});
    return a;
}

}  // namespace tsf::test
