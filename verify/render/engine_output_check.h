// Engine output check: a rendered mesh counts as a success only when it is a
// solid. OpenSCAD's own verdict is not enough: OpenSCAD 2021.01 prints
// "Simple: yes" and the WebAssembly build with Manifold prints "NoError" for
// unions that come out open or with a wrong volume (docs/engines.md).
//
// checkEngineMesh is the cheap, purely topological gate (no CGAL; the full
// verifier in verify/ adds self-intersections and the values read back):
//   [empty]        the mesh has triangles;
//   [degenerate]   no triangle repeats a vertex (after exact vertex merging);
//   [edges]        every directed edge a->b occurs exactly once and its
//                  reverse b->a exactly once: closed, every edge has two
//                  triangles, neighbours consistently oriented;
//   [pieces]       one connected piece (triangles linked through shared vertices);
//   [volume]       positive signed volume (outward normals), and, when the
//                  expected volume is known, equal to it within the rounding
//                  of the file's coordinates (see kStlCoordinateRoundoff);
//   [solid_check]  the caller's own check, if any (EngineOutputExpectation).
// renderScadChecked puts the rule "a bad mesh is an engine failure" in one
// place: the output file appears only when the engine succeeded and its mesh
// passes.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "gen/mesh.h"
#include "verify/render/openscad_runner.h"

namespace tsf {

/// Relative rounding of one coordinate written to binary STL (float32 unit
/// roundoff, 2^-24). The volume tolerance is a shell of that thickness times
/// the largest coordinate over the whole surface: area * max|coordinate| * this.
inline constexpr double kStlCoordinateRoundoff = 5.9604644775390625e-8;

struct EngineOutputExpectation {
    /// Volume of the solid the file should describe (mm^3), e.g. the direct
    /// mesher's volume of the same Scene; unknown for an edited file or one
    /// rendered with -D / -p overrides.
    std::optional<double> volume_mm3;
    /// A further check of the mesh, run last and only when every check above
    /// passed: e.g. the verifier's self-intersection test (verify/solid_checks.h),
    /// which this library cannot call itself. Returns "" for a good mesh, else
    /// one line saying what is wrong. Empty function = none.
    std::function<std::string(const Mesh&)> solid_check;
};

struct EngineOutputCheck {
    bool checked = false;           ///< false: the format cannot be read back (AMF, PNG); nothing was checked
    bool ok = false;                ///< checked and every check passed
    std::string problem;            ///< first failed check, one line for people ("" when ok or not checked)
    size_t triangles = 0;
    size_t degenerate_triangles = 0;   ///< triangles repeating a vertex
    size_t open_edges = 0;             ///< directed edges whose reverse is missing
    size_t overused_edges = 0;         ///< directed edges occurring more than once
    size_t pieces = 0;
    double volume_mm3 = 0;             ///< signed volume of the mesh
    double volume_tolerance_mm3 = 0;   ///< allowed |volume - expected| (see kStlCoordinateRoundoff)
};

/// Runs the checks listed in the file comment on `mesh` (mm).
EngineOutputCheck checkEngineMesh(const Mesh& mesh, const EngineOutputExpectation& expect = {});

/// Reads the mesh file at path (STL, OFF, 3MF, OBJ, recognised by content
/// when the extension is not one of those) and checks it. A file that cannot
/// be read is a failed check with the reader's message. AMF and PNG files
/// give checked = false.
EngineOutputCheck checkEngineOutputFile(const std::string& path, ScadExportFormat format,
                                        const EngineOutputExpectation& expect = {});

/// renderScad(engine, request, progress), then checkEngineOutputFile on what
/// it wrote. When the engine succeeded but the check fails, the result
/// becomes Status::Failed with summary "<engine> wrote a broken mesh: ..."
/// and no file appears at request.output_path (an existing one is left
/// untouched, as for any failed render). *check (if given) receives the check.
/// Throws what renderScad throws.
ScadRenderResult renderScadChecked(const ScadEngine& engine, const ScadRenderRequest& request,
                                   const ScadProgress& progress = {}, const EngineOutputExpectation& expect = {},
                                   EngineOutputCheck* check = nullptr);

}  // namespace tsf
