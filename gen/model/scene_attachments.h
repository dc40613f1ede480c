// Attachments and cuts: the vocabulary in which a feature hands its solid to
// the consumers (the direct mesher, the parts of a multi-part model), so
// that none of them has to know which feature made it. Data only; the
// features produce these (gen/model/features/), gen/model/attachments.h
// gathers them from a Scene.
//
// An ATTACHMENT is a body that stands beside or on the pillars and is not a
// cell: the orientation tab, the braille legend's plate and dots, the
// tactile scale. It is joined to the pillars exactly, never by a boolean:
//   - where it stands against a pillar's wall, the wall is not drawn over
//     the contact's z span (a WallContact on a hexagon edge, or a
//     RingContact on the edge of a planar face that draws the cell), and the
//     wall's corner lines split at the span's ends, as they would for a
//     neighbouring pillar of that span;
//   - its body leaves those sides open, and every body vertex on a contact's
//     corner names the lattice corner (JoinedBody::lattice_id), so the
//     mesher uses the pillars' own vertex there: the two share the
//     contact's edges, with no T-junction.
// A CUT is a hole into the flat bottom (a half's pin hole): a ring on the
// bottom, a straight wall up to a depth and a cone to an apex.
//
// Frame and units as the Scene's (gen/model/scene.h): mm in x and y (or
// lattice coordinates, snapped by Scene::point), z in the Scene's z units.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "gen/field/hex_grid.h"
#include "gen/geometry/mesh.h"
#include "gen/model/scene_marks.h"

namespace tsf {

/// How the model is put together: one piece, or parts that touch (a
/// multi-part 3MF, gen/mesh/scene_parts.h).
enum class Assembly : uint8_t {
    OnePiece,  ///< every attachment joined to the pillars
    Parts,     ///< an attachment's own part apart; only what stays with the pillars joined
};

/// A corner of an attachment's outline seen from +z (the orientation tab's,
/// the braille legend's plate): its position (mm, on the kXYSnapMm grid)
/// and, where it is a hex corner of a pillar the body stands against, that
/// corner's lattice vertex id (hex_grid.h; -1: the body's own).
struct OutlinePoint {
    double x_mm = 0, y_mm = 0;
    int64_t lattice = -1;
};

/// Edge `edge` (0..5, hex_grid.h) of kept cell `kept` is covered by an
/// attachment over [bottom_units, top_units]: no wall is drawn there over
/// that span.
struct WallContact {
    int32_t kept = -1;
    int edge = 0;
    int64_t bottom_units = 0, top_units = 0;
};

/// The same along the edge from -> to (planar vertex ids, the face's
/// direction) of a planar face that draws a cell (a mark in the data).
struct RingContact {
    int64_t from = -1, to = -1;
    int64_t bottom_units = 0, top_units = 0;
};

/// A body to join to the pillars: a mesh (mm) whose vertices on a contact's
/// corner name that lattice corner (lattice_id[v] >= 0, hex_grid.h; its z
/// is on the z grid), -1 for the body's own. Open where it meets the pillars.
struct JoinedBody {
    Mesh mesh;
    std::vector<int64_t> lattice_id;
};

/// An x, y box in the model frame, mm.
struct BoxMm {
    double x0 = 0, x1 = 0, y0 = 0, y1 = 0;
};

/// Part of the model frame (mm) a feature takes (gen/model/feature.h),
/// which a feature placed later keeps clear of; `what` and `leave_out` let
/// that feature say why it could not be placed ("the braille legend's
/// plate", "--title/--units (the plate north of the pillars)").
struct FootprintClaim {
    BoxMm box;
    std::string what;
    std::string leave_out;
};

/// What stands beside the pillars east or west and takes bed width from
/// them, before the Scene is built: the attachment's name for a person and
/// its width (mm).
struct SideWidth {
    std::string what;  ///< "the tactile scale"
    double width_mm = 0;
};

/// One attachment as an Assembly draws it.
struct Attachment {
    /// The part its own piece prints as in a multi-part model ("marks",
    /// "legend", "scale"): parts of one name are one part.
    std::string part;
    /// What the pillars' walls give way to, and the body joined to them.
    std::vector<WallContact> walls;
    std::vector<RingContact> ring_walls;
    JoinedBody joined;
    /// Assembly::Parts: its own part, closed (empty: nothing apart).
    Mesh own_part;
};

/// A hole into the flat bottom: `ring` counter-clockwise from above (lattice
/// coordinates) at z = 0, a straight wall up to depth_units, a cone to the
/// apex at `centre`, apex_units high.
struct BottomHole {
    std::vector<PlanarPoint> ring;
    LatticePoint centre;
    int64_t depth_units = 0, apex_units = 0;
};

/// A place where the written mesh must show what the Scene says, so one
/// read-back (verify/attachment_readback.h) proves every attachment and mark
/// from the model file, whatever feature made it. A probe is a vertical line
/// at (x, y) mm: cast down it from above the mesh, the first surface met must
/// be at z_mm (a surface probe), or nothing may be met at all (an empty
/// probe: a cut through the whole model, such as the orientation notch).
/// Probes stand where the surface is level or at a vertex of the drawn
/// surface (a braille dot's apex), so the expected height is exact, not
/// sampled from a curve.
struct SurfaceProbe {
    std::string what;  ///< for a person: "braille dot 3 of 12", "the step for 10"
    double x_mm = 0, y_mm = 0;
    bool empty = false;  ///< true: the vertical line meets no surface at all
    double z_mm = 0;     ///< else: z of the first surface met from above
    /// Largest slope (dz per mm in x, y) of the surface next to the probe: 0
    /// for a level surface. A model written in float32 moves each vertex by
    /// up to 2^-24 of its coordinates, so a probe on a slope (a dot's apex)
    /// reads that shift times the slope, which the read-back allows for.
    double slope = 0;
};

/// The probes of one read-back check.
struct ProbeSet {
    std::string name;   ///< the check is "<name>_read_back": "legend", "scale", "marks"
    std::string title;  ///< "the legend plate and every braille dot at its height"
    std::vector<SurfaceProbe> probes;
};

}  // namespace tsf
