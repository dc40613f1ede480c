// A class map's textures in the scene sidecar and the summary. See
// class_textures_record.h.
#include "gen/model/features/class_textures_record.h"

#include <sstream>

#include "gen/model/features/class_textures.h"
#include "gen/model/sidecar_fields.h"
#include "gen/util/number_format.h"

namespace tsf {

using namespace sidecar;

json classTexturesRecord(const Scene& s) {
    const SceneTextures* t = sceneTextures(s);
    if (!t) return nullptr;
    json classes = json::array();
    for (const ClassTexture& c : t->classes)
        classes.push_back({c.code, textureName(c.texture), c.shared, c.cells});
    return {{"height_units", t->height_units},
            {"relief_units", t->relief_units},
            {"textures_used", t->textures_used},
            {"classes", classes}};
}

void readClassTexturesRecord(const json& record, const std::string& path, int /*version*/, Scene& s) {
    if (!record.is_object()) fail(path, std::string("expected an object, found ") + typeName(record));
    SceneTextures t;
    t.height_units = getInt(record, path, "height_units");
    t.relief_units = getInt(record, path, "relief_units");
    if (t.relief_units < 1 || t.height_units <= t.relief_units)
        fail(path, "expected 0 < relief_units < height_units");
    t.textures_used = getInt32(record, path, "textures_used", 1, kTextureCount);
    const json& classes = getArray(record, path, "classes");
    for (size_t i = 0; i < classes.size(); ++i) {
        const std::string p = path + ".classes[" + std::to_string(i) + "]";
        const json& c = classes[i];
        if (!c.is_array() || c.size() != 4 || !c[1].is_string() || !c[2].is_boolean())
            fail(p, "expected [code, texture, shared, cells]");
        const auto texture = textureNamed(c[1].get<std::string>());
        if (!texture) fail(p + "[1]", "unknown texture \"" + c[1].get<std::string>() + "\"");
        if (int(*texture) >= t.textures_used) fail(p + "[1]", "a texture beyond textures_used");
        t.classes.push_back({toNumber(c[0], p + "[0]"), *texture, c[2].get<bool>(), toInt(c[3], p + "[3]")});
    }
    if (t.classes.empty()) fail(join(path, "classes"), "a class map has at least one class");
    ClassTextureRequest rq;
    rq.max_textures = t.textures_used;
    s.params.requests.set(rq);
    s.features.set(std::move(t));
}

json classTexturesFactsJson(const Scene& s) {
    const SceneTextures* t = sceneTextures(s);
    if (!t) return nullptr;
    json shared = json::array();
    for (const ClassTexture& c : t->classes)
        if (c.shared) shared.push_back(c.code);
    return {{"height_mm", s.zMm(t->height_units)},
            {"relief_mm", s.zMm(t->relief_units)},
            {"textures_used", t->textures_used},
            {"shared", shared}};
}

std::string classTexturesFactsLines(const Scene& s) {
    if (!sceneTextures(s)) return "";
    const SceneTextures& t = *sceneTextures(s);
    std::ostringstream o;
    o << "  textures  the classes are nominal: every class " << formatFixed(s.zMm(t.height_units), 2)
      << " mm above the floor, told apart by " << t.textures_used << (t.textures_used == 1 ? " texture" : " textures")
      << " " << formatFixed(s.zMm(t.relief_units), 2) << " mm deep (commonest class first";
    size_t shared = 0;
    for (const ClassTexture& c : t.classes) shared += c.shared;
    if (shared > 0)
        o << "; the " << shared << " rarest classes share " << textureName(t.classes.back().texture)
          << ": --classes N, or --class-order for heights";
    o << ")\n";
    return o.str();
}

}  // namespace tsf
