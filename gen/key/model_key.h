// The model's key: what a reader needs to use a model without seeing it, as
// plain text for a screen reader (MODEL.key.txt) and as formatted braille
// for an embosser (MODEL.key.brf, braille_ready_file.h).
//
// A braille plate holds a title and a range; most people who are blind do
// not read braille fluently, and what the model shows, its scale, how to
// find north and what the textures mean do not fit a plate. The key says it
// all, in short paragraphs, from the Scene and the file's own words
// (nothing is decided here). The reader's part comes first, in this order:
//   the title; what the model shows in the data's own words (the maker's
//   --about, else the file's long_name or band description, its units
//   spelled out, its time step) and its place in a series; how big a
//   hexagon is and what it stands for; the range of the data and of the
//   pillars; how heights map to values and how to read one; the classes;
//   where the no-data pits are, in words; tilts and dimples; how to find
//   north; the plate's braille and the tactile scale; the size, the ground
//   and the scale; how the pieces go together.
// Then a last section, headed kModelKeyMadeHeading: how the values were
// made from the file, what was read from it, the tsf version: the
// processing, and the only place a command-line option may appear.
//
// Numbers are for the ear and the finger (formatForReader: no e-notation,
// thousands grouped by commas), units spelled out (unit_words.h), and a
// number is joined to its unit by a no-break space (U+00A0), so the BRF
// never ends a line between them; modelKeyText writes plain spaces.
#pragma once

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "gen/field/raster.h"
#include "gen/model/scene.h"

namespace tsf {

struct ModelKeyFacts {
    std::string input_name;  ///< the input's file name (never its folders)
    std::string field_how;   ///< how the values were made from it (HexField::how): the last section
    std::string version;     ///< tsf's version
    /// What was read from the file ("Format: GeoTIFF ..."), one "Name: value"
    /// each: the last section.
    std::vector<std::string> read_facts;
    /// The maker's own words for what the model shows (--about): the
    /// key's "What it shows" paragraph, in place of the file's words.
    std::string about;
    /// The data in the file's words (FieldInput::description, variable,
    /// step, units): what the model shows when there is no --about.
    std::string description, variable, step, units;
    /// What one hexagon's value is (HexField::per_hexagon); "" for one value of the data.
    std::string per_hexagon;
    bool points = false;  ///< the values are of points binned into hexagons (counts, sums, means)
    /// The data's own extremes as read (FieldInput::min, max; NaN: none,
    /// or points, whose values are made only by the binning).
    double data_min = std::numeric_limits<double>::quiet_NaN();
    double data_max = std::numeric_limits<double>::quiet_NaN();
    /// A series (--band 1-12): this model is number series_index (1-based)
    /// of series_count, all on one value scale; 0 when not a series.
    int series_index = 0, series_count = 0;
    /// Grid cells (col, row; row 0 north) without data that the model
    /// leaves out (culled): the key says where they are.
    std::vector<std::pair<int32_t, int32_t>> left_out_nodata;
    /// The values are class codes (FieldInput::categorical), and the names
    /// the file gives them: the key lists every class with its height.
    bool categorical = false;
    std::vector<RasterClass> class_names;
    std::vector<double> class_order;  ///< --class-order (FieldInput::class_order): the cells hold ranks
    /// The ground the model shows and its scale, one sentence; "" when the
    /// file does not say how long its units are.
    std::string ground;
    /// How the printed pieces go together (the tiles of a model larger than
    /// the bed), one paragraph; "" for a model in one piece.
    std::string assembly;
    /// Where a fingertip cannot read the model (a legibility check that
    /// fails with every setting tsf could choose), one paragraph; "" when
    /// every check passes.
    std::string legibility;
    /// More for the last section (advice on options, notes), one sentence each.
    std::vector<std::string> made_notes;
};

/// The paragraph that opens the key's last section: the processing, never
/// before it.
inline constexpr const char* kModelKeyMadeHeading = "How this model was made";

/// The key's paragraphs: the first is the title line, each other a few
/// sentences. UTF-8 text without control characters.
std::vector<std::string> modelKeyParagraphs(const Scene& scene, const ModelKeyFacts& facts);

/// The paragraphs as a text file: a header line tsf recognises its own key
/// by (kModelKeyHeader), then the paragraphs separated by blank lines, each
/// on one line (a screen reader reads a paragraph at a time); no-break
/// spaces written as spaces.
std::string modelKeyText(const std::vector<std::string>& paragraphs);

/// The first line of every key file tsf writes.
inline constexpr const char* kModelKeyHeader = "tsf model key";

/// True when a key file's text starts with kModelKeyHeader (a key tsf
/// wrote, which a later run may replace).
bool isTsfModelKey(const std::string& text);

}  // namespace tsf
