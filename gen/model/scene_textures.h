// The tactile textures of a class map as the Scene holds them (in
// Scene::features, gen/model/feature_state.h): data only.
// Where they come from is gen/model/features/class_textures.h; the mesher,
// the OpenSCAD file and the verifier draw and read them through the shaped
// tops (scene_top_shapes.h) they are made of.
#pragma once

#include <cstdint>
#include <vector>

namespace tsf {

/// What a class's tops feel like. The order is the order they are handed out
/// in (the commonest class first): a calm surface for the largest areas, and
/// line and point textures taking turns, so two classes met one after the
/// other feel as different as they can.
enum class Texture : uint8_t {
    Level,             ///< flat tops
    RidgesEastWest,    ///< each top a ramp rising north: ridges along the rows, a step at each row's north edge
    Dimples,           ///< each top a shallow cone into its centre
    RidgesNorthSouth,  ///< each top a ramp rising east: ridges along the columns, a step at each east edge
    Bumps,             ///< each top a shallow cone out of its centre
};

/// How many textures a finger tells apart on a map: the five above.
inline constexpr int kTextureCount = 5;

/// What the user asked for (--classes), in SceneParams::requests: none
/// there, textures wanted, up to kTextureCount.
struct ClassTextureRequest {
    /// A class map (FieldInput::categorical) without --class-order gets textures at one height.
    bool wanted = true;
    /// At most this many textures (--classes N, 1..kTextureCount): the
    /// commonest classes get one each, the rarer ones share the last.
    int max_textures = kTextureCount;
};

struct ClassTexture {
    double code = 0;          ///< the class's value in the data
    Texture texture = Texture::Level;
    bool shared = false;      ///< one of the rarer classes that share the last texture
    int64_t cells = 0;        ///< the field's cells of this class (what the order is by)
};

/// The textures as placed (in Scene::features).
struct SceneTextures {
    int64_t height_units = 0;  ///< every class's top above the floor, z units
    int64_t relief_units = 0;  ///< a dimple's depth, a bump's height, a ridge's step, z units
    std::vector<ClassTexture> classes;  ///< commonest first
    int textures_used = 0;
};

}  // namespace tsf
