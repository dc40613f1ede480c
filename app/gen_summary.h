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
    std::string verify_text;
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

/// Human-readable summary (several lines, each "label  text").
std::string formatSummary(const GenSummary& s);
/// The same facts as JSON.
nlohmann::json summaryJson(const GenSummary& s);

/// Facts about a Scene alone (also used by `tsf info`).
nlohmann::json sceneFactsJson(const Scene& scene);
std::string formatSceneFacts(const Scene& scene);

}  // namespace tsf::cli
