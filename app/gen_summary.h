// The one-screen summary of a generated model, for people and (--json) programs.
#pragma once

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/field/hex_field.h"
#include "gen/geometry/mesh.h"
#include "gen/model/scene.h"

namespace tsf::cli {

struct GenSummary {
    std::string input;
    const HexField* field = nullptr;
    const Scene* scene = nullptr;
    const Mesh* mesh = nullptr;
    std::vector<std::pair<std::string, std::string>> outputs;  ///< (path, what)
    std::vector<std::pair<std::string, double>> timings_ms;    ///< stage -> ms
    nlohmann::json verify;  ///< verifier report, null when not run
    std::string verify_text;  ///< the verdict, the read-back, what did not pass
    std::string checks_text;  ///< the names of the checks passed (details)
    std::vector<std::string> printer_notes;  ///< what --bed, --nozzle, --layer changed (printer_fit.h)
    nlohmann::json halves;   ///< --halves: the pieces, their checks and figures (halves_output.h); null otherwise
    std::string halves_text;
    nlohmann::json tiles;    ///< --tile: the tiles, their checks and the assembly's (tiles_output.h); null otherwise
    std::string tiles_text;
    std::string supports_text;  ///< a one-piece mirrored model: the supports it needs
    /// Defaults that pass (legible_defaults.h): what changed and why, or why nothing passes.
    std::vector<std::string> legibility;
    nlohmann::json legibility_json;
};

/// Human-readable summary, for a screen reader as much as a screen: what
/// was written and what to check first, then the model's size and
/// heights, then the details; lines of at most about 80 characters,
/// "by" for dimensions and words for arrows (spokenText).
std::string formatSummary(const GenSummary& s);
/// The same facts as JSON.
nlohmann::json summaryJson(const GenSummary& s);

/// Facts about a Scene alone (also used by `tsf info`).
nlohmann::json sceneFactsJson(const Scene& scene);
/// with_size_and_heights false: without the size and heights lines (the
/// gen summary says them first).
std::string formatSceneFacts(const Scene& scene, bool with_size_and_heights = true);

}  // namespace tsf::cli
