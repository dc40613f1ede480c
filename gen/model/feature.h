// The feature contract: what a feature of a model (something it carries
// besides the pillars: the tactile scale, ...; or something of the pillars
// themselves: a class map's textures) hands to the rest of tsf, so
// that buildScene, the mesher, the parts, the read-backs, the sidecar, the
// summary and the key draw and report it without naming it. Each feature
// fills in one Feature, and features() (gen/model/feature_registry.h) is
// the one registry of them.
//
// A feature
//   - places itself in a phase of buildScene (FeaturePhase), reading the
//     Scene as the features before it left it, and keeps its own state in
//     Scene::features (gen/model/feature_state.h);
//   - claims its footprint (FootprintClaim, kept in Scene::claims once it is
//     placed): a feature placed later keeps clear of every claim without
//     knowing whose it is;
//   - hands in its solid in the vocabulary of gen/model/scene_attachments.h
//     (an attachment, its x, y box, its top at a point, the probes of its
//     read-back, the check of what the mesher relies on) and, before the
//     Scene is built, the bed width it takes beside the pillars;
//   - writes and reads its sidecar record and gives its facts for the
//     summary (gen/model/feature_records.h);
//   - says what the model's key tells a reader about it;
//   - hands in its piece of the generated OpenSCAD file (ScadPiece) as text,
//     which gen/scad/scad_attachments.h joins into the terrain polyhedron
//     or draws with the feature's own scad_lib/ module;
//   - says whether it survives a cut into tiles, and how it is carried
//     when the model is more than one piece or carries the orientation
//     marks: the marks it carries (PlacedMarks, which the key, the tiles
//     and the tactile check read without naming it), the room it
//     needs across a cut into halves and its side of the cut in each half,
//     the cells a tile keeps with it and what that tile is asked;
//   - claims what a hand must find on it (TactileClaim) and the braille it
//     prints (BrailleClaim), which the tactile check proves as printed;
//   - a feature of the pillars themselves (FeaturePhase::Frame) decides
//     from the field before any height, may stand the values at heights of
//     its own (the value mapping), shapes the cells' tops (TopShaping) and
//     keeps their relief under a mirrored model, says what the summary, the
//     key and the tactile check say instead of the heights (OneHeight), what
//     tells a class map's classes apart (ClassMark, KeyClasses) and the
//     thresholds its check is held to (FeatureThreshold); a feature that
//     measures heights (needs_heights) is refused beside it;
//   - a feature that is a piece of the model (a tile, FeaturePhase::UnderTops)
//     keeps its share of the cells the cull keeps, cuts into the bottom
//     (BottomHole: a tile's code pits), keeps the tops over them level and
//     draws the whole model's marks in the data where the whole has them.
// What the user asks of a feature is held in SceneParams::requests by the
// feature's own request type, set by the command line.
// Every entry may be null: the feature has nothing of that kind.
//
// The feature not yet in the registry (the halves) is still
// named by the lists in gen/model/attachments.cpp, gen/model/feature_records.cpp,
// gen/scad/scad_attachments.cpp and gen/key/model_key.cpp, which splice the
// registry in where its features stood, phase by phase (FeaturePhase), so
// every output keeps its order.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "gen/field/bin_regression.h"
#include "gen/field/hex_field.h"
#include "gen/geometry/mesh.h"
#include "gen/model/features/braille.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// Where in buildScene a feature places itself.
enum class FeaturePhase : uint8_t {
    /// Before any height, once the frame is set (the pitch, the lattice's
    /// stretch, the value mapping): a feature of the pillars themselves,
    /// decided from the field (Feature::frame), that may stand the values
    /// at heights of its own and shape the cells' tops (a class map's
    /// textures).
    Frame,
    /// After the cells and the marks in the data are placed, before the
    /// tops are shaped: what goes under level tops (a tile's code pits
    /// under the cells they keep level).
    UnderTops,
    /// After the cells' tops are final (tilted, textured): a body beside
    /// the pillars placed before the one carrying the marks, which keeps
    /// clear of what it claims (the braille legend's plate).
    BeforeMarks,
    /// After BeforeMarks: a body beside the pillars that carries the
    /// orientation marks (the orientation tab). When the marks were asked
    /// on it and it finds no place, buildScene builds the Scene again with
    /// the marks in the data.
    Marks,
    /// After the features of Marks: a body beside the pillars that stands
    /// against cells rising to the floor.
    Beside,
};

