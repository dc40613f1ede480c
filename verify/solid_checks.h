// Solid checks: is this mesh a printable solid?
//
// Runs, in order (check ids in brackets; docs/verifier.md has the details):
//   topology from the indices alone (verify/mesh_topology.h):
//     [valid_input]            finite coordinates, indices in range
//     [closed]                 no border edges; offenders are the holes
//     [manifold_edges]         no edge with three or more triangles
//     [manifold_vertices]      no vertex where two fans of triangles touch
//     [consistent_orientation] neighbours traverse their shared edge in opposite directions;
//                              offenders are the triangles that disagree with their neighbours
//     [single_piece]           exactly one edge-connected component (a model in several
//                              pieces falls apart on the printer bed)
//     [distinct_vertices]      no two vertices at exactly the same position (warning)
//   geometry with CGAL (Epick by default; Epeck when exact):
//     [degenerate_faces]       no triangle with a repeated index or three collinear points
//     [self_intersections]     no two triangles meeting other than at a shared vertex or edge
//                              (broad phase: the verifier's column grid, verify/column_grid.h)
//     [outward_orientation]    every component has positive volume (needs a closed,
//                              consistently oriented manifold; else skipped)
// Positions are millimetres in the model frame; offenders carry mm positions.
// Empty mesh: [single_piece] fails ("no triangles"); the others pass or skip.
#pragma once

#include <memory>
#include <vector>

#include "gen/geometry/mesh.h"
#include "verify/report.h"
#include "verify/column_grid.h"

namespace tsf {

struct SolidOptions {
    bool exact = false;        ///< use the exact-construction kernel (slower; see docs/verifier.md)
    size_t max_offenders = 10; ///< per check
    /// Test for self-intersections (CGAL; about 4 us per triangle). Skipping
    /// it is reported as a skipped check, never as a pass.
    bool self_intersections = true;
    /// [single_piece] passes with several pieces (noted): a part of a
    /// multi-part model that stands on another part (verify/verify_parts.h).
    bool pieces_allowed = false;
    /// The verifier's column grid of this mesh, when the caller has one;
    /// else checkSolid builds one for the self-intersection test (after the
    /// topology, whose memory is free by then) and hands it back in
    /// SolidResult::grid.
    const ColumnGrid* grid = nullptr;
};

struct SolidResult {
    MeshSummary mesh;          ///< name and read_notes left empty
    std::vector<Check> checks;
    std::vector<Stage> stages;
    bool closed_oriented_manifold = false;  ///< closed, manifold, consistently oriented, finite
    /// The grid checkSolid built, if it built one (for the ray checks). It
    /// reads the checked mesh in place: keep that mesh alive while using it.
    std::unique_ptr<ColumnGrid> grid;
};

SolidResult checkSolid(const Mesh& mesh, const SolidOptions& options);

}  // namespace tsf
