// Engine output check: a rendered mesh counts as a success only when it is a
// solid. OpenSCAD's own verdict is not enough: OpenSCAD 2021.01 prints
// "Simple: yes" and the WebAssembly build with Manifold prints "NoError" for
// unions that come out open or with a wrong volume (docs/engines.md).
//
// checkEngineMesh judges the mesh with the verifier's own analyses, in order:
//   [empty]        the mesh has triangles;
//   topology from the indices (verify/mesh_topology.h, no CGAL):
//   [valid]        every index refers to a vertex, every coordinate is finite;
//   [degenerate]   no triangle repeats a vertex (after exact vertex merging);
//   [edges]        every edge has exactly two triangles, which traverse it in
//                  opposite directions: closed, manifold, consistently oriented;
//   [vertices]     no vertex where two fans of triangles touch;
//   [pieces]       one edge-connected piece;
//   [volume]       positive signed volume (outward normals), and, when the
//                  expected volume is known, equal to it within the rounding
//                  of the file's coordinates (see kStlCoordinateRoundoff);
//   [solid]        when asked (EngineOutputExpectation::solid_checks), the
//                  verifier's solid checks with CGAL (verify/solid_checks.h).
// renderScadChecked puts the rule "a bad mesh is an engine failure" in one
// place: the output file appears only when the engine succeeded and its mesh
// passes.
#pragma once

#include <cstddef>
#include <optional>
#include <string>

#include "gen/geometry/mesh.h"
#include "runners/openscad/openscad_runner.h"

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
    /// Also run the verifier's solid checks (checkSolid with the exact kernel),
    /// last and only when every check above passed: they see what the indices
    /// cannot, such as self-intersections (a T-junction Manifold left at one
    /// corner, docs/engines.md) and zero-area triangles. About 4 us per
    /// triangle; `tsf render` turns them on. The exact kernel because the
    /// filtered one can stop on a CGAL precondition for such near-degenerate
    /// input.
    bool solid_checks = false;
};

struct EngineOutputCheck {
    bool checked = false;           ///< false: the format cannot be read back (AMF, PNG); nothing was checked
    bool ok = false;                ///< checked and every check passed
    std::string problem;            ///< first failed check, one line for people ("" when ok or not checked)
    size_t triangles = 0;
    size_t degenerate_triangles = 0;   ///< triangles repeating a vertex
    size_t open_edges = 0;             ///< edges with one triangle (MeshTopology::border_edges)
    size_t overused_edges = 0;         ///< edges traversed twice in one direction or with three or more triangles
    size_t pinched_vertices = 0;       ///< vertices where two fans of triangles touch
    size_t pieces = 0;                 ///< edge-connected pieces
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
