// makeVerifiedModel: a Scene -> the model tsf writes, already proven: its
// direct mesh and self-check, and, as the Scene and the request ask, its
// parts for a multi-part 3MF and its support-free halves with their pins,
// each checked the way it prints. One call for every front end (the `tsf`
// command line is one), so no front end can write a model it did not
// verify, or verify it differently.
//
// A check that fails is a bug in tsf, not in the input: makeVerifiedModel
// throws ModelVerificationFailed with the failing report, and nothing of the
// model may be written.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/geometry/mesh_parts.h"
#include "gen/model/scene.h"
#include "verify/halves_check.h"
#include "verify/verify_model.h"
#include "verify/verify_parts.h"

namespace tsf {

/// Above this many triangles the default self-check leaves out the
/// self-intersection test and printability (minutes on a large model);
/// ModelRequest::verify_full keeps them.
inline constexpr size_t kQuickVerifyTriangles = 3'000'000;

struct ModelRequest {
    bool verify = true;         ///< false: mesh only (tsf gen --no-verify)
    bool verify_full = false;   ///< every check also above kQuickVerifyTriangles
    bool parts = false;         ///< mesh the parts of a multi-part 3MF (gen/mesh/scene_parts.h) and verify them
    /// The file stores float32 (STL, 3MF): the checks of what is written (the
    /// one solid, or each part, or each half and pin) run on the mesh as the
    /// file holds it (gen/mesh_io/float32_mesh.h), not on the doubles.
    bool stored_as_float32 = false;
    VerifyOptions verify_options;  ///< name, nozzle, layer, ... (the Scene is always the one given)
    /// Called with the mesh as soon as it is made, before any check: a front
    /// end's own early refusal (a model larger than the printer's bed) ends
    /// the call there by throwing.
    std::function<void(const Mesh&)> on_mesh;
    /// When set, the one solid is handed to it exactly as it is checked (as
    /// the file holds it) while it is verified, on a thread of its own: the
    /// file is written and synced during the checks instead of after them.
    /// Only where that solid is what a front end writes and checks run (no
    /// parts, no halves, verify on); not called when no thread can be had
    /// (VerifiedModel::written_ahead then stays false). What it writes must
    /// be discardable until the model has passed: tsf gen writes through an
    /// OutputSet that is committed only after every check. A failed check is
    /// thrown first, once the write has ended; an exception from the write
    /// is rethrown after the checks pass.
    std::function<void(const Mesh&)> write_ahead;
};

/// The support-free halves of a Scene with halves, as they print.
struct VerifiedHalves {
    Mesh upper, lower, pins;
    std::optional<VerifyReport> upper_report, lower_report, pin_report;  ///< each piece alone (when verified)
    std::optional<HalvesCheckResult> pair;                               ///< the halves as a pair (when verified)
};

struct VerifiedModel {
    Mesh mesh;                          ///< the one solid (meshScene)
    std::optional<VerifyReport> report; ///< its self-check, against the Scene (when verified)
    bool quick = false;                 ///< the self-check left out self-intersections and printability for size
    bool written_ahead = false;         ///< ModelRequest::write_ahead was handed the mesh and returned
    std::vector<MeshPart> parts;        ///< with ModelRequest::parts
    std::optional<PartsVerifyReport> parts_report;
    std::optional<VerifiedHalves> halves;  ///< when the Scene has halves
};

/// A model, or one of its pieces, that failed its own checks.
class ModelVerificationFailed : public std::runtime_error {
public:
    ModelVerificationFailed(std::string piece, std::string report)
        : std::runtime_error("the " + piece + " failed verification"), piece_(std::move(piece)),
          report_(std::move(report)) {}
    const std::string& piece() const { return piece_; }    ///< "generated model", "model's parts", "upper half", ...
    const std::string& report() const { return report_; }  ///< the report a person reads, every check

private:
    std::string piece_, report_;
};

/// See the file comment. `progress` (may be empty) is told the name of each
/// stage as it starts ("meshing", "verifying", "meshing parts", ...).
VerifiedModel makeVerifiedModel(const Scene& scene, const ModelRequest& request,
                                const std::function<void(const std::string&)>& progress = {});

}  // namespace tsf
