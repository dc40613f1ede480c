#include "gen/key/model_key.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <optional>

#include "gen/field/hex_grid.h"
#include "gen/key/places_in_words.h"
#include "gen/key/unit_words.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/braille.h"
#include "gen/model/features/placed_marks.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/features/felt_heights.h"
#include "gen/model/scene_classes.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

/// Joins a number to its unit: the BRF keeps them on one line.
const std::string kNoBreak = "\u00A0";

std::string num(double v) { return formatForReader(v, 4); }

/// "5 millimetres" (up to 3 significant digits).
std::string mm(double v) { return formatForReader(v, 3) + kNoBreak + (v == 1 ? "millimetre" : "millimetres"); }

/// The value with its unit words, joined: "12.5 degrees Celsius".
std::string amount(double v, const UnitWords& u) {
    const std::string& w = v == 1 ? u.singular : u.plural;
    return num(v) + (w.empty() ? "" : kNoBreak + w);
}

/// "from 1 to 5 millimetres per day".
std::string range(double lo, double hi, const UnitWords& u) { return "from " + num(lo) + " to " + amount(hi, u); }

/// The units a reader is told: --units as the maker wrote them (spelled
/// out when they are a known unit), else the file's.
UnitWords readerUnits(const Scene& s, const ModelKeyFacts& facts) {
    return unitWords(s.params.words.units.empty() ? facts.units : s.params.words.units);
}

std::string capitalised(std::string text) {
    if (!text.empty()) text[0] = char(std::toupper(static_cast<unsigned char>(text[0])));
    return text;
}

/// A step "2000-02-01" (or "2000-02-01 06:00") as "1 February 2000" (", 06:00"):
/// read as a date aloud, and in braille one number each (a hyphen between
/// numbers needs a new number sign, which not every braille table writes).
/// Any other step as it is.
std::string stepWords(const std::string& step) {
    static constexpr const char* kMonths[] = {"January", "February", "March",     "April",   "May",      "June",
                                              "July",    "August",   "September", "October", "November", "December"};
    auto digits = [&](size_t from, size_t n) {
        for (size_t k = from; k < from + n; ++k)
            if (k >= step.size() || !std::isdigit(static_cast<unsigned char>(step[k]))) return false;
        return true;
    };
    if (!(step.size() == 10 || (step.size() == 16 && step[10] == ' ' && step[13] == ':' && digits(11, 2) && digits(14, 2))) ||
        !digits(0, 4) || step[4] != '-' || !digits(5, 2) || step[7] != '-' || !digits(8, 2))
        return step;
    const int month = std::stoi(step.substr(5, 2)), day = std::stoi(step.substr(8, 2));
    if (month < 1 || month > 12 || day < 1 || day > 31) return step;
    return std::to_string(day) + " " + kMonths[month - 1] + " " + step.substr(0, 4) +
           (step.size() == 16 ? ", " + step.substr(11) : "");
}

std::string titleParagraph(const Scene& s, const ModelKeyFacts& facts) {
    if (!s.params.words.title.empty()) return s.params.words.title;
    if (!facts.description.empty())
        return capitalised(facts.description) + (facts.step.empty() ? "" : ", " + stepWords(facts.step));
    return "Model of " + facts.input_name;
}

std::string showsParagraph(const ModelKeyFacts& facts, const UnitWords& u) {
    std::string p = "What it shows: ";
    if (!facts.about.empty()) {
        p += facts.about;
        if (p.back() != '.') p += ".";
    } else {
        std::string what = !facts.description.empty() ? facts.description
                           : !facts.variable.empty()  ? "the variable " + facts.variable + " of the file " + facts.input_name
                           : facts.points             ? "the points of the file " + facts.input_name
                                                      : "the values of the file " + facts.input_name;
        if (!u.plural.empty()) what += (facts.points && facts.description.empty() ? ", as " : ", in ") + u.plural;
        if (!facts.step.empty()) what += ", for " + stepWords(facts.step);
        p += what + ".";
    }
    if (facts.series_count > 1)
        p += " This is model " + std::to_string(facts.series_index) + " of " + std::to_string(facts.series_count) +
             " in a series, all on one height scale: a pillar of the same height means the same value in every model "
             "of the series.";
    return p;
}

std::string heightsParagraph(const Scene& s, const UnitWords& u) {
    const ValueMapping& m = s.mapping;
    std::string p = "How to read a height: a pillar's height above the floor shows its value. The floor is " +
                    amount(m.baseline, u) + "; a pillar " + mm(m.max_height_mm) + " high is " + amount(m.value_max, u) + ". ";
    switch (m.transfer) {
    case Transfer::Linear: {
        const double per_mm = (m.value_max - m.baseline) / m.max_height_mm;
        p += "Heights are proportional to the values: each millimetre of height is " + amount(per_mm, u) + ".";
        break;
    }
    case Transfer::Sqrt:
        p += "Heights grow with the square root of the values, so small values stay apart and large ones do not "
             "tower: a pillar twice as high holds four times the value above the floor's.";
        break;
    case Transfer::Log:
        p += "Heights follow the logarithm of the values (two powers of ten from the floor to the top): each step "
             "up of the same height multiplies the value.";
        break;
    }
    return p + " " + feltLevelsSentence(m.max_height_mm, sceneMeasures(s));
}

