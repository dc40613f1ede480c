#include "app/gen_run/key_files.h"

#include <cctype>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "app/ground_scale.h"
#include "app/key_stamp.h"
#include "app/tiles_output.h"
#include "gen/key/braille_ready_file.h"
#include "gen/key/model_key.h"
#include "gen/key/spoken_text.h"
#include "gen/util/atomic_file.h"

namespace tsf::cli {

namespace {

// What the key says of the field, the run and the model as printed.
ModelKeyFacts keyFacts(const GenCommandOptions& o, const HexField& field, const Scene& scene,
                       const std::optional<VerifiedTiles>& tiles, const LegibilityOutcome& legibility) {
    ModelKeyFacts facts;
    facts.input_name = std::filesystem::path(o.gen.input).filename().string();
    facts.field_how = spokenText(field.how);
    facts.version = TSF_VERSION;
    facts.about = o.about;
    facts.description = field.input.description;
    facts.variable = field.input.variable;
    facts.step = field.input.step;
    facts.units = field.input.units;
    facts.per_hexagon = field.per_hexagon;
    facts.points = field.input.kind == "points";
    if (!facts.points) facts.data_min = field.input.min, facts.data_max = field.input.max;
    for (int32_t r = 0; r < field.grid.rows; ++r)
        for (int32_t c = 0; c < field.grid.cols; ++c)
            if (!std::isfinite(field.at(c, r)) && scene.keptAt(c, r) < 0) facts.left_out_nodata.push_back({c, r});
    facts.series_index = o.series_index;
    facts.series_count = o.series_count;
    // What was read, for the last section (the band list and class
    // names are said elsewhere or are too long for a key).
    for (const ReadFact& f : field.input.facts)
        if (!f.name.empty() && f.name != "bands" && f.name != "class names")
            facts.read_facts.push_back(std::string(1, char(std::toupper(static_cast<unsigned char>(f.name[0])))) +
                                       f.name.substr(1) + ": " + f.value);
    facts.categorical = field.input.categorical;
    facts.legibility = legibility.key;
    if (!legibility.change.empty()) facts.made_notes.push_back(legibility.change);
    facts.class_names = field.input.classes;
    facts.class_order = field.input.class_order;
    if (const auto g = groundScale(scene, field)) facts.ground = groundSentence(*g);
    if (tiles)
        facts.assembly = "The model prints in " + std::to_string(tiles->tiles.size()) + " tiles, in " +
                         std::to_string(tiles->layout.rows) + " rows from north to south and " +
                         std::to_string(tiles->layout.cols) +
                         " columns from west to east. Along most edges between tiles, teeth of one tile lock into "
                         "the next when it is lowered onto them from above. "
                         "Under each tile, pits form an L: a corner pit, then one pit for each column number "
                         "going east, and one for each row number going south. " + tilesMarksSentence(*tiles);
    return facts;
}

}  // namespace

void writeKeyFiles(const GenCommandOptions& o, const HexField& field, const Scene& scene,
                   const std::optional<VerifiedTiles>& tiles, const LegibilityOutcome& legibility,
                   const std::optional<FileStamp>& model_stamp, GenSummary& summary) {
    const std::vector<std::string> key = modelKeyParagraphs(scene, keyFacts(o, field, scene, tiles, legibility));
    const auto [text_path, brf_path] = keyPaths(o);
    // The model's stamp ends each key, after all a reader reads (key_stamp.h).
    const std::string stamp = model_stamp ? keyStampLine(std::filesystem::path(o.output).filename().string(), *model_stamp)
                                          : std::string();
    writeFileAtomically(text_path, [&](std::ostream& out) {
        out << modelKeyText(key);
        if (!stamp.empty()) out << "\n" << stamp << "\n";
    });
    std::string brf = brailleReadyFile(key, scene.params.words.braille_table);
    if (!stamp.empty()) {
        std::string line = stamp;
        // Braille ASCII is 0x20 to 0x5F: capitals; anything else of a file name a '?'.
        for (char& c : line) {
            c = char(std::toupper(static_cast<unsigned char>(c)));
            if (c < 0x20 || c > 0x5F) c = '?';
        }
        brf += line + "\r\n\f";
    }
    writeFileAtomically(brf_path, [&](std::ostream& out) { out << brf; });
    summary.outputs.push_back({text_path, "key in plain text for a screen reader"});
    summary.outputs.push_back({brf_path, "key in braille for an embosser: BRF 40 by 25 in " + scene.params.words.braille_table});
}

}  // namespace tsf::cli
