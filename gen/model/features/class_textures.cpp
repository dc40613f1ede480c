// Class textures: which class gets which texture, and the shapes that draw
// them. See class_textures.h.
#include "gen/model/features/class_textures.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {

const char* textureName(Texture t) {
    switch (t) {
        case Texture::Level: return "level";
        case Texture::RidgesEastWest: return "ridges east-west";
        case Texture::Dimples: return "dimples";
        case Texture::RidgesNorthSouth: return "ridges north-south";
        case Texture::Bumps: return "bumps";
    }
    return "level";
}

std::optional<Texture> textureNamed(const std::string& name) {
    for (int t = 0; t < kTextureCount; ++t)
        if (name == textureName(Texture(t))) return Texture(t);
    return std::nullopt;
}

const char* textureFeel(Texture t) {
    switch (t) {
        case Texture::Level: return "flat tops";
        case Texture::RidgesEastWest:
            return "ridges running east-west: each hexagon a ramp rising north, a step down at its north edge";
        case Texture::Dimples: return "a dimple in the middle of each hexagon";
        case Texture::RidgesNorthSouth:
            return "ridges running north-south: each hexagon a ramp rising east, a step down at its east edge";
        case Texture::Bumps: return "a bump in the middle of each hexagon";
    }
    return "";
}

const SceneTextures* sceneTextures(const Scene& s) { return s.features.get<SceneTextures>(); }

bool classTexturesApply(const HexField& field, const SceneParams& p) {
    const ClassTextureRequest* rq = p.requests.get<ClassTextureRequest>();
    return field.input.categorical && field.input.class_order.empty() && (!rq || rq->wanted);
}

SceneTextures decideClassTextures(const HexField& field, const SceneParams& p, double pitch_mm, double y_scale) {
    const ClassTextureRequest* rq = p.requests.get<ClassTextureRequest>();
    const int most = rq ? rq->max_textures : kTextureCount;
    if (most < 1 || most > kTextureCount)
        throw InputError("--classes must be 1 to " + std::to_string(kTextureCount) + " (got " + std::to_string(most) +
                         "): a finger tells " + std::to_string(kTextureCount) +
                         " textures apart; for more classes, stand them at heights with --class-order");
    const char* instead = " (its classes stand at one height and are told apart by texture); give --class-order "
                          "if the classes are ordered, for heights";
    if (p.tilt != TiltSource::None)
        throw InputError(std::string("--tilt leans each top by its value's slope: a class map has none") + instead);
    if (p.halves)
        throw InputError(std::string("--halves cuts a slab the textures' ridges would cross; leave out --halves on a "
                                     "class map") + instead);

    std::map<double, int64_t> count;
    for (const double v : field.values)
        if (!std::isnan(v)) ++count[v];
    SceneTextures t;
    for (const auto& [code, cells] : count) t.classes.push_back({code, Texture::Level, false, cells});
    std::stable_sort(t.classes.begin(), t.classes.end(),
                     [](const ClassTexture& a, const ClassTexture& b) { return a.cells > b.cells; });
    const size_t own = t.classes.size() <= size_t(most) ? t.classes.size() : size_t(most) - 1;
    for (size_t i = 0; i < t.classes.size(); ++i) {
        t.classes[i].texture = Texture(std::min(i, size_t(most) - 1));
        t.classes[i].shared = i >= own;
    }
    t.textures_used = int(std::min(t.classes.size(), size_t(most)));

    // No fan leans more than a tilted top may: a dimple's or bump's steepest
    // triangle rises `relief` over the distance from the centre to the
    // nearest edge (half the pitch; less to the slanted edges of a hexagon
    // squashed north-south, hex_grid.h); its centre and corners are whole z
    // steps, so it may use the whole slope. The ridges' planes rise over a
    // row spacing or a pitch, and their corners round to the z grid: a step
    // is kept to spare there (as the tilt's limit does). The relief is whole
    // z steps (whole layers with --layer): 0.6 mm at 0.2 mm layers where the
    // cells allow it, never 0.4 when 0.6 fits.
    const double h = pitch_mm / kSqrt3 * y_scale;  // centre to the top corner
    const double inradius = std::min(0.5 * pitch_mm, pitch_mm * h / std::hypot(pitch_mm, h));
    const double slope = std::tan(p.max_slope_deg * std::numbers::pi / 180.0);
    const double ridge_run = std::min(pitch_mm, 1.5 * h);  // a pitch east, a row spacing north
    const double relief_mm = std::min({kTextureReliefMm, slope * inradius - 1e-6,
                                       std::max(0.0, slope - p.z_snap_mm / inradius) * ridge_run});
    t.relief_units = std::max<int64_t>(1, int64_t(std::floor(relief_mm / p.z_snap_mm + 1e-9)));
    t.height_units = std::max(snapUnits(kTextureHeightMm, p.z_snap_mm), t.relief_units + 1);
    return t;
}

