// The edge ruler: raised teeth along the model's south and west edges, every
// N cells, so a reader says where a value is ("third tooth east, second
// north") and finds it again, and the key says which column and row each
// tooth marks.
//
// A tooth is a small block beside an edge pillar: a collar from z = 0 to
// the floor (the base's top) standing against the pillar's outer walls
// exactly as the tab and the tactile scale do
// (gen/model/scene_attachments.h), and on its outer part, kRulerCollarMm
// clear of the pillar, a ridge kRulerToothRiseMm above the floor: a finger
// sweeping along the edge meets it, and `tsf feel` (whose relief is the
// height above the floor) renders it. The collar keeps the raised part off
// the pillar, so a tooth stands beside a pillar of any height.
//   - SOUTH, under the bottom tip of the southernmost pillar whose centre
//     lies on the tick's line (lattice i, every N cells of a row from the
//     south-west pillar): against the pillar's south-west and south-east
//     walls, reaching kRulerToothDepthMm south of the tip, as wide as the
//     pillar; it marks that pillar's column;
//   - WEST, against the west wall of the westernmost pillar of every Nth
//     row, from the southernmost row whose westernmost pillar sticks out
//     west of the rows beside it (rows alternate by half a cell; a tooth in
//     the notch between two rows would leave a slot too narrow to print),
//     reaching kRulerToothDepthMm west, as tall (north-south) as that wall;
//     it marks that row. Chosen by tsf, N is even along this edge, so on a
//     rectangle every line has a pillar that sticks out.
// Every vertex where a tooth meets its pillar is a lattice corner at
// height 0 or the floor, so the joined model needs no boolean operation.
//
// A tooth stands only where it is clear of every other pillar (by
// kRulerGapMm: a slot a nozzle prints) and of what was placed before it (the
// orientation tab, the legend's plate, the scale: Scene::claims), where its
// pillar rises to the floor at the walls it touches (not a no-data pit, not
// a tilted corner below the floor, not a mark's face). A line with no room
// has no tooth; the key lists the teeth there are, in order, with what each
// marks, so counting teeth always gives the right column and row.
//
// Flat models only: a mirrored model has no floor to stand the teeth on.
// Placed by placeRuler in FeaturePhase::Beside, after the tactile scale.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "gen/model/feature.h"
#include "gen/model/scene.h"
#include "gen/model/scene_attachments.h"

namespace tsf {

/// How far a tooth reaches out from the pillars, mm: its collar and a
/// ridge 2 mm deep, a bump a fingertip finds sweeping along an edge.
inline constexpr double kRulerToothDepthMm = 3.0;
/// The collar between the pillar and the ridge, at the floor, mm: two
/// nozzle widths and a little, so the slot beside a tall pillar prints open.
inline constexpr double kRulerCollarMm = 1.0;
/// How far the ridge rises above the floor, mm: raised lines of tactile
/// graphics are felt from about 0.5 mm and read without searching at 1 mm
/// (docs/tactile.md); five 0.2 mm layers.
inline constexpr double kRulerToothRiseMm = 1.0;
/// The least distance between two teeth chosen by tsf, mm: a fingertip
/// counts bumps 10 mm apart without slipping over one (docs/tactile.md).
inline constexpr double kRulerSpacingMm = 10.0;
/// The least gap between a tooth and a pillar it does not stand against, mm:
/// two 0.4 mm nozzle widths and a little, so the slot prints open.
inline constexpr double kRulerGapMm = 1.0;

/// What the user asks for (tsf gen --ruler [N]), in SceneParams::requests.
struct RulerRequest {
    std::optional<int> every;  ///< cells between teeth on both edges; none = chosen (kRulerSpacingMm)
};

/// One tooth as placed.
struct RulerTooth {
    bool south = true;       ///< south edge (marks a column) or west edge (marks a row)
    int32_t kept = -1;       ///< the pillar it stands against
    int32_t col = 0, row = 0;  ///< that pillar's grid cell (row 0 the north row)
    int32_t ordinal = 0;     ///< which line: 0 the south-west pillar's, then every `every` cells east or north
    /// Its footprint (mm, counter-clockwise from above): south, the
    /// pillar's lower-right corner, its bottom tip, its lower-left corner,
    /// then the two outer corners; west, the pillar's lower-left and
    /// upper-left corners, then the two outer corners.
    std::vector<double> xy;  ///< x0, y0, x1, y1, ...
    /// The ridge's footprint (mm, counter-clockwise): its corner on the side
    /// before the outer edge, the two outer corners, its corner on the side
    /// after it.
    std::vector<double> ridge;
};

/// The ruler as placed on a model.
struct SceneRuler {
    int every_x = 0, every_y = 0;  ///< cells between teeth along the south and the west edge
    bool every_given = false;      ///< --ruler N (else chosen)
    double spacing_x_mm = 0, spacing_y_mm = 0;  ///< between neighbouring lines
    int32_t lines_x = 0, lines_y = 0;  ///< lines along each edge (teeth where there is room)
    int64_t top_units = 0;         ///< the ridges' top: kRulerToothRiseMm above the floor
    std::vector<RulerTooth> teeth; ///< south teeth west to east, then west teeth south to north
};

/// The ruler placed on `scene`, or null.
const SceneRuler* sceneRuler(const Scene& scene);

/// Places the ruler SceneParams::requests asks for (none when it asks for
/// nothing). Throws InputError saying what to change when it cannot stand.
void placeRuler(Scene& scene);

/// The teeth as one body: joined, open where they stand against the
/// pillars (those vertices name their lattice corners); else closed.
JoinedBody meshRulerBody(const Scene& scene, bool joined);
std::optional<Attachment> rulerAttachment(const Scene& scene, Assembly assembly);
std::optional<BoxMm> rulerBoxMm(const Scene& scene);
std::optional<int64_t> rulerTopAt(const Scene& scene, double x_mm, double y_mm);
ProbeSet rulerProbes(const Scene& scene);
/// What the mesher relies on (InputError "scene: ruler: ...").
void checkRuler(const Scene& scene);

// ruler_record.cpp: the sidecar record, the facts, the key and the OpenSCAD piece.
nlohmann::json rulerRecord(const Scene& scene);
void readRulerRecord(const nlohmann::json& record, const std::string& path, int version, Scene& scene);
nlohmann::json rulerFactsJson(const Scene& scene);
std::string rulerFactsLines(const Scene& scene);
std::string rulerKeyParagraph(const Scene& scene, const KeyNumbers& numbers);
std::optional<ScadPiece> rulerScadPiece(const Scene& scene);
/// What the ruler asks a hand to find: each ridge at least 0.5 mm above
/// the floor, once printed.
std::vector<TactileClaim> rulerTactileClaims(const Scene& scene);

}  // namespace tsf