std::string orientationParagraph(const Scene& s) {
    std::string p = "Finding north: ";
    const PlacedMarks m = placedMarks(s);
    if (!m.has_notch && !m.has_triangle) return p + "this model was made without orientation marks.";
    if (m.has_notch)
        p += "a V-shaped notch " + mm(m.notch_depth_mm) + " deep is cut into the model's south-west corner, through its whole "
             "height. Turn the model so the notch is at your near left: north is then away from you and east to your "
             "right. ";
    if (m.has_triangle) {
        p += "A raised right triangle stands " + m.triangle_place +
             ", its right angle at the south-west and its longer leg running east, to your right, when the model is "
             "turned that way.";
        if (m.underside)
            p += " The same triangle is raised on the tab's underside: turned over, its longer leg runs to your left, "
                 "as the data is mirrored there.";
    }
    if (!m.note.empty()) p += " " + m.note;
    return p;
}

void classParagraphs(const Scene& s, const ModelKeyFacts& facts, const KeyNumbers& numbers,
                     std::vector<std::string>& out) {
    // Class codes: their range and a height per unit mean nothing; each
    // class is told by name and height, or by what a feature tells it
    // apart by (a class map's textures).
    const std::vector<SceneClass> classes = sceneClasses(s, facts.class_names, facts.class_order);
    const std::optional<KeyClasses> told_apart = featureKeyClasses(s, numbers);
    out.push_back("The values are classes, not amounts: " + std::to_string(classes.size()) +
                  (classes.size() == 1 ? " class" : " classes") +
                  ". Each hexagon holds one class, the most common where it stands, never a mix. " +
                  (told_apart ? told_apart->heights
                   : facts.class_order.empty()
                       ? std::string("Each class stands at its own height, in the order of its code in the file; a "
                                     "higher pillar is not more of anything.")
                       : std::string("The classes are ordered, lowest first, as the model's maker gave them: each "
                                     "stands one even step above the one before.")));
    auto hexagons = [](int64_t n) { return num(double(n)) + (n == 1 ? " hexagon" : " hexagons"); };
    if (told_apart) {
        // One sentence per mark (a texture), the classes that have it, in
        // the feature's order.
        std::string list = told_apart->list_lead;
        for (size_t t = 0; t < told_apart->marks.size(); ++t) {
            const KeyClasses::Mark& mark = told_apart->marks[t];
            std::string who;
            int64_t cells = 0;
            size_t named = 0;
            for (const SceneClass& c : classes)
                if (c.texture == mark.name) {
                    who += std::string(named++ == 0 ? "" : ", ") + "class " + className(c);
                    cells += c.cells;
                }
            if (named == 0) continue;
            list += std::string(t == 0 ? " " : "; ") + mark.name + " (" + mark.feel + "): " + who +
                    (named > 1 ? " (these classes share it)" : "") + ", " + hexagons(cells);
        }
        out.push_back(list + ".");
    } else {
        std::string list = "The classes, by height:";
        for (size_t k = 0; k < classes.size(); ++k)
            list += std::string(k == 0 ? " " : "; ") + "class " + className(classes[k]) + ", " +
                    mm(classes[k].height_mm) + ", " + hexagons(classes[k].cells);
        out.push_back(list + ".");
    }
    if (const std::string b = backgroundSentence(classes); !b.empty()) out.push_back(b);
}

}  // namespace

