// VerifyReport: what the verifier found, for people and for programs.
//
// A report is a list of checks. Each check has a stable id (the --json key a
// script can rely on), a status, the number of offenders, the worst few with
// their position in millimetres (model frame: x east, y north, z up), and the
// time it took. Figures that belong to one family of checks (the mesh summary,
// the values read back, the agreement with a reference, printability) are kept
// in their own structs next to the list.
//
// Status rules: a check that could not run (its precondition failed, e.g. the
// volume of an open mesh) is Skipped with a note saying why; a Skipped check
// is not a failure by itself, the check that made it impossible is. Warn is
// used by printability checks unless VerifyOptions::fail_on_warnings.
//
// The report passes iff no check has status Fail.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/geometry/mesh.h"

namespace tsf {

enum class CheckStatus { Pass, Fail, Warn, Skipped };
const char* toString(CheckStatus);  ///< "pass", "fail", "warn", "skipped"

/// One place where a check found a problem.
struct Offender {
    Vec3 at_mm;          ///< where (mm, model frame)
    double amount = 0;   ///< check-specific magnitude (see the check's `unit`); NaN if none
    std::string detail;  ///< one line a person can act on ("edge 12-13 has 1 triangle")
};

struct Check {
    std::string id;       ///< stable key, e.g. "closed", "self_intersections" (docs/verifier.md)
    std::string title;    ///< short human name
    CheckStatus status = CheckStatus::Skipped;
    int64_t count = 0;    ///< offenders found
    std::string unit{};   ///< unit of Offender::amount ("mm", "mm^3", "" for none)
    std::vector<Offender> worst{};  ///< the worst offenders, worst first, at most VerifyOptions::max_offenders
    std::string note{};   ///< one line: what was measured, or why the check was skipped
    double time_ms = 0;   ///< wall time of the stage that produced this check (see VerifyReport::stages)
    std::string stage{};  ///< that stage's name; checks produced together share one stage
};

/// A timed step of the verifier (several checks can come from one step).
struct Stage {
    std::string name;  ///< "topology", "degenerate", "cgal_mesh", "self_intersections", ...
    double time_ms = 0;
};

/// Basic facts about the mesh that was checked.
struct MeshSummary {
    std::string name;                 ///< file path or "(in memory)"
    size_t vertex_count = 0;
    size_t triangle_count = 0;
    size_t edge_count = 0;
    Bounds bounds;                    ///< mm
    double volume_mm3 = 0;            ///< CGAL volume when closed and oriented; else NaN
    double signed_volume_mm3 = 0;     ///< divergence theorem over all triangles (always computed)
    double area_mm2 = 0;
    size_t component_count = 0;
    size_t unreferenced_vertices = 0;
    size_t duplicate_position_vertices = 0;
    std::vector<std::string> read_notes;  ///< what the reader had to do to build the mesh (merges, repairs)
};

/// One kept cell's measured heights (values read back).
struct CellReadback {
    int32_t col = 0, row = 0;          ///< grid cell
    double x_mm = 0, y_mm = 0;         ///< where the ray was cast
    std::string surface;               ///< "top" or "bottom"
    double expected_mm = 0;            ///< z the scene asks for
    double measured_mm = 0;            ///< z the ray met; NaN when the ray missed the mesh
    double error_mm = 0;               ///< measured - expected (NaN when missed)
    double value = 0;                  ///< the cell's data value (NaN = no data)
    double value_read = 0;             ///< value the measured height stands for (NaN for no-data cells)
    double value_error = 0;            ///< value_read - the value clamped to the mapped range (NaN for no data)
};

struct ReadbackFigures {
    size_t cells_checked = 0;          ///< kept cells
    size_t surfaces_checked = 0;       ///< rays cast at kept cells (top and bottom)
    size_t missed = 0;                 ///< rays that met no triangle
    size_t over_tolerance = 0;         ///< surfaces off by more than tolerance_mm
    double tolerance_mm = 0;           ///< height_step_tolerance_mm + float32_rounding_mm
    double height_step_tolerance_mm = 0;  ///< half the z snap step: the measured height rounds to the expected step
    double float32_rounding_mm = 0;    ///< largest rounding of a z coordinate stored as float32 (STL)
    double max_error_mm = 0;           ///< max |error_mm| over surfaces that were met
    double mean_error_mm = 0;          ///< mean |error_mm|
    double max_value_error = 0;        ///< max |value_error| (data units)
    double mean_value_error = 0;
    size_t outside_cells_checked = 0;  ///< grid cells that are not kept (rays must miss)
    size_t outside_cells_hit = 0;      ///< ... that met material
    std::vector<CellReadback> worst;   ///< largest |error_mm| first (missed rays first of all)
};

/// Tilted tops read back (verify/tilt_readback.h).
struct TiltReadbackFigures {
    size_t cells_checked = 0;          ///< cells with a tilted top
    size_t missed = 0;                 ///< rays that met no surface
    size_t over_tolerance = 0;         ///< surfaces whose slope is off by more than the cell's tolerance
    double max_error_top = 0;          ///< max |measured - Scene slope| on the tops, mm per mm
    double max_error_bottom = 0;       ///< the same on mirrored bottoms (0 when flat)
    double max_top_bottom = 0;         ///< max |top slope - bottom slope| as measured (mirrored)
    double max_tolerance = 0;          ///< the largest per-cell tolerance used, mm per mm
    double max_slope = 0;              ///< steepest Scene slope, mm per mm
    std::vector<std::string> worst;    ///< the worst cells, described
};

struct AgreementFigures {
    std::string reference;             ///< reference mesh name
    size_t reference_triangles = 0;
    double volume_mm3 = 0;             ///< this model
    double reference_volume_mm3 = 0;
    double volume_difference_mm3 = 0;  ///< this - reference
    double volume_tolerance_mm3 = 0;   ///< area * distance tolerance (a shell of that thickness)
    /// Largest distance found from this mesh to the reference: sampled on the
    /// triangles not proven to lie on the reference, 0 when all are. A lower
    /// bound of the true Hausdorff distance.
    double hausdorff_to_reference_mm = 0;
    double hausdorff_from_reference_mm = 0;  ///< the same from the reference to this mesh
    /// Each true Hausdorff distance lies in [figure, figure + this]: the
    /// sampling radius, or rounding_bound_mm if larger. 0 when the exact
    /// comparison proved the surfaces the same.
    double hausdorff_error_bound_mm = 0;
    double distance_tolerance_mm = 0;
    bool surfaces_compared = false;    ///< the exact surface comparison ran (coordinates on one integer grid)
    bool surfaces_identical = false;   ///< ... and proved the two surfaces the same
    size_t planes = 0;                 ///< distinct planes holding triangles of either mesh
    size_t differing_planes = 0;       ///< planes where the two surfaces differ
    size_t opposite_planes = 0;        ///< planes where they coincide but face opposite ways (inside out)
    double differing_area_mm2 = 0;            ///< this model's area left to sampling
    double reference_differing_area_mm2 = 0;  ///< the reference's area left to sampling
    std::string rounded_to;            ///< roundings under which more triangles matched ("float32", a grid); "" none
    double rounding_bound_mm = 0;      ///< distance proven on the triangles those roundings matched (0 if none)
    size_t samples = 0;                ///< distance samples taken on those areas, both directions
    size_t sample_budget = 0;          ///< the budget the sampling radius was chosen for
};

struct PrintabilityFigures {
    double nozzle_mm = 0;
    double layer_mm = 0;
    double min_wall_mm = 0;     ///< thinnest horizontal thickness found (NaN if none measured)
    double min_gap_mm = 0;      ///< narrowest gap between two walls facing each other (NaN if none within 10 nozzle widths)
    double min_slab_mm = 0;     ///< thinnest vertical thickness (base, mirrored slab) (NaN if none)
    std::optional<Vec3> bed_mm; ///< bed size when given
    bool fits_bed = true;
    bool fits_bed_rotated = false;  ///< fits only when turned by 90 degrees about z
    double overhang_area_mm2 = 0;   ///< surface facing down more than 45 degrees from the vertical, off the bed
    double overhang_max_height_mm = 0;  ///< the highest of it above the bed (supports that tall)
};

struct VerifyReport {
    MeshSummary mesh;
    bool exact = false;                     ///< exact-construction kernel used
    std::vector<Check> checks;              ///< in the order they ran
    std::optional<ReadbackFigures> readback;
    std::optional<TiltReadbackFigures> tilt;
    std::optional<AgreementFigures> agreement;
    std::optional<PrintabilityFigures> printability;
    std::vector<Stage> stages;              ///< in the order they ran
    double total_ms = 0;

    bool passed() const;
    size_t countStatus(CheckStatus s) const;
    /// The check with this id, or nullptr.
    const Check* find(const std::string& id) const;
};

/// A few lines for people: mesh facts, one line per check (status, count,
/// note), the worst offenders with coordinates, the time of each stage, and a
/// verdict.
std::string formatReport(const VerifyReport& report);

/// Every figure of the report; schema in docs/verifier.md ("format": "tsf-verify-report", "version": 1).
/// NaN numbers are written as null.
nlohmann::json toJson(const VerifyReport& report);

}  // namespace tsf