ValueMapping classTextureMapping(const HexField& field, double height_mm) {
    double lowest = INFINITY;
    for (const double v : field.values)
        if (!std::isnan(v)) lowest = std::min(lowest, v);
    ValueMapping m;
    m.transfer = Transfer::Linear;
    m.max_height_mm = height_mm;
    // Below every class: a round number where one is (codes are mostly
    // whole), else the next double down.
    m.baseline = std::isfinite(lowest) && lowest - 1 < lowest ? std::floor(lowest) - 1 : std::nextafter(lowest, -INFINITY);
    m.value_max = m.baseline;
    return m;
}

std::vector<std::string> classTextureLegendLines(const SceneTextures& t, const std::vector<RasterClass>& names) {
    std::vector<std::string> lines;
    for (int k = 0; k < t.textures_used; ++k) {
        std::string who;
        for (const ClassTexture& c : t.classes) {
            if (int(c.texture) != k) continue;
            std::string name = formatSignificant(c.code);
            for (const RasterClass& n : names)
                if (n.code == c.code && !n.name.empty()) name = n.name;
            who += (who.empty() ? "" : ", ") + name;
        }
        if (!who.empty()) lines.push_back(std::string(textureName(Texture(k))) + ": " + who);
    }
    return lines;
}

const ClassTexture* classTexture(const SceneTextures& t, double code) {
    for (const ClassTexture& c : t.classes)
        if (c.code == code) return &c;
    return nullptr;
}

void frameClassTextures(Scene& s, const HexField& field) {
    if (!classTexturesApply(field, s.params)) return;
    const SceneTextures& t = s.features.set(decideClassTextures(field, s.params, s.pitch_mm, s.y_scale));
    s.mapping = classTextureMapping(field, s.zMm(t.height_units));
    // The braille legend names the classes by texture where they fit.
    if (s.params.words.inBraille() && s.params.words.key_lines.empty())
        s.params.words.key_lines = classTextureLegendLines(t, field.input.classes);
}

void classTextureShapes(const Scene& s, std::vector<PlaneSlope>& slopes, std::vector<int32_t>& centre_dz) {
    slopes.assign(s.keptCount(), {});
    centre_dz.assign(s.keptCount(), 0);
    const SceneTextures* textures = sceneTextures(s);
    if (!textures) return;
    const double relief_mm = s.zMm(textures->relief_units);
    const double row_spacing_mm = latticeY({0, 3}, s.pitch_mm, s.y_scale);  // rows are 3 lattice j apart
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data) continue;
        if (!s.drawn_by_face.empty() && s.drawn_by_face[k]) continue;
        const ClassTexture* c = classTexture(*textures, s.value[k]);
        if (!c) continue;
        switch (c->texture) {
            case Texture::Level: break;
            case Texture::RidgesEastWest: slopes[k].y = relief_mm / row_spacing_mm; break;
            case Texture::RidgesNorthSouth: slopes[k].x = relief_mm / s.pitch_mm; break;
            case Texture::Dimples: centre_dz[k] = -int32_t(textures->relief_units); break;
            case Texture::Bumps: centre_dz[k] = int32_t(textures->relief_units); break;
        }
    }
}

}  // namespace tsf
