#include "gen/key/model_key.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gen/field/hex_grid.h"
#include "gen/model/features/marks.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/features/class_textures.h"
#include "gen/model/features/felt_heights.h"
#include "gen/model/scene_classes.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

std::string num(double v) { return formatSignificant(v, 4); }
std::string mm(double v) { return formatSignificant(v, 3) + " mm"; }

/// " airports" (with a space) or "" when no units were given.
std::string unitsAfter(const Scene& s) { return s.params.legend.units.empty() ? "" : " " + s.params.legend.units; }

std::string heightsParagraph(const Scene& s) {
    const ValueMapping& m = s.mapping;
    const std::string u = unitsAfter(s);
    std::string p = "A pillar's height above the floor shows its value: " + num(m.baseline) + u + " at the floor, " +
                    num(m.value_max) + u + " at " + mm(m.max_height_mm) + " above it. ";
    switch (m.transfer) {
    case Transfer::Linear: {
        const double per_mm = (m.value_max - m.baseline) / m.max_height_mm;
        p += "Heights are proportional to the values: each millimetre is " + num(per_mm) + u + ".";
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
    return p + " " + feltLevelsSentence(m.max_height_mm, s.scale.has_value());
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

}  // namespace

std::vector<std::string> modelKeyParagraphs(const Scene& s, const ModelKeyFacts& facts) {
    std::vector<std::string> out;
    const std::string u = unitsAfter(s);
    out.push_back(s.params.legend.title.empty() ? "Model of " + facts.input_name : s.params.legend.title);
    std::string shows = "What it shows: " + facts.field_how + ".";
    for (const std::string& f : facts.read_facts) shows += " " + f + ".";
    out.push_back(shows + " Made by tsf " + facts.version + " from the file " + facts.input_name + ".");

    // The values as modelled (kept cells with data).
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    int64_t pits = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] == CellKind::NoData || !std::isfinite(s.value[k])) {
            ++pits;
            continue;
        }
        lo = std::min(lo, s.value[k]);
        hi = std::max(hi, s.value[k]);
    }
    std::string values = "Each hexagon is " + mm(s.pitch_mm) + " across";
    values += s.one_to_one ? (s.textures ? " and stands for one value of the data. "
                                         : " and stands for one value of the data, at its own height. ")
                           : " and stands for the values that fell in it, as said above. ";
    if (facts.categorical) {
        // Class codes: their range and a height per unit mean nothing; each
        // class is told by name and height.
        const std::vector<SceneClass> classes = sceneClasses(s, facts.class_names, facts.class_order);
        values += "The values are classes, not amounts: " + std::to_string(classes.size()) +
                  (classes.size() == 1 ? " class" : " classes") +
                  ". Each hexagon holds one class, the most common where it stands, never a mix. " +
                  (s.textures ? "Every class stands at one height, " + mm(s.zMm(s.textures->height_units)) +
                                    " above the floor, and is told apart by the feel of its tops, " +
                                    mm(s.zMm(s.textures->relief_units)) + " deep; no class is more than another."
                   : facts.class_order.empty()
                       ? std::string("Each class stands at its own height, in the order of its code in the file; a "
                                     "higher pillar is not more of anything.")
                       : std::string("The classes are ordered, lowest first, as the model's maker gave them: each "
                                     "stands one even step above the one before."));
        out.push_back(values);
        if (s.textures) {
            // One sentence per texture, the classes that have it, commonest first.
            std::string list = "The textures:";
            for (int t = 0; t < s.textures->textures_used; ++t) {
                std::string who;
                int64_t cells = 0;
                size_t named = 0;
                for (const SceneClass& c : classes)
                    if (c.texture == textureName(Texture(t))) {
                        who += std::string(named++ == 0 ? "" : ", ") + "class " + className(c);
                        cells += c.cells;
                    }
                if (named == 0) continue;
                list += std::string(t == 0 ? " " : "; ") + textureName(Texture(t)) + " (" + textureFeel(Texture(t)) +
                        "): " + who + (named > 1 ? " (these classes share it)" : "") + ", " + std::to_string(cells) +
                        (cells == 1 ? " hexagon" : " hexagons");
            }
            out.push_back(list + ".");
        } else {
            std::string list = "The classes, by height:";
            for (size_t k = 0; k < classes.size(); ++k)
                list += std::string(k == 0 ? " " : "; ") + "class " + className(classes[k]) + ", " +
                        mm(classes[k].height_mm) + ", " + std::to_string(classes[k].cells) +
                        (classes[k].cells == 1 ? " hexagon" : " hexagons");
            out.push_back(list + ".");
        }
        if (const std::string b = backgroundSentence(classes); !b.empty()) out.push_back(b);
    } else {
        if (std::isfinite(lo))
            values += "The values go from " + num(lo) + " to " + num(hi) + u + ".";
        out.push_back(values);
        out.push_back(heightsParagraph(s));
    }
    if (pits > 0)
        out.push_back(std::to_string(pits) + (pits == 1 ? " cell has" : " cells have") +
                      " no data: each is a pit " + mm(s.zMm(s.nodata_pit_units)) +
                      " below the floor, never a value. Between tall pillars its bottom may be out of a fingertip's "
                      "reach: a hole you cannot feel the bottom of holds no data.");
    if (s.shapes.cells_textured > 0)
        out.push_back(std::to_string(s.shapes.cells_textured) +
                      " cells at the floor hold no data and are there only to hold the model together: each has a "
                      "cone-shaped dimple " + mm(s.zMm(s.shapes.dimple_units)) + " deep at its centre. They are not values.");
    if (s.shapes.cells_tilted > 0 && s.params.tilt != TiltSource::None)
        out.push_back(std::string("Pillar tops lean: each leans the way ") +
                      (s.params.tilt == TiltSource::Points ? "the points crowd within its hexagon"
                                                           : "the data rises across its hexagon") +
                      ", at most " + formatSignificant(s.params.max_slope_deg, 3) +
                      " degrees. The height at a top's centre is its value.");
    out.push_back(orientationParagraph(s));
    if (s.legend) {
        std::string p = "Braille on the plate north of the pillars reads:";
        for (const std::string& line : s.legend->layout.text) p += " \"" + line + "\".";
        out.push_back(p);
    }
    if (s.scale) {
        std::string steps;
        for (size_t k = 0; k < s.scale->steps.size(); ++k)
            steps += (k == 0 ? "" : k + 1 == s.scale->steps.size() ? " and " : ", ") + num(s.scale->steps[k].value);
        out.push_back("A tactile scale stands east of the pillars: " + std::to_string(s.scale->steps.size()) +
                      " steps, the lowest in the south, at " + steps + u +
                      ". Put a finger on a pillar and one on the steps to read its value.");
    }
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
    return out;
}

std::string modelKeyText(const std::vector<std::string>& paragraphs) {
    std::string out = std::string(kModelKeyHeader) + "\n";
    for (const std::string& p : paragraphs) out += "\n" + p + "\n";
    return out;
}

bool isTsfModelKey(const std::string& text) { return text.rfind(std::string(kModelKeyHeader) + "\n", 0) == 0; }

}  // namespace tsf
