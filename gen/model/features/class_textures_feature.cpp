// The class textures' entry in the feature registry. See
// class_textures_feature.h.
#include "gen/model/features/class_textures_feature.h"

#include "gen/model/features/class_textures.h"
#include "gen/model/features/class_textures_record.h"
#include "gen/util/number_format.h"

namespace tsf {

namespace {

// Dimples and ridges go below a top's level: a mirrored model keeps their
// relief under its lowest cell.
int64_t classTexturesReliefBelow(const Scene& s) {
    const SceneTextures* t = sceneTextures(s);
    return t ? t->relief_units : 0;
}

std::optional<TopShaping> classTexturesTopShaping(const Scene& s) {
    const SceneTextures* t = sceneTextures(s);
    if (!t) return std::nullopt;
    TopShaping shaping;
    classTextureShapes(s, shaping.slopes, shaping.centre_dz);
    if (t->relief_units * s.z_snap_mm < kMinFeltTextureReliefMm - 1e-9)
        shaping.note = "the class textures rise only " + formatSignificant(s.zMm(t->relief_units), 2) + " mm on cells " +
                       formatSignificant(s.pitch_mm, 3) + " mm across, below the " +
                       formatSignificant(kMinFeltTextureReliefMm) +
                       " mm a finger finds without searching: larger cells (fewer --bins, a larger --cell)";
    return shaping;
}

std::optional<OneHeight> classTexturesOneHeight(const Scene& s) {
    const SceneTextures* t = sceneTextures(s);
    if (!t) return std::nullopt;
    OneHeight o;
    o.summary_heights = "one height for every class, " + formatFixed(s.zMm(t->height_units), 2) +
                        " mm above the floor: a class map's codes are names, not amounts (--class-order stands ordered "
                        "classes at heights)";
    o.summary_values = " values is one pillar with its class's texture";
    o.summary_classes = "each class a texture, commonest first:";
    o.unmeasurable = "a class map has one height (its classes stand at one height and are told apart by texture); give "
                     "--class-order if the classes are ordered, for heights";
    // What must be felt is the textures' relief, not steps between heights.
    const double relief = s.zMm(t->relief_units);
    o.felt = relief + 1e-9 >= kMinFeltTextureReliefMm;
    o.felt_note = "a class map: its classes stand at one height and are told apart by " +
                  std::to_string(t->textures_used) + " textures " + formatSignificant(relief, 3) + " mm deep (at least " +
                  formatSignificant(kMinFeltTextureReliefMm, 2) + " mm is felt without searching" +
                  (o.felt ? ")" : "; larger cells give deeper textures)");
    return o;
}

// Commonest first, the order the textures are handed out in.
std::vector<ClassMark> classTexturesClassMarks(const Scene& s) {
    std::vector<ClassMark> out;
    if (const SceneTextures* t = sceneTextures(s))
        for (const ClassTexture& c : t->classes) out.push_back({c.code, textureName(c.texture), c.shared});
    return out;
}

std::optional<KeyClasses> classTexturesKeyClasses(const Scene& s, const KeyNumbers& say) {
    const SceneTextures* t = sceneTextures(s);
    if (!t) return std::nullopt;
    KeyClasses k;
    k.heights = "Every class stands at one height, " + say.length_mm(s.zMm(t->height_units)) +
                " above the floor, and is told apart by the feel of its tops, " + say.length_mm(s.zMm(t->relief_units)) +
                " deep; no class is more than another.";
    k.list_lead = "The textures:";
    for (int i = 0; i < t->textures_used; ++i) k.marks.push_back({textureName(Texture(i)), textureFeel(Texture(i))});
    return k;
}

std::vector<FeatureThreshold> classTexturesThresholds() {
    return {
        {"tactile_height_steps", "class textures' relief, in whole layers", kMinFeltTextureReliefMm, "mm",
         "0.02 in for an areal pattern (BANA, Guidelines and Standards for Tactile Graphics, 2010); printed in whole "
         "layers: 0.6 mm at 0.2 mm layers where the cells' slope allows it"},
        {"tactile_height_steps", "most textures on one model", double(kTextureCount), "",
         "at most five area textures on a graphic, else a key (APH, Guidelines for Design of Tactile Graphics, 1997; "
         "BANA 2010)"},
    };
}

}  // namespace

const Feature& classTexturesFeature() {
    static const Feature feature{
        .name = "class_textures",
        .option = "--classes",
        .phase = FeaturePhase::Frame,
        .place = nullptr,  // decided in the frame (frame, below)
        .claim = nullptr,
        .attachment = nullptr,  // drawn as the cells' own tops
        .box = nullptr,
        .top_at = nullptr,
        .highest_z_mm = nullptr,
        .probes = nullptr,
        .check = nullptr,
        .side_width = nullptr,
        .record = classTexturesRecord,
        .read_record = readClassTexturesRecord,
        .facts_listed_when_absent = false,
        .facts_json = classTexturesFactsJson,
        .facts_lines = classTexturesFactsLines,
        .key_paragraph = nullptr,  // the key's class paragraphs say it (key_classes)
        .scad_piece = nullptr,     // the .scad file draws the cells' shaped tops
        .measures = nullptr,
        .survives_tiles = nullptr,  // the tiles refuse shaped tops (top_shaping)
        .tactile_claims = nullptr,
        .record_listed_when_absent = true,
        .frame = frameClassTextures,
        .relief_below_units = classTexturesReliefBelow,
        .top_shaping = classTexturesTopShaping,
        .one_height = classTexturesOneHeight,
        .class_marks = classTexturesClassMarks,
        .key_classes = classTexturesKeyClasses,
        .thresholds = classTexturesThresholds,
    };
    return feature;
}

}  // namespace tsf
