// The printed halves and pins. See halves_mesh.h.
#include "gen/mesh/halves_mesh.h"

#include <cassert>
#include <cmath>

#include "gen/mesh/direct_mesher.h"
#include "gen/model/scene.h"
#include "gen/model/features/halves.h"

namespace tsf {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The model's depth (mm) on the 1 um grid: the line the lower half is reflected about is its middle.
double modelDepthMm(const Scene& scene) { return snapXy(gridDepth(scene.grid, scene.pitch_mm, scene.y_scale)); }

Mesh reflectY(const Mesh& m, double depth_mm) {
    Mesh out;
    out.positions.reserve(m.positions.size());
    for (const Vec3& p : m.positions) out.positions.push_back({p.x, snapXy(depth_mm - p.y), p.z});
    out.triangles.reserve(m.triangles.size());
    for (const auto& t : m.triangles) out.triangles.push_back({t[0], t[2], t[1]});
    return out;
}

}  // namespace

Mesh meshHalf(const Scene& scene, HalfKind kind) {
    assert(scene.halves && kind != HalfKind::Whole);
    const Mesh half = meshScene(halfScene(scene, kind));
    return kind == HalfKind::Upper ? half : reflectY(half, modelDepthMm(scene));
}

Mesh turnLowerHalf(const Mesh& printed, const Scene& scene) { return reflectY(printed, modelDepthMm(scene)); }

Mesh pinMesh(const PinGeometry& pins, double x_mm, double y_mm) {
    Mesh m;
    const uint32_t n = uint32_t(kHoleSides);
    const double top = snapXy(pins.pin_length_mm);
    for (double z : {0.0, top})
        for (uint32_t k = 0; k < n; ++k) {
            const double a = 2 * kPi * (k + 0.5) / n;
            m.positions.push_back({snapXy(x_mm + pins.pin_radius_mm * std::cos(a)),
                                   snapXy(y_mm + pins.pin_radius_mm * std::sin(a)), z});
        }
    for (uint32_t k = 0; k < n; ++k) {
        const uint32_t a0 = k, b0 = (k + 1) % n, a1 = a0 + n, b1 = b0 + n;
        m.triangles.push_back({a0, b0, b1});  // the side faces out
        m.triangles.push_back({a0, b1, a1});
    }
    for (uint32_t k = 1; k + 1 < n; ++k) {
        m.triangles.push_back({0, k + 1, k});              // bottom, facing down
        m.triangles.push_back({n, n + k, n + k + 1});      // top, facing up
    }
    return m;
}

Mesh pinsMesh(const PinGeometry& pins) {
    Mesh m;
    // Three diameters apart: room for the slicer's perimeters and a fingertip.
    const double spacing = 3 * 2 * pins.pin_radius_mm;
    for (int p = 0; p < kPinCount; ++p) {
        const Mesh one = pinMesh(pins, pins.pin_radius_mm + p * spacing, pins.pin_radius_mm);
        const uint32_t base = uint32_t(m.positions.size());
        m.positions.insert(m.positions.end(), one.positions.begin(), one.positions.end());
        for (const auto& t : one.triangles) m.triangles.push_back({t[0] + base, t[1] + base, t[2] + base});
    }
    return m;
}

}  // namespace tsf
