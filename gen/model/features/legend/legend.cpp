#include "gen/model/features/legend/legend.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

#include "gen/model/features/braille.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

// The model's xy grid: positions are rounded to 1 um (docs/model.md).
double snapUm(double mm) { return std::round(mm * 1000.0) / 1000.0; }

std::vector<std::string> words(const std::string& line) {
    std::vector<std::string> out;
    std::istringstream in(line);
    std::string w;
    while (in >> w) out.push_back(w);
    return out;
}

// Breaks a line at spaces so that its braille fits max_cells.
std::vector<std::string> breakLine(const std::string& line, const LegendParams& p) {
    if (p.max_cells <= 0 || int(translateToBraille(line, p.table).size()) <= p.max_cells) return {line};
    std::vector<std::string> out;
    std::string current;
    for (const std::string& w : words(line)) {
        const std::string candidate = current.empty() ? w : current + " " + w;
        if (int(translateToBraille(candidate, p.table).size()) <= p.max_cells) {
            current = candidate;
            continue;
        }
        if (current.empty() || int(translateToBraille(w, p.table).size()) > p.max_cells) {
            const double need = double(translateToBraille(w, p.table).size()) * p.standard.cell_pitch_mm;
            char buf[64];
            std::snprintf(buf, sizeof buf, "%.0f", need + 2 * p.margin_mm);
            throw InputError("braille legend: the word '" + w + "' needs " + buf +
                             " mm, wider than the model; give a shorter --title or --units");
        }
        out.push_back(current);
        current = w;
    }
    if (!current.empty()) out.push_back(current);
    return out;
}

}  // namespace

LegendLayout layoutLegend(const LegendParams& p) {
    LegendLayout l;
    l.standard = p.standard;
    const BrailleStandard& s = p.standard;
    for (const std::string& line : p.lines) {
        if (words(line).empty()) continue;
        for (const std::string& part : breakLine(line, p)) {
            // The line as read: a no-break space (legendRangeText) is a space.
            std::string read = part;
            for (size_t at; (at = read.find("\u00A0")) != std::string::npos;) read.replace(at, 2, " ");
            l.text.push_back(read);
            l.cells.push_back(translateToBraille(part, p.table));
        }
    }
    if (l.cells.empty()) return l;
    size_t widest = 0;
    for (const auto& c : l.cells) widest = std::max(widest, c.size());
    const double r = s.dot_base_mm / 2;
    // A cell is 2 dots wide and 3 (or 4) high; lines are line_pitch apart.
    const double cell_w = s.dot_pitch_mm, cell_h = 2 * s.dot_pitch_mm;
    l.width_mm = snapUm(2 * p.margin_mm + 2 * r + double(widest - 1) * s.cell_pitch_mm + cell_w);
    l.depth_mm = snapUm(2 * p.margin_mm + 2 * r + double(l.cells.size() - 1) * s.line_pitch_mm + cell_h);
    for (size_t line = 0; line < l.cells.size(); ++line) {
        // Dot 1 of the first cell of this line.
        const double y1 = l.depth_mm - p.margin_mm - r - double(line) * s.line_pitch_mm;
        for (size_t k = 0; k < l.cells[line].size(); ++k) {
            const double x1 = p.margin_mm + r + double(k) * s.cell_pitch_mm;
            const uint8_t cell = l.cells[line][k];
            for (int dot = 0; dot < 8; ++dot) {
                if (!(cell & (1u << dot))) continue;
                // Dots 1-3 west column rows 0-2, 4-6 east column rows 0-2, 7 west and 8 east on row 3.
                const int column = dot < 3 ? 0 : dot < 6 ? 1 : dot - 6;
                const int rank = dot < 3 ? dot : dot < 6 ? dot - 3 : 3;
                l.dots.push_back({snapUm(x1 + column * s.dot_pitch_mm), snapUm(y1 - rank * s.dot_pitch_mm)});
            }
        }
    }
    return l;
}

std::string legendRangeText(double low, double high, const std::string& units) {
    // A no-break space keeps the unit on the line of its number (layoutLegend).
    return formatForReader(low, 4) + " to " + formatForReader(high, 4) + (units.empty() ? "" : "\u00A0" + units);
}

}  // namespace tsf
