#include "app/gen_summary.h"

#include "app/ground_scale.h"
#include "app/printer_fit.h"
#include "gen/model/attachments.h"
#include "gen/model/feature_records.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/felt_heights.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene_classes.h"
#include "gen/key/spoken_text.h"
#include "gen/util/number_format.h"

#include <cmath>
#include <optional>
#include <cstdio>
#include <sstream>

namespace tsf::cli {

namespace {

// A line a screen reader moves through at once: at most two rows of a
// 40-cell braille display (continuations indented under the label column).
constexpr size_t kSummaryLineChars = 80;
constexpr size_t kSummaryIndent = 12;

std::string mappingText(const Scene& s) {
    const ValueMapping& m = s.mapping;
    std::ostringstream o;
    o << toString(m.transfer) << ": value " << formatForReader(m.baseline, 6) << " at the floor; value "
      << formatForReader(m.value_max, 6) << " at " << formatFixed(m.max_height_mm, 2) << " mm above it";
    if (m.transfer == Transfer::Linear && m.value_max > m.baseline && m.max_height_mm > 0) {
        // The span of two finite values can exceed the largest double
        // (1e308 and -1e308): divide the halves, then double.
        double per_mm = (m.value_max - m.baseline) / m.max_height_mm;
        if (!std::isfinite(per_mm)) per_mm = 2.0 * ((m.value_max / 2 - m.baseline / 2) / m.max_height_mm);
        o << "; 1 mm is " << (std::isfinite(per_mm) ? formatForReader(per_mm, 4) : std::string("more than the largest double"))
          << " data units";
    }
    return o.str();
}
}  // namespace

nlohmann::json sceneFactsJson(const Scene& s) {
    nlohmann::json j;
    j["grid"] = {{"cols", s.grid.cols}, {"rows", s.grid.rows}};
    j["cells"] = {{"total", s.grid.cellCount()}, {"with_data", s.cells_with_data},
                  {"nonempty", s.cells_nonempty}, {"kept", s.keptCount()}, {"kept_without_data", s.cells_nodata_kept}};
    j["pitch_mm"] = s.pitch_mm;
    j["y_scale"] = s.y_scale;  // the hexagons' north-south stretch (1: regular)
    const double zmax = s.zMm(highestPillarTop(s));
    j["size_mm"] = {gridWidth(s.grid, s.pitch_mm), gridDepth(s.grid, s.pitch_mm, s.y_scale), zmax};
    if (s.keptCount() > 0) {
        // The footprint of everything placed: the pillars and every attachment.
        const BoxMm f = sceneFootprint(s);
        j["footprint_mm"] = {{"west", f.x0}, {"east", f.x1}, {"south", f.y0}, {"north", f.y1}};
    }
    j["z_snap_mm"] = s.z_snap_mm;
    j["mapping"] = {{"transfer", toString(s.mapping.transfer)}, {"baseline", s.mapping.baseline},
                    {"value_max", s.mapping.value_max}, {"max_height_mm", s.mapping.max_height_mm},
                    {"base_mm", s.params.base_mm}};
    j["cull"] = toString(s.params.cull);
    j["bottom"] = toString(s.params.bottom);
    if (s.params.bottom == Bottom::Mirrored) j["mirror_thickness_mm"] = s.zMm(s.mirror_thickness_units);
    j["floor_mm"] = s.zMm(s.floor_units);  // the z of height 0 (mirrored: at or below the bed)
    j["one_pillar_per_value"] = s.one_to_one;
    if (s.params.cull == Cull::Concave)
        j["concave"] = {{"cells_convex_hull", s.cells_convex}, {"volume_saved_mm3", s.volume_saved_mm3}};
    j["nodata_pit_mm"] = s.zMm(s.nodata_pit_units);
    j["tilt"] = {{"source", toString(s.params.tilt)}, {"steepness", s.params.steepness},
                 {"max_slope_deg", s.params.max_slope_deg}, {"cells_tilted", s.shapes.cells_tilted},
                 {"cells_slope_limited", s.shapes.cells_slope_limited}, {"cells_clamped", s.shapes.cells_clamped},
                 {"cells_clamped_level", s.shapes.cells_flat_clamped}};
    j["structural_texture"] = {{"enabled", s.params.structural_texture}, {"cells", s.shapes.cells_textured},
                               {"dimple_mm", s.zMm(s.shapes.dimple_units)}};
    nlohmann::json marks = nlohmann::json::object();
    if (s.marks.notch)
        marks["notch"] = {{"depth_mm", s.marks.notch->depth_mm}, {"width_mm", s.marks.notch->width_mm},
                          {"opening_deg", s.marks.notch->opening_deg},
                          {"apex_mm", {planarX(s.marks.notch->apex, s.pitch_mm), planarY(s.marks.notch->apex, s.pitch_mm, s.y_scale)}}};
    else
        marks["notch"] = nullptr;
    if (s.marks.triangle)
        marks["triangle"] = {{"leg_x_mm", s.marks.triangle->leg_x_mm}, {"leg_y_mm", s.marks.triangle->leg_y_mm},
                             {"height_mm", s.zMm(s.marks.triangle->raise_units)},
                             {"corner_mm", {planarX(s.marks.triangle->corner, s.pitch_mm),
                                            planarY(s.marks.triangle->corner, s.pitch_mm, s.y_scale)}}};
    else
        marks["triangle"] = nullptr;
    j["marks"] = marks;
    // The features' own facts (gen/model/feature_records.h).
    for (const FeatureFacts& f : featureFacts()) {
        nlohmann::json value = f.json(s);
        if (value.is_null() && !f.listed_when_absent) continue;
        nlohmann::json* at = &j;
        for (const std::string& key : factsPath(f)) at = &(*at)[key];
        *at = std::move(value);
    }
    j["notes"] = s.notes;
    return j;
}

std::string formatSceneFacts(const Scene& s, bool with_size_and_heights) {
    std::ostringstream o;
    const double w = gridWidth(s.grid, s.pitch_mm), d = gridDepth(s.grid, s.pitch_mm, s.y_scale);
    const double zmax = s.zMm(highestPillarTop(s));
    o << "  cells     " << s.keptCount() << " kept of " << s.grid.cols << " x " << s.grid.rows << " = "
      << s.grid.cellCount() << " (" << s.cells_nonempty << " above the floor, " << s.cells_with_data - s.cells_nonempty
      << " at the floor, " << s.grid.cellCount() - s.cells_with_data << " without data; culling: "
      << toString(s.params.cull) << ")\n";
    if (with_size_and_heights) {
        o << "  size      " << formatFixed(w, 1) << " x " << formatFixed(d, 1) << " x " << formatFixed(zmax, 1)
          << " mm (grid box), hexagons " << formatFixed(s.pitch_mm, 2) << " mm across flats";
        if (s.keptCount() > 0 && !attachmentBoxes(s).empty()) {
            const BoxMm f = sceneFootprint(s);
            o << "; " << formatFixed(f.x1 - f.x0, 1) << " x " << formatFixed(f.y1 - f.y0, 1)
              << " mm with what stands beside the pillars";
        }
        o << "\n";
    }
    const std::optional<OneHeight> one_height = featureOneHeight(s);
    if (one_height)
        o << "  heights   " << one_height->summary_heights << "\n";
    else if (with_size_and_heights)
        o << "  heights   " << mappingText(s) << "\n"
          << "  levels    " << feltLevelsSentence(s.mapping.max_height_mm, sceneMeasures(s)) << "\n";
    if (s.params.bottom == Bottom::Flat)
        o << "  bottom    flat, base " << formatFixed(s.params.base_mm, 2) << " mm\n";
    else
        o << "  bottom    mirrored: every pillar " << formatFixed(s.zMm(s.mirror_thickness_units), 2)
          << " mm thick; the underside shows the negated data"
          << (s.floor_units < 0 ? "; the model stands on the bed, its lowest pillar's underside at z = 0: heights "
                                  "count from " + formatFixed(-s.zMm(s.floor_units), 2) + " mm below the bed"
                                : std::string())
          << "\n";
    o << "  z snap    " << formatSignificant(s.z_snap_mm, 4) << " mm\n";
    if (s.y_scale != 1.0)
        o << "  aspect    true: the hexagons are stretched " << formatFixed(100.0 * (s.y_scale - 1.0), 1)
          << "% north-south so rows of pillars stand a cell apart, as the raster's rows do on the ground "
             "(--regular-hexagons: regular ones, the model 13% shallower)\n";
    else if (!s.params.true_aspect && s.one_to_one)
        o << "  aspect    regular hexagons (--regular-hexagons): rows 0.866 of a cell apart, so the model is 13% "
             "shallower north-south than the ground\n";
    if (s.one_to_one)
        o << "  values    one pillar per value: each of the " << s.cells_with_data
          << (one_height ? one_height->summary_values : std::string(" values stands at its own height")) << "\n";
    if (s.marks.notch)
        o << "  notch     V " << formatFixed(s.marks.notch->depth_mm, 1) << " mm deep, " << formatFixed(s.marks.notch->width_mm, 1)
          << " mm wide, at the origin (south-west) corner, through the whole height\n";
    if (s.marks.triangle) {
        const OrientationTriangle& t = *s.marks.triangle;
        o << "  triangle  raised " << formatFixed(s.zMm(t.raise_units), 2) << " mm, legs " << formatFixed(t.leg_x_mm, 1)
          << " mm east (x) and " << formatFixed(t.leg_y_mm, 1) << " mm north (y), right angle at ("
          << formatFixed(planarX(t.corner, s.pitch_mm), 1) << ", " << formatFixed(planarY(t.corner, s.pitch_mm, s.y_scale), 1) << ") mm\n";
    }
    if (s.params.tilt != TiltSource::None)
        o << "  tilt      " << toString(s.params.tilt) << " x " << formatSignificant(s.params.steepness, 3) << ": "
          << s.shapes.cells_tilted << " tops tilted, at most " << formatSignificant(s.params.max_slope_deg, 3)
          << " degrees (" << s.shapes.cells_slope_limited << " limited to that, " << s.shapes.cells_clamped
          << " clamped at the floor, the height range or a mark, " << s.shapes.cells_flat_clamped
          << " of them level); each reads its value at its centre\n";
    if (s.shapes.cells_textured > 0)
        o << "  texture   " << s.shapes.cells_textured << " structural cells (kept only to hold the model together, "
          << "no data) carry a cone-shaped dimple " << formatFixed(s.zMm(s.shapes.dimple_units), 2)
          << " mm deep at the centre\n";
    for (const FeatureFacts& f : featureFacts()) o << f.lines(s);
    for (const std::string& n : s.notes) o << "  note      " << n << "\n";
    return o.str();
}

// The classes of a categorical model, a few per line: what each class
// code stands for (the file's name) and where it stands.
static std::string classesLine(const Scene& scene, const FieldInput& input) {
    constexpr size_t kListed = 16;  // the rest are in --json and the key
    const std::vector<SceneClass> classes = sceneClasses(scene, input.classes, input.class_order);
    const std::optional<OneHeight> one_height = featureOneHeight(scene);
    std::string o = "  classes   " + std::to_string(classes.size()) +
                    " classes, each hexagon one class (the most common of its pixels, never a mean); " +
                    (one_height                  ? one_height->summary_classes
                     : input.class_order.empty() ? "heights follow the class codes and mean no more or less:"
                                                 : "heights follow the order given (--class-order), one step each:");
    for (size_t k = 0; k < classes.size() && k < kListed; ++k)
        o += std::string(k == 0 ? " " : "; ") + className(classes[k]) + " (" + std::to_string(classes[k].cells) +
             " cells, " +
             (classes[k].texture.empty() ? formatFixed(classes[k].height_mm, 2) + " mm"
                                         : classes[k].texture + (classes[k].texture_shared ? ", shared" : "")) +
             ")";
    if (classes.size() > kListed) o += "; ... " + std::to_string(classes.size() - kListed) + " more in --json and the key";
    if (const std::string b = backgroundSentence(classes); !b.empty()) o += "\n  background " + b + " " + backgroundRemedy(classes) + ".";
    return o + "\n";
}

nlohmann::json summaryJson(const GenSummary& s) {
    nlohmann::json j;
    j["input"] = s.input;
    if (s.field)
        j["field"] = {{"how", s.field->how},
                      {"pitch_data_units", s.field->pitch_data},
                      // The data in the file's own words, as the key says them.
                      {"description", s.field->input.description},
                      {"variable", s.field->input.variable},
                      {"step", s.field->input.step},
                      {"units", s.field->input.units},
                      {"per_hexagon", s.field->per_hexagon}};
    if (s.scene) j["scene"] = sceneFactsJson(*s.scene);
    j["ground"] = nullptr;
    if (s.scene && s.field)
        if (const auto g = groundScale(*s.scene, *s.field))
            j["ground"] = {{"width_m", g->width_m},
                           {"depth_m", g->depth_m},
                           {"scale", g->east_west},
                           {"scale_north_south", g->north_south},
                           {"hexagon_area_km2", g->hexagon_area_km2 > 0 ? nlohmann::json(g->hexagon_area_km2) : nlohmann::json(nullptr)},
                           {"longitude_scale", s.field->input.longitude_scale > 0
                                                   ? nlohmann::json(s.field->input.longitude_scale)
                                                   : nlohmann::json(nullptr)}};
    if (s.scene && s.field && s.field->input.categorical) {
        nlohmann::json classes = nlohmann::json::array();
        for (const SceneClass& c : sceneClasses(*s.scene, s.field->input.classes, s.field->input.class_order))
            classes.push_back({{"code", c.code}, {"name", c.name.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.name)},
                               {"cells", c.cells}, {"height_mm", c.height_mm},
                               {"texture", c.texture.empty() ? nlohmann::json(nullptr) : nlohmann::json(c.texture)},
                               {"texture_shared", c.texture_shared}, {"background", c.background}});
        j["classes"] = classes;
        j["class_order_given"] = !s.field->input.class_order.empty();
    } else {
        j["classes"] = nullptr;
    }
    if (s.mesh) {
        const Bounds b = meshBounds(*s.mesh);
        j["mesh"] = {{"vertices", s.mesh->vertexCount()}, {"triangles", s.mesh->triangleCount()},
                     {"volume_mm3", signedVolume(*s.mesh)},
                     {"bounds_mm", {{b.min.x, b.min.y, b.min.z}, {b.max.x, b.max.y, b.max.z}}}};
    }
    j["outputs"] = nlohmann::json::array();
    for (const auto& [path, what] : s.outputs) j["outputs"].push_back({{"path", path}, {"kind", what}});
    for (const auto& [stage, ms] : s.timings_ms) j["timings_ms"][stage] = ms;
    if (!s.verify.is_null()) j["verify"] = s.verify;
    if (!s.halves.is_null()) j["halves"] = s.halves;
    if (!s.tiles.is_null()) j["tiles"] = s.tiles;
    j["printer"] = s.printer_notes;
    if (!s.legibility_json.is_null()) j["legibility"] = s.legibility_json;
    return j;
}

