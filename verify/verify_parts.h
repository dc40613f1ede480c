// verifyParts: the verifier for a model written as several parts (a
// multi-part 3MF, gen/geometry/mesh_parts.h).
//
// Each part alone gets verifyModel's solid checks (no Scene, no reference):
// closed, manifold, outward, no self-intersections. The first part is the
// body the others stand on: it must be one piece and gets the printability
// checks too; a later part may be several pieces (the braille dots) and is
// not judged for printability alone (a dome alone is thin at its rim; what
// prints is the dome on the plate, judged in the one-solid model). Then the assembly, the parts
// together:
//   [parts_overlap]  no two parts fill the same volume; touching is fine
//                    (verify/assembly_checks.h);
//   with a Scene, the values read back (verify/readback.h) and tilted tops
//   (verify/tilt_readback.h) on the parts side by side: a ray from above meets
//   the highest surface of any part, which is what a finger meets.
// The report passes iff every part's report and the assembly's pass.
// Millimetres, model frame. Never throws for a bad mesh.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/geometry/mesh_parts.h"
#include "gen/model/scene.h"
#include "verify/verify_model.h"

namespace tsf {

struct PartReport {
    std::string name;     ///< the part's name (3MF object name)
    VerifyReport report;  ///< the part alone
};

struct PartsVerifyReport {
    std::vector<PartReport> parts;
    VerifyReport assembly;  ///< the parts together: [parts_overlap], values read back
    bool passed() const;
};

/// Verifies parts as above; options.name names the file, options.reference
/// is not used (compare a one-part model instead).
PartsVerifyReport verifyParts(const std::vector<MeshPart>& parts, const Scene* scene, const VerifyOptions& options);

/// Each part's report under a "part N of M: NAME" heading, then the
/// assembly's, then one verdict line.
std::string formatPartsReport(const PartsVerifyReport& report);

/// {"format": "tsf-verify-parts-report", "version": 1, "passed", "parts":
/// [{"name", "report": <tsf-verify-report>}], "assembly": <tsf-verify-report>}.
nlohmann::json toJson(const PartsVerifyReport& report);

}  // namespace tsf
