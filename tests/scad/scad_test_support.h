// Helpers of the OpenSCAD tests: a bumpy field, the real openscad binary, an
// independent reference for a Scene's solid, and reading generated files.
// Fields, parameters and files come from the shared test support
// (tests/support/).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "gen/field/hex_field.h"
#include "gen/geometry/mesh.h"
#include "gen/mesh_io/mesh_reader.h"
#include "gen/model/scene.h"
#include "tests/support/fields.h"
#include "tests/support/files.h"
#include "runners/openscad/openscad_runner.h"

namespace tsf::test {

/// A bumpy field with a few holes (NaN) and an empty rim on two sides, so
/// that hull culling drops cells and keeps some no-data cells inside.
inline HexField bumpyField(int cols, int rows) {
    return fieldFromFunction(cols, rows, [=](int c, int r) {
        if (c == 0 && r < rows / 2) return 0.0;           // empty corner: culled
        if ((c * 7 + r * 3) % 11 == 5) return kNaN;       // no data, inside the hull
        return 0.5 + 9.5 * std::fabs(std::sin(0.9 * c + 0.4 * r * r)) + (c + r) % 3;
    });
}

/// The real openscad binary (tests fail, not skip, when it is missing: the
/// project's setup installs it).
inline const ScadEngine& openscad() {
    static const std::unique_ptr<ScadEngine> engine = makeOpenScadEngine();
    return *engine;
}

/// Renders scad_path to a binary STL next to it and returns the result.
inline ScadRenderResult renderStl(const std::string& scad_path, const std::string& stl_path,
                                  const std::vector<ScadDefine>& defines = {}, const std::string& param_file = "",
                                  const std::string& param_set = "") {
    ScadRenderRequest rq;
    rq.scad_path = scad_path;
    rq.output_path = stl_path;
    rq.format = ScadExportFormat::Stl;
    rq.defines = defines;
    rq.parameter_file = param_file;
    rq.parameter_set = param_set;
    rq.timeout_s = 120;
    return renderScad(openscad(), rq);
}

/// Every ERROR / TRACE line of a result, for failure messages.
inline std::string errorText(const ScadRenderResult& r) {
    std::string out = r.summary;
    for (const ScadMessage& m : r.errors()) out += "\n  " + formatScadMessage(m);
    return out;
}

/// The `values` rows of a generated file: [line index, entries] per grid row.
struct ValuesBlock {
    std::vector<size_t> line_index;               ///< index into the file's lines
    std::vector<std::vector<std::string>> cells;  ///< trimmed entry texts
};

inline std::vector<std::string> splitLines(const std::string& text) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

inline std::string joinLines(const std::vector<std::string>& lines) {
    std::string out;
    for (const std::string& l : lines) out += l + "\n";
    return out;
}

inline std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(' ');
    const size_t b = s.find_last_not_of(' ');
    return a == std::string::npos ? std::string() : s.substr(a, b - a + 1);
}

/// Finds `values = [` and reads one "[a, b, ...]" row per line until "];".
inline ValuesBlock readValuesBlock(const std::vector<std::string>& lines) {
    ValuesBlock block;
    size_t i = 0;
    while (i < lines.size() && lines[i].rfind("values = [", 0) != 0) ++i;
    for (++i; i < lines.size() && lines[i] != "];"; ++i) {
        const size_t open = lines[i].find('['), close = lines[i].find(']');
        if (open == std::string::npos || close == std::string::npos) break;
        std::vector<std::string> row;
        std::stringstream entries(lines[i].substr(open + 1, close - open - 1));
        for (std::string e; std::getline(entries, e, ',');) row.push_back(trim(e));
        block.line_index.push_back(i);
        block.cells.push_back(row);
    }
    return block;
}

/// The generated text with entry (col, row) of `values` replaced by `text`.
inline std::string withValue(const std::string& scad, int32_t col, int32_t row, const std::string& text) {
    std::vector<std::string> lines = splitLines(scad);
    const ValuesBlock block = readValuesBlock(lines);
    std::string& line = lines[block.line_index.at(size_t(row))];
    std::vector<std::string> cells = block.cells.at(size_t(row));
    cells.at(size_t(col)) = text;
    std::string joined;
    for (size_t c = 0; c < cells.size(); ++c) joined += (c ? ", " : "") + cells[c];
    line = line.substr(0, line.find('[') + 1) + joined + line.substr(line.find(']'));
    return joinLines(lines);
}

}  // namespace tsf::test