/// The first claim that `box` grown by clearance_mm on every side
/// overlaps; null when it is clear of them all.
inline const FootprintClaim* firstClaimHit(const std::vector<FootprintClaim>& claims, const BoxMm& box,
                                           double clearance_mm) {
    for (const FootprintClaim& c : claims)
        if (box.x0 - clearance_mm < c.box.x1 && box.x1 + clearance_mm > c.box.x0 && box.y0 - clearance_mm < c.box.y1 &&
            box.y1 + clearance_mm > c.box.y0)
            return &c;
    return nullptr;
}

/// A feature's piece of a generated OpenSCAD file, as text, so the emitter
/// (gen/scad/scad_attachments.h) writes it without knowing the feature.
/// The file then holds `header`, then the sentence's end and either
///   - the attachment joined into the terrain's one polyhedron (the
///     polyhedron strategy, when scad_lib/tsf_joined.scad can join it):
///     `variable = <walls, points, corners, triangles>;` and an assert that
///     the cell, snap and mirror are the ones it was placed for; or
///   - `variable = value;` for `module_call`, its own scad_lib/ module
///     (library_file), which wraps the terrain: a union.
struct ScadPiece {
    /// Its customizer section with the switch that shows it and the
    /// [Hidden] comment before its data, whose last sentence the emitter
    /// ends.
    std::string header;
    /// What ends the header's last sentence: "." (the legend's, a list of
    /// its lines in quotes, ends with none: "").
    std::string header_end = ".";
    std::string show_switch;   ///< "show_scale": on as generated, off in the other parameter sets
    std::string variable;      ///< "tactile_scale"
    std::string what;          ///< for a person, in the joined file's assert: "the tactile scale"
    std::string value;         ///< the variable for its own module: "[[...], ...]"
    std::string library_file;  ///< "tsf_scale.scad"
    std::string module_call;   ///< "tsf_with_scale(tactile_scale, show_scale) "
    /// A feature that words its data in its own way sets these; "" is the
    /// emitter's: header_end, a new line and a comment naming
    /// tsf_joined.scad before the joined data, header_end and a new line
    /// before `value`, and scad_lib/tsf_joined.scad's assert after the
    /// joined data, none after `value`.
    std::string joined_lead;  ///< between the header and `variable = <joined>;`
    std::string value_lead;   ///< between the header and `variable = value;`
    /// Its own assert of the parameters it was placed for, written after
    /// its data in both files (ending in a blank line).
    std::string own_assert;
};

/// Something a feature asks a hand to find, which the tactile check
/// (verify/tactile.h, `tactile_features`) proves as printed: an element
/// whose top stands top_z_mm high over a surface at base_z_mm beside it
/// must rise at least min_rise_mm once both are printed in whole layers,
/// and be at least min_width_mm across (and two nozzle widths, so it
/// prints as a shape, not a blob).
struct TactileClaim {
    std::string what;  ///< for a person: "the step for 20", "the tooth of column 5"
    double x_mm = 0, y_mm = 0;  ///< where, model frame
    double top_z_mm = 0, base_z_mm = 0;
    double min_rise_mm = 0;
    double width_mm = 0;  ///< its narrowest width
    double min_width_mm = 0;
    std::string source;  ///< where the minimums come from
};

/// Braille a feature prints (a legend's text), which the tactile check
/// (verify/tactile.h, `tactile_braille`) proves inside the standards'
/// range of a printed dot: its dots' sizes and where the first stands.
struct BrailleClaim {
    BrailleStandard standard;
    size_t dots = 0;
    Vec3 first_dot_mm;  ///< the first dot's centre on its surface, model frame; 0 without dots
};

/// How the model's key (gen/key/model_key.h) writes numbers for a reader: a
/// number alone, and a value with the model's units.
struct KeyNumbers {
    std::function<std::string(double)> number;
    std::function<std::string(double)> amount;
    std::function<std::string(double)> length_mm;  ///< a length in mm with its unit: "5 millimetres"
};

/// The shapes a feature gives the cells' tops, drawn by resolveTopShapes
/// (gen/model/features/tilt.h) as they are, not times --steepness.
struct TopShaping {
    std::vector<PlaneSlope> slopes;  ///< per kept cell: its top's slope, mm per mm (x east, y north)
    std::vector<int32_t> centre_dz;  ///< per kept cell: its top's centre above its level, z units
    /// What a reader should know about them, added to Scene::notes once
    /// the tops are shaped; "" for nothing.
    std::string note;
};

