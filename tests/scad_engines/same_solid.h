// The check every render test of the generated OpenSCAD file makes: an
// engine's render of a Scene's file is the direct mesher's solid (volume,
// bounding box, the same surface plane by plane with the exact kernel, every
// cell read back, the solid checks: closed, manifold, one piece, no
// self-intersection, no zero-area triangle).
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>

#include "engine_fixtures.h"
#include "gen/mesh/direct_mesher.h"
#include "gen/mesh_io/stl_reader.h"
#include "runners/openscad/engine_output_check.h"
#include "verify/verify_model.h"

namespace tsf::test {

namespace same_solid_fs = std::filesystem;

inline const EngineOrReason& engineNamed(const std::string& name) {
    return name == "wasm" ? wasmEngine() : nativeEngine();
}

// The bar for "the same solid": volumes equal to 1e-6 relative.
inline constexpr double kVolumeRelativeTolerance = 1e-6;

// Largest |coordinate| of a mesh (mm): scales the float32 rounding of STL.
inline double maxAbsCoordinate(const Mesh& m) {
    double r = 0;
    for (const Vec3& p : m.positions) r = std::max({r, std::abs(p.x), std::abs(p.y), std::abs(p.z)});
    return r;
}

// Checks `mesh` (an engine's render, read back) against `direct`, the direct
// mesher's mesh of `scene`: volume, bounding box, the same surface plane by
// plane, every cell read back, the solid checks.
inline void expectSameMesh(const std::string& engine_name, const Mesh& mesh, const Scene& scene, const Mesh& direct,
                    const same_solid_fs::path& out) {
    const double direct_volume_mm3 = signedVolume(direct);
    EXPECT_LE(std::abs(signedVolume(mesh) - direct_volume_mm3), kVolumeRelativeTolerance * direct_volume_mm3)
        << engine_name << ": volume " << signedVolume(mesh) << " vs direct " << direct_volume_mm3;
    const Bounds a = meshBounds(mesh), b = meshBounds(direct);
    const double rounding_mm = maxAbsCoordinate(direct) * kStlCoordinateRoundoff;
    for (auto [x, y] : {std::pair{a.min.x, b.min.x}, {a.min.y, b.min.y}, {a.min.z, b.min.z}, {a.max.x, b.max.x},
                        {a.max.y, b.max.y}, {a.max.z, b.max.z}})
        EXPECT_NEAR(x, y, rounding_mm) << engine_name << ": bounding boxes differ";

    VerifyOptions vo;
    vo.name = out.string();
    vo.printability = false;
    vo.reference = &direct;  // the same surface, plane by plane (verify/agreement.h)
    vo.reference_name = "direct mesher";
    vo.exact = true;  // exact predicates and constructions: a self-touching corner is found for sure
    const VerifyReport report = verifyModel(mesh, &scene, vo);
    EXPECT_TRUE(report.passed()) << engine_name << ":\n" << formatReport(report);
    ASSERT_TRUE(report.readback.has_value());
    EXPECT_EQ(report.readback->cells_checked, scene.keptCount());
    EXPECT_EQ(report.readback->over_tolerance, 0u);
}

// Renders `scad` with `engine` and checks the result against `scene`.
inline void expectSameSolid(const ScadEngine& engine, const Scene& scene, const same_solid_fs::path& scad, const same_solid_fs::path& out,
                     const ScadRenderRequest& base = {}) {
    ScadRenderRequest rq = base;
    rq.scad_path = scad.string();
    rq.output_path = out.string();
    rq.timeout_s = 300;
    const Mesh direct = meshScene(scene);
    EngineOutputCheck check;
    const ScadRenderResult r = renderScadChecked(engine, rq, {}, {signedVolume(direct)}, &check);
    ASSERT_TRUE(r.ok()) << engine.name() << ": " << r.summary << "\n" << r.output;
    EXPECT_TRUE(check.ok) << check.problem;
    expectSameMesh(engine.name(), readStl(out.string()), scene, direct, out);
}

}  // namespace tsf::test
