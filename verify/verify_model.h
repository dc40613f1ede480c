// verifyModel: the verifier's one entry point.
//
// Runs, on one mesh:
//   1. the solid checks (verify/solid_checks.h), always;
//   2. the values read back against a Scene (verify/readback.h), when a Scene is given;
//   3. the agreement with a reference mesh (verify/agreement.h), when one is given;
//   4. the printability warnings (verify/printability.h), unless turned off;
//   5. the tactile checks (verify/tactile.h), when asked for.
// and returns one VerifyReport (verify/report.h): report.passed() is the
// verdict, formatReport() the text for people, toJson() the figures.
//
// Units: millimetres, model frame (x east, y north, z up). Never throws for a
// bad mesh (a bad mesh is a failing report); throws std::bad_alloc only.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"
#include "verify/agreement.h"
#include "verify/printability.h"
#include "verify/report.h"

namespace tsf {

struct VerifyOptions {
    std::string name;                     ///< shown in the report (file path); "" = "(in memory)"
    std::vector<std::string> read_notes;  ///< what reading the file needed (from MeshReadReport), shown as is
    bool exact = false;                   ///< exact-construction kernel for the solid checks
    bool self_intersections = true;       ///< false: skip the (slowest) self-intersection test, reported as skipped
    size_t max_offenders = 10;            ///< worst offenders listed per check
    bool pieces_allowed = false;          ///< [single_piece] passes with several pieces (a part standing on another)

    // Values read back (used when a Scene is given).
    double height_tolerance_mm = 0;       ///< 0 = half the Scene's z snap step (see readback.h)

    // Agreement (used when `reference` is set; not owned, must outlive the call).
    const Mesh* reference = nullptr;
    std::string reference_name;
    double distance_tolerance_mm = kDefaultAgreementToleranceMm;

    // Printability.
    bool printability = true;
    double nozzle_mm = kDefaultNozzleMm;
    double layer_mm = kDefaultLayerMm;
    std::optional<Vec3> bed_mm;
    bool fail_on_warnings = false;        ///< printability warnings fail the report

    // The model as a hand reads it (verify/tactile.h): sharp points, knife
    // edges, places a fingertip cannot reach, and with a Scene the marks.
    bool tactile = false;
    bool tactile_as_warnings = false;     ///< a tactile check that fails is a warning (tsf gen's self-check)
    double tactile_sample_mm = 0.5;       ///< spacing of the top surface's samples for the fingertip's reach
};

/// Verifies `mesh`; `scene` (nullable) is the Scene it was made from, for the
/// values read back.
VerifyReport verifyModel(const Mesh& mesh, const Scene* scene, const VerifyOptions& options);

}  // namespace tsf
