// The model's key: what a reader needs to use a model without seeing it, as
// plain text for a screen reader (MODEL.key.txt) and as formatted braille
// for an embosser (MODEL.key.brf, braille_ready_file.h).
//
// A braille plate holds a title and a range; most people who are blind do
// not read braille fluently, and what the model shows, its scale, how to
// find north and what the textures mean do not fit a plate. The key says it
// all, in short paragraphs, from the Scene alone (nothing is decided here):
// what the model shows and how it was made; the values and their heights;
// the orientation marks and how to turn the model; the legend, the scale,
// tilts, dimples and pits; the classes of a class map; the size.
#pragma once

#include <string>
#include <vector>

#include "gen/field/raster.h"
#include "gen/model/scene.h"

namespace tsf {

struct ModelKeyFacts {
    std::string input_name;  ///< the input's file name (never its folders)
    std::string field_how;   ///< how the values were made from it (HexField::how)
    std::string version;     ///< tsf's version
    /// What was read from a file of several (its variable, band, time step,
    /// units), one "name: value" each; said after how the values were made.
    std::vector<std::string> read_facts;
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
};

/// The key's paragraphs: the first is the title line, each other a few
/// sentences. UTF-8 text without control characters.
std::vector<std::string> modelKeyParagraphs(const Scene& scene, const ModelKeyFacts& facts);

/// The paragraphs as a text file: a header line tsf recognises its own key
/// by (kModelKeyHeader), then the paragraphs separated by blank lines, each
/// on one line (a screen reader reads a paragraph at a time).
std::string modelKeyText(const std::vector<std::string>& paragraphs);

/// The first line of every key file tsf writes.
inline constexpr const char* kModelKeyHeader = "tsf model key";

/// True when a key file's text starts with kModelKeyHeader (a key tsf
/// wrote, which a later run may replace).
bool isTsfModelKey(const std::string& text);

}  // namespace tsf
