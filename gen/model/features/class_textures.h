// Class textures: a class map's classes told apart by touch, at one height.
//
// Classes are nominal: a land-cover map's "forest" is not more than its
// "water", so standing each class at a height of its own (its code, or a
// rank) invents an order the data does not have. Unless the user says the
// classes are ordered (--class-order), every class stands at one height and
// its tops carry a texture (scene_textures.h): level, ridges east-west,
// dimples, ridges north-south, bumps. The commonest class gets the first,
// the next the second, and so on; with more classes than textures (or than
// --classes N allows) the rarer classes share the last one, and the summary
// and the key say which.
//
// A texture is drawn as a shaped top (top_shapes.h), so the direct mesher,
// the OpenSCAD file and the verifier draw and read the same numbers:
//   - ridges: the top is a plane rising `relief` over one row spacing (north)
//     or one pitch (east), so neighbours of the class meet in a step of
//     `relief` at each row's north edge or each cell's east edge;
//   - dimples and bumps: the top's centre `relief` below or above its corners.
// The relief is kTextureReliefMm where the cells allow, less on small cells:
// no fan leans more than a tilted top may (--max-slope), so it prints and
// reads as a slope, never a blade. The one height is kTextureHeightMm above
// the floor, so a dimple keeps material under it.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "gen/field/bin_regression.h"
#include "gen/field/hex_field.h"
#include "gen/model/scene.h"
#include "gen/model/scene_textures.h"

namespace tsf {

/// How far a texture rises or sinks where the cells are large enough, mm:
/// tactile graphics ask at least 0.5 mm of relief for an areal pattern (BANA,
/// Guidelines and Standards for Tactile Graphics, 2010: 0.02 in); twice that
/// is felt without searching.
inline constexpr double kTextureReliefMm = 1.0;
/// Below this relief a texture is hard to find (the summary says so), mm.
inline constexpr double kMinFeltTextureReliefMm = 0.5;
/// Every class's top above the floor, mm: a dimple keeps a millimetre of
/// material above the floor under it.
inline constexpr double kTextureHeightMm = 2.0;

/// "level", "ridges east-west", "dimples", "ridges north-south", "bumps".
const char* textureName(Texture texture);
/// The inverse of textureName; none for any other text.
std::optional<Texture> textureNamed(const std::string& name);
/// How the texture feels, one phrase for the key ("flat tops", ...).
const char* textureFeel(Texture texture);

/// The textures placed on `scene` (Scene::features); null without them.
const SceneTextures* sceneTextures(const Scene& scene);

/// True when `field` is a class map whose classes get textures: categorical,
/// no class order given, textures wanted (ClassTextureRequest in
/// SceneParams::requests; none there: wanted, up to kTextureCount).
bool classTexturesApply(const HexField& field, const SceneParams& params);

/// The textures of a class map's classes (classTexturesApply), by the
/// field's cell counts, commonest first (ties: the smaller code), and the
/// relief the cells allow at `pitch_mm` and the lattice's `y_scale`. Throws InputError when the model
/// asks for what textures cannot be combined with (--tilt, --halves, a
/// height scale) or max_textures is out of range, saying what to change.
SceneTextures decideClassTextures(const HexField& field, const SceneParams& params, double pitch_mm, double y_scale);

/// The value -> height mapping of a textured class map: every class at
/// `height_mm` above the floor. It is the constant mapping (value_max =
/// baseline, below the lowest code: every value above it stands at full
/// height) that the OpenSCAD library computes the same way, so the .scad
/// file stays a table of class codes.
ValueMapping classTextureMapping(const HexField& field, double height_mm);

/// One line per texture for the braille legend: "ridges east-west: Open
/// Water", the classes that share it after one another ("bumps: 21, 22, 31"),
/// each class by the file's name for it (`names`), else its code.
std::vector<std::string> classTextureLegendLines(const SceneTextures& textures, const std::vector<RasterClass>& names);

/// The texture of class `code`; none when the Scene has no such class.
const ClassTexture* classTexture(const SceneTextures& textures, double code);

/// Decides a class map's textures once the frame is set (classTexturesApply;
/// nothing otherwise): keeps them in Scene::features, stands every class at
/// their one height (Scene::mapping) and, for the braille legend, names the
/// classes by texture (SceneParams::words.key_lines) unless lines are given.
void frameClassTextures(Scene& scene, const HexField& field);

/// Per kept cell of `scene` (heights and marks placed, textures decided):
/// the slope of a ridged top (mm per mm, for resolveTopShapes) and the
/// centre offset of a dimpled or bumped one (z units). Cells without data
/// and cells drawn by a mark's face stay level.
void classTextureShapes(const Scene& scene, std::vector<PlaneSlope>& slopes, std::vector<int32_t>& centre_dz);

}  // namespace tsf
