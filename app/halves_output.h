// `tsf gen --mirror --halves`: the two halves and the pins, verified and
// written instead of the one-piece model (gen/model/features/halves.h).
#pragma once

#include <string>

#include "app/gen_summary.h"
#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_writer.h"
#include "gen/model/scene.h"
#include "pipeline/verified_model.h"
#include "verify/verify_model.h"

namespace tsf::cli {

/// The files -o MODEL.ext becomes: MODEL-upper.ext, MODEL-lower.ext, MODEL-pins.ext.
struct HalvesPaths {
    std::string upper, lower, pins;
};
HalvesPaths halvesPaths(const std::string& output);

/// The halves' figures and checks (pipeline/verified_model.h makes and
/// verifies the pieces) for the summary: summary.halves and halves_text.
void summarizeHalves(const VerifiedHalves& halves, GenSummary& summary);

/// Writes the pieces to halvesPaths(output) and lists them in the summary.
void writeHalves(const VerifiedHalves& pieces, const std::string& output, const MeshWriteOptions& wo, GenSummary& summary);

/// The pieces side by side (upper, lower, pins along x, 10 mm apart), for the preview.
Mesh halvesSideBySide(const VerifiedHalves& pieces);

/// The summary line for a one-piece mirrored model: the supports its
/// underside needs (from the verifier's overhang figures); "" when none.
std::string supportsText(const VerifyReport& report);

}  // namespace tsf::cli
