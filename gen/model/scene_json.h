// Scene sidecar: a Scene as JSON, written beside a model (`model.stl.scene.json`)
// so that `tsf verify --scene` can check the model's heights without the
// original field and options.
//
// Format ("format": "tsf-scene", "version": 8), one object:
//   grid {cols, rows}, pitch_mm, y_scale (version 8: the lattice's
//   north-south stretch, gen/field/hex_grid.h; 1 before), z_snap_mm,
//   params {pitch_mm, fit_width_mm, fit_depth_mm, max_height_mm, base_mm,
//           transfer, baseline_mode, baseline_value, value_max (null = unset),
//           z_snap_mm, cull, bottom, true_aspect (version 8)}  -- enums by their CLI names (scene.h toString)
//   mapping {transfer, baseline, value_max, max_height_mm},
//   floor_units, mirror_thickness_units, cells_with_data, cells_nonempty,
//   cells_nodata_kept, nodata_pit_units, one_to_one,
//   marks {notch: null | {apex, mouth_a, mouth_b: [i, j] lattice coordinates,
//                         depth_mm, width_mm, opening_deg},
//          triangle: null | {corner, east, north: [i, j], leg_x_mm, leg_y_mm,
//                            raise_units, anchor (kept index)},
//          tab: null | {outline [[x, y, lattice id (-1: the tab's own)], ...] mm,
//                       counter-clockwise, joined [0|1 per edge], touched
//                       [[kept index, edge 0..5]], bottom_units, top_units, box_mm
//                       [west, east, south, north], notch null | {depth_mm, width_mm,
//                       opening_deg}, triangle null | {corners_mm [[x, y] x 3],
//                       raise_units, underside (mirrored: also below the tab)}}
//                  (version 6: the orientation tab, gen/model/features/tab/orientation_tab.h)},
//   faces: null | {extra [[i, j], ...] (planar points after the lattice's ids),
//                  faces [{anchor, raise_units, cells [kept index], rings [[id, ...]],
//                          across [[[kind, index], ...] per ring] (kind 0 outside
//                          with index -1, 1 a face, 2 a kept cell), triangles
//                          [[id, id, id]], read_point null | [i, j]}]}
//          -- the marks' planar faces as built (gen/model/scene_marks.h),
//   shapes: null | {tilt, steepness, structural_texture, cells_tilted, cells_clamped,
//                   cells_clamped_level, cells_textured, dimple_units, first_id,
//                   extra [[i, j]], extra_z [z units]} -- fan centres and crossings,
//   legend: null | {title, units, table (as asked for, for reports),
//            standard {name, dot_base_mm, dot_height_mm, dot_pitch_mm,
//                      cell_pitch_mm, line_pitch_mm},
//            text [lines], cells [[braille cell 0..255, ...] per line],
//            dots [[x, y] legend frame mm], size_mm [w, d], origin_mm [x, y]
//            (the legend frame's origin in the model frame), reach_row,
//            plate_mm {south, north, east}, plate_top_units,
//            plate_bottom_units (version 7; 0 before)},
//   scale: null | {step, step_given, x0_i, y0_j, y1_j, x_mm [west, steps'
//           west, east], y_mm [south, north], foot_top_units,
//           steps [[value, top_units, y_south_mm, y_north_mm], ...],
//           contacts [kept index], fillers [kept index]},
//   class_textures: null | {height_units, relief_units, textures_used,
//           classes [[code, texture name, shared, cells], ...] commonest first}
//           (a class map's classes at one height, told apart by texture:
//           gen/model/features/class_textures.h; the textures themselves are
//           the cells' shapes),
//   hull [[i, j], ...], notes [...],
//   model (optional) {file, bytes, xxh3_64}: the model file written with
//         this sidecar (tsf gen -o): its name without folder, its size and
//         the XXH3-64 hash of its bytes as 16 hex digits
//         (gen/util/file_stamp.h), so a sidecar from another run is refused
//         (sidecars written before XXH3 hold fnv1a64, FNV-1a 64, instead),
//   cells [{col, row, value (null = no data), top, bottom,
//           fan (only a cell drawn as a fan): {centre_top, crossings_top [6],
//                  centre_bottom, crossings_bottom [6] (mirrored)} planar ids,
//           shape (only a tilted or structural cell): {top_dz [6], centre_dz,
//                  bottom_dz [6], bottom_centre_dz (mirrored), slope [x, y] mm/mm,
//                  structural}}, ...]   -- ordered by (row, col)
// marks.tab, legend, scale and class_textures are the features' own records, each written
// and read by its feature (gen/model/feature_records.h: the one list); the
// sidecar places them at those members and names no feature.
// Heights (top, bottom, floor_units, ...) are integers in z_snap_mm units;
// lengths are millimetres; doubles are written in their shortest form that
// reads back to the same bits, so a Scene round-trips exactly.
// Everything is recorded as resolved and read as recorded: reading a sidecar
// translates no braille, places nothing and triangulates nothing (the
// legend, the scale, the marks' faces, the tilted tops' fans). Every index
// read is checked against the Scene, so a hand-edited sidecar is an
// InputError, never a face reaching outside the model. Scene::kept_index,
// kind and drawn_by_face follow from the cells and the faces. Sidecars of
// versions 1 to 4 have their faces and fans built again from the marks and
// the offsets.
#pragma once