/// What a feature that stands every value at one height says instead of the
/// value mapping's heights (which then measure nothing).
struct OneHeight {
    std::string summary_heights;  ///< the summary's heights line, after "heights   "
    std::string summary_values;   ///< the summary's values line after "each of the N"
    std::string summary_classes;  ///< the summary's classes line: how they are told apart, and in what order
    /// Why a measure of heights means nothing on it, and what to change,
    /// for the refusal of a feature that measures ("a class map has one
    /// height (...); give ...").
    std::string unmeasurable;
    /// What a hand must feel instead of the steps between heights (the
    /// tactile check's height steps, verify/tactile.h, warns when not felt).
    bool felt = true;
    std::string felt_note;
};

/// A class of a class map as a feature tells it apart: by what
/// (SceneClass::texture, gen/model/scene_classes.h).
struct ClassMark {
    double code = 0;      ///< the class's value in the data
    std::string name;     ///< what tells it apart: "ridges east-west"
    bool shared = false;  ///< it shares that with other classes (there are more classes than marks)
};

/// What the key says of a class map's classes when a feature tells them
/// apart: a sentence on their heights, and a paragraph listing them
/// (instead of by height) as `list_lead`, then per mark the classes that
/// have it.
struct KeyClasses {
    std::string heights;    ///< "Every class stands at one height, ..."
    std::string list_lead;  ///< "The textures:"
    struct Mark {
        std::string name;  ///< ClassMark::name
        std::string feel;  ///< how it feels: "flat tops"
    };
    std::vector<Mark> marks;  ///< in the order they are handed out
};

/// A threshold a feature's tactile claims are held to, with its source, for
/// the tactile check's table (verify/tactile.h, tactileThresholds()).
struct FeatureThreshold {
    const char* check;  ///< the tactile check it belongs to
    const char* what;
    double value;
    const char* unit;
    const char* source;
};

struct Feature {
    const char* name;  ///< its sidecar record's and facts' path, dotted ("scale")
    const char* option;  ///< the option that asks for it, for messages ("--scale")
    FeaturePhase phase;
    /// Places what SceneParams asks of it (nothing when nothing is asked).
    /// Throws InputError saying what to change when it cannot stand.
    void (*place)(Scene& scene);
    /// The part of the model frame it takes; none without it.
    std::optional<FootprintClaim> (*claim)(const Scene& scene);
    /// Its body (gen/model/scene_attachments.h); none without it.
    std::optional<Attachment> (*attachment)(const Scene& scene, Assembly assembly);
    /// Its x, y box, mm; none without it.
    std::optional<BoxMm> (*box)(const Scene& scene);
    /// z (units) of its top at (x, y) mm; none outside its box or without it.
    std::optional<int64_t> (*top_at)(const Scene& scene, double x_mm, double y_mm);
    /// z (mm) of its highest point where it may stand above the highest
    /// pillar (the float32 z grid must resolve it); none without it.
    std::optional<double> (*highest_z_mm)(const Scene& scene) = nullptr;
    /// Its read-back; no probes without it.
    ProbeSet (*probes)(const Scene& scene);
    /// Checks what the mesher relies on to join it (InputError "scene: ...").
    void (*check)(const Scene& scene);
    /// The bed width it will take beside the pillars for these parameters.
    std::optional<SideWidth> (*side_width)(const SceneParams& params);
    /// Its sidecar record and its facts (FeatureRecord, FeatureFacts: the
    /// path is `name`).
    nlohmann::json (*record)(const Scene& scene);
    void (*read_record)(const nlohmann::json& record, const std::string& path, int version, Scene& scene);
    /// Listed as null in the sidecar and the facts when the Scene has none
    /// (the features that always were); else left out then.
    bool facts_listed_when_absent;
    nlohmann::json (*facts_json)(const Scene& scene);
    std::string (*facts_lines)(const Scene& scene);
    /// Its paragraph in the model's key; "" without it.
    std::string (*key_paragraph)(const Scene& scene, const KeyNumbers& numbers);
    /// Its piece of the generated OpenSCAD file; none without it.
    std::optional<ScadPiece> (*scad_piece)(const Scene& scene);
    /// True when a reader can measure a pillar's value against it (the key
    /// and the summary then say how many levels are felt apart by it).
    bool (*measures)(const Scene& scene);
    /// False when the model carries it and cannot be cut into tiles.
    bool (*survives_tiles)(const Scene& scene);
    // How it is carried when the model is more than one piece, or carries
    // the orientation marks (a body beside the pillars can carry them in
    // their stead):
    /// The orientation marks it carries, as placed (what a reader is told
    /// of them and the tactile check measures); none when it carries none
    /// (they are in the data, or there are none).
    std::optional<PlacedMarks> (*carried_marks)(const Scene& scene) = nullptr;
    /// The z units it needs across the cut into halves in every pillar it
    /// may stand against, both sides together: the slab the model is cut at
    /// grows to hold them (gen/model/phases/halves_slab.h). 0 without.
    int64_t (*room_across_cut_units)(const Scene& scene) = nullptr;
    /// Its state in one half (gen/model/features/halves.h): `half` is a copy
    /// of `whole` whose pillars are cut at whole.halves->split_units; it
    /// keeps its side of the cut there.
    void (*cut_into_half)(const Scene& whole, Scene& half, HalfKind kind) = nullptr;
    /// A cut into tiles keeps it whole, in the tile that carries the marks
    /// (gen/model/features/tiles.h): the kept cells it stands against,
    /// which stay in that tile.
    std::vector<int32_t> (*tile_cells)(const Scene& scene) = nullptr;
    /// What that tile is asked (tile.requests) so that it carries it as the
    /// whole model placed it rather than placing it again against fewer
    /// pillars (its cells named by grid cell index).
    void (*carry_into_tile)(const Scene& whole, SceneParams& tile) = nullptr;
    /// What it asks a hand to find (the tactile check proves it as
    /// printed); none without it.
    std::vector<TactileClaim> (*tactile_claims)(const Scene& scene);
    /// The braille it prints, which the tactile check proves printable;
    /// none without it.
    std::optional<BrailleClaim> (*braille)(const Scene& scene) = nullptr;