std::string formatSummary(const GenSummary& s) {
    // Essentials first: what was written, then what to check (the
    // verdict, warnings, supports, pieces), then the model's size and
    // heights; the details after.
    std::ostringstream o;
    o << "tsf gen: " << s.input << "\n";
    if (!s.outputs.empty()) {
        o << "Wrote:\n";
        for (const auto& [path, what] : s.outputs) o << "  " << path << " (" << what << ")\n";
    }
    if (!s.verify_text.empty() || !s.supports_text.empty() || !s.halves_text.empty() || !s.tiles_text.empty() ||
        !s.printer_notes.empty() || !s.legibility.empty()) {
        o << "Check:\n" << s.verify_text << s.supports_text << s.halves_text << s.tiles_text;
        for (const std::string& n : s.printer_notes) o << "  printer   " << n << "\n";
        // What tsf changed so a hand can read the model, or why it could not.
        for (const std::string& n : s.legibility) o << "  legible   " << n << "\n";
    }
    if (s.scene) {
        const Scene& sc = *s.scene;
        const double w = gridWidth(sc.grid, sc.pitch_mm), d = gridDepth(sc.grid, sc.pitch_mm, sc.y_scale);
        o << "Model:\n  size      " << formatFixed(w, 1) << " by " << formatFixed(d, 1) << " by "
          << formatFixed(sc.zMm(highestPillarTop(sc)), 1) << " mm (grid box), " << sc.keptCount() << " pillars "
          << formatFixed(sc.pitch_mm, 2) << " mm across flats";
        if (sc.keptCount() > 0 && !attachmentBoxes(sc).empty()) {
            const BoxMm f = sceneFootprint(sc);
            o << "; " << formatFixed(f.x1 - f.x0, 1) << " by " << formatFixed(f.y1 - f.y0, 1)
              << " mm with what stands beside the pillars";
        }
        o << "\n";
        if (!featureOneHeight(sc))
            o << "  heights   " << mappingText(sc) << "\n"
              << "  levels    " << feltLevelsSentence(sc.mapping.max_height_mm, sceneMeasures(sc)) << "\n";
    }
    o << "Details:\n";
    if (s.field) o << "  input     " << s.field->how << "\n";
    if (s.scene) o << formatSceneFacts(*s.scene, false);
    if (s.scene && s.field)
        if (const auto g = groundScale(*s.scene, *s.field)) o << groundLine(*g, s.field->input);
    if (s.scene && s.field && s.field->input.categorical) o << classesLine(*s.scene, s.field->input);
    if (s.mesh)
        o << "  mesh      " << s.mesh->vertexCount() << " vertices, " << s.mesh->triangleCount() << " triangles, volume "
          << formatFixed(signedVolume(*s.mesh), 1) << " mm^3\n";
    o << s.checks_text;
    if (!s.timings_ms.empty()) {
        o << "  time     ";
        for (const auto& [stage, ms] : s.timings_ms) o << " " << stage << " " << formatFixed(ms, 0) << " ms;";
        o.seekp(-1, std::ios_base::cur);
        o << "\n";
    }
    return shortLines(spokenText(o.str()), kSummaryLineChars, kSummaryIndent);
}

}  // namespace tsf::cli