#include <optional>
#include <string>

#include <nlohmann/json.hpp>

#include "gen/model/scene.h"
#include "gen/util/file_stamp.h"

namespace tsf {

inline constexpr const char* kSceneJsonFormat = "tsf-scene";
/// 5: everything as resolved: the legend as placed (dots, plate, standard), not
/// as asked for, the marks' faces and the tilted tops' fans; 4: scale;
/// 3: shapes; 2: marks, nodata_pit_units, one_to_one. 1 to 4 are still read,
/// except a version 4 sidecar with a legend (it recorded only the request).
inline constexpr int kSceneJsonVersion = 8;
/// Largest grid (cols * rows) a sidecar may describe: bounds the memory a
/// malformed file can make the reader allocate (kept_index: 4 bytes a cell).
inline constexpr int64_t kMaxSceneJsonCells = 100'000'000;

/// Largest sidecar file read (bytes): a sidecar at kMaxSceneJsonCells kept
/// cells would be larger, but models that size are not verified through a
/// sidecar; the cap keeps an endless stream (/dev/zero) from filling memory.
inline constexpr int64_t kMaxSceneJsonBytes = int64_t(2) << 30;  // 2 GiB

/// The model file a sidecar belongs to (its "model" member).
struct SceneModelRecord {
    std::string file;  ///< file name, no folder
    FileStamp stamp;   ///< its size and hash when the sidecar was written
};

/// Every field of the Scene (see the file comment).
nlohmann::json sceneToJson(const Scene& scene);

/// The Scene described by j. Throws InputError (no file, no line) whose
/// message starts with the JSON path of the problem ("cells[12].top: expected
/// an integer") for a missing or mistyped member, an unknown enum name, a
/// wrong format or version, a cell outside the grid, cells out of
/// (row, col) order or repeated, or a cell whose bottom is not below its top.
Scene sceneFromJson(const nlohmann::json& j);

/// The sidecar's cells as writeSceneJson writes them after the scene's head
/// (one cell a line). They are most of a large sidecar (a million cells:
/// 63 MB, about 0.15 s to format) and do not depend on the model's stamp,
/// so a caller may format them while the model is still being written.
std::string sceneCellsJson(const Scene& scene);

/// Writes sceneToJson(scene) to path atomically (gen/util/atomic_file.h),
/// one cell per line, with the "model" member when `model` is given; `cells`
/// is sceneCellsJson(scene) when the caller formatted them already (else
/// they are formatted here, a block at a time). Throws InputError for an
/// unusable folder, std::runtime_error for I/O failures.
void writeSceneJson(const Scene& scene, const std::string& path, const SceneModelRecord* model = nullptr,
                    const std::string* cells = nullptr);

/// Reads a sidecar (at most kMaxSceneJsonBytes). Throws InputError naming
/// path: with line and column for malformed JSON, with the JSON path (as
/// sceneFromJson) for a bad Scene or a bad "model" member. `model`, when
/// given, receives the "model" member (empty when the sidecar has none).
Scene readSceneJson(const std::string& path, std::optional<SceneModelRecord>* model = nullptr);

/// The same for text already in memory; `path` names the source in errors.
Scene parseSceneJson(const std::string& text, const std::string& path,
                     std::optional<SceneModelRecord>* model = nullptr);

/// Throws InputError naming sidecar_path when `record` names the file at
/// model_path (same file name) but the file there is not the one the sidecar
/// was written with (another size or hash): the model and its sidecar come
/// from different runs of tsf gen. Files of other names (an OpenSCAD render
/// of the same model) are not compared.
void checkSceneModelRecord(const SceneModelRecord& record, const std::string& sidecar_path,
                           const std::string& model_path);

}  // namespace tsf