std::vector<std::string> modelKeyParagraphs(const Scene& s, const ModelKeyFacts& facts) {
    std::vector<std::string> out;
    const UnitWords u = readerUnits(s, facts);
    const KeyNumbers numbers{num, [&u](double v) { return amount(v, u); }, mm};
    out.push_back(titleParagraph(s, facts));
    out.push_back(showsParagraph(facts, u));

    // The values as modelled (kept cells with data), and where the pits are.
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    std::vector<std::pair<int32_t, int32_t>> pits;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] == CellKind::NoData || !std::isfinite(s.value[k])) {
            pits.push_back({s.col[k], s.row[k]});
            continue;
        }
        lo = std::min(lo, s.value[k]);
        hi = std::max(hi, s.value[k]);
    }
    std::string values = "Each hexagon is " + mm(s.pitch_mm) + " across";
    if (s.one_to_one) values += " and stands for one value of the data.";
    else if (!facts.per_hexagon.empty()) values += " and stands for " + facts.per_hexagon + ".";
    else values += " and stands for the values that fell in it.";
    if (facts.categorical) {
        out.push_back(values);
        classParagraphs(s, facts, numbers, out);
    } else {
        const bool data_range = std::isfinite(facts.data_min) && std::isfinite(facts.data_max);
        if (data_range) values += " The data's own values go " + range(facts.data_min, facts.data_max, u) + ".";
        if (std::isfinite(lo)) {
            const bool same = data_range && lo == facts.data_min && hi == facts.data_max;
            if (!data_range) values += " The pillars' values go " + range(lo, hi, u) + ".";
            else if (!same)
                values += std::string(s.one_to_one ? " The pillars' values, of the hexagons kept, go "
                                                    : " The pillars' values, one for each hexagon, go ") +
                          range(lo, hi, u) + ".";
        }
        out.push_back(values);
        out.push_back(heightsParagraph(s, u));
    }
    if (!pits.empty()) {
        const int64_t n = int64_t(pits.size());
        out.push_back(num(double(n)) + (n == 1 ? " cell has" : " cells have") + " no data, " +
                      placesInWords(s.grid.cols, s.grid.rows, pits) + ": each is a pit " + mm(s.zMm(s.nodata_pit_units)) +
                      " below the floor, never a value. Between tall pillars its bottom may be out of a fingertip's "
                      "reach: a hole you cannot feel the bottom of holds no data.");
    }
    if (!facts.left_out_nodata.empty())
        out.push_back("The data has no values " + placesInWords(s.grid.cols, s.grid.rows, facts.left_out_nodata) +
                      ": the model leaves " + (facts.left_out_nodata.size() == 1 ? "that place" : "those places") +
                      " out, so its edge follows the data.");
    if (s.shapes.cells_textured > 0)
        out.push_back(num(double(s.shapes.cells_textured)) +
                      " cells at the floor hold no data and are there only to hold the model together: each has a "
                      "cone-shaped dimple " + mm(s.zMm(s.shapes.dimple_units)) + " deep at its centre. They are not values.");
    if (s.shapes.cells_tilted > 0 && s.params.tilt != TiltSource::None)
        out.push_back(std::string("Pillar tops lean: each leans the way ") +
                      (s.params.tilt == TiltSource::Points ? "the points crowd within its hexagon"
                                                           : "the data rises across its hexagon") +
                      ", at most " + num(s.params.max_slope_deg) + kNoBreak +
                      "degrees. The height at a top's centre is its value.");
    out.push_back(orientationParagraph(s));
    for (const Feature* f : features())
        if (f->key_paragraph)
            if (std::string p = f->key_paragraph(s, numbers); !p.empty()) out.push_back(std::move(p));
    const double top = s.zMm(highestPillarTop(s));
    std::string size = "The pillars cover " + mm(gridWidth(s.grid, s.pitch_mm)) + " from west to east and " +
                       mm(gridDepth(s.grid, s.pitch_mm, s.y_scale)) + " from south to north, and stand up to " + mm(top) + " high";
    if (s.params.bottom == Bottom::Flat)
        size += " on a flat base " + mm(s.params.base_mm) + " thick.";
    else
        size += ". The underside mirrors the top: seen from below, high values are deep pockets.";
    if (s.params.bottom == Bottom::Mirrored && s.floor_units < 0)
        size += " The lowest pillar stands on the table; heights are counted from " + mm(-s.zMm(s.floor_units)) +
                " below it.";
    if (!facts.ground.empty()) size += " " + facts.ground;
    out.push_back(size);
    if (s.halves)
        out.push_back("The model prints in two halves, upper and lower, joined by pins that fit one way only.");
    if (!facts.assembly.empty()) out.push_back(facts.assembly);
    if (!facts.legibility.empty()) out.push_back(facts.legibility);

    // The last section: how the values were made, and the file's details.
    out.push_back(kModelKeyMadeHeading);
    std::string made = capitalised(facts.field_how) + ".";
    for (const std::string& f : facts.read_facts) made += " " + f + ".";
    for (const std::string& n : facts.made_notes) made += " " + n + (n.empty() || n.back() == '.' ? "" : ".");
    out.push_back(made);
    out.push_back("The braille of the plate and of this key's BRF file is " + brailleCodeName(s.params.words.braille_table) +
                  " (liblouis table " + s.params.words.braille_table + "). Made by tsf " + facts.version + " from the file " +
                  facts.input_name + ".");
    return out;
}

std::string modelKeyText(const std::vector<std::string>& paragraphs) {
    std::string out = std::string(kModelKeyHeader) + "\n";
    for (std::string p : paragraphs) {
        for (size_t at; (at = p.find(kNoBreak)) != std::string::npos;) p.replace(at, kNoBreak.size(), " ");
        out += "\n" + p + "\n";
    }
    return out;
}

bool isTsfModelKey(const std::string& text) { return text.rfind(std::string(kModelKeyHeader) + "\n", 0) == 0; }

}  // namespace tsf