    // --- A feature of the pillars themselves (FeaturePhase::Frame) ---
    // (Each with its default: a feature without it need not list it.)
    /// Its record is listed as null in the sidecar when the Scene has none
    /// even where its facts are not (facts_listed_when_absent false): a
    /// record the sidecar always had.
    bool record_listed_when_absent = false;
    /// Decides what the field asks of it once the frame is set, before any
    /// height; may replace the value mapping (Scene::mapping) and the
    /// model's words (SceneParams::words). Throws InputError saying what to
    /// change when it cannot stand, or when the model asks for what it
    /// cannot be combined with.
    void (*frame)(Scene& scene, const HexField& field) = nullptr;
    /// How far below their level it shapes the tops, z units: a mirrored
    /// model keeps that much under its lowest cell (gen/model/phases/cell_heights.h).
    int64_t (*relief_below_units)(const Scene& scene) = nullptr;
    /// The shapes of the cells' tops (after the heights, the marks and a
    /// tile's code); none when it shapes none.
    std::optional<TopShaping> (*top_shaping)(const Scene& scene) = nullptr;
    /// When it stands every value at one height, what is said instead of
    /// the heights; none otherwise.
    std::optional<OneHeight> (*one_height)(const Scene& scene) = nullptr;
    /// Per class of a class map it tells apart, in its order: what tells
    /// it apart; empty when it tells none apart.
    std::vector<ClassMark> (*class_marks)(const Scene& scene) = nullptr;
    /// What the key says of the classes it tells apart; none when it tells
    /// none apart.
    std::optional<KeyClasses> (*key_classes)(const Scene& scene, const KeyNumbers& numbers) = nullptr;
    /// The thresholds its tactile check is held to, with their sources.
    std::vector<FeatureThreshold> (*thresholds)() = nullptr;
    /// True when the user asked for it (null: asked for by the field).
    bool (*asked)(const SceneParams& params) = nullptr;
    /// It measures heights: when asked for on a model whose values a
    /// feature stands at one height (one_height), it is refused before it
    /// is placed, saying why.
    bool needs_heights = false;

    // --- A feature that is a piece of the model (FeaturePhase::UnderTops) ---
    /// Of the cells the cull keeps (grid layout, 1 = keep), keeps only its
    /// share (a tile's cells). Throws InputError when the share cannot
    /// stand (not one piece).
    void (*keep_share)(const HexGrid& grid, const SceneParams& params, std::vector<uint8_t>& keep) = nullptr;
    /// Its cuts into the model's bottom (BottomHole, gen/model/scene_attachments.h);
    /// none without them.
    std::vector<BottomHole> (*bottom_holes)(const Scene& scene) = nullptr;
    /// True when kept cell k's top must stay level (a pit under it, or the
    /// same cell of a piece that keeps it level): no structural dimple.
    bool (*keeps_level)(const Scene& scene, size_t kept) = nullptr;
    /// The orientation marks in the data it draws where the whole model has
    /// them rather than placing them again on its own cells (the tile that
    /// carries them; the triangle's anchor a kept cell of this Scene); none:
    /// the marks are placed as usual. Throws InputError when its cells do
    /// not hold them.
    std::optional<Marks> (*given_marks)(const Scene& scene) = nullptr;
};

}  // namespace tsf
