#include "verify/tactile.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "gen/field/hex_grid.h"
#include "gen/model/feature_registry.h"
#include "gen/model/features/felt_heights.h"
#include "gen/model/features/braille.h"
#include "gen/model/features/placed_marks.h"
#include "gen/model/features/top_shapes.h"
#include "gen/model/scene.h"
#include "gen/util/number_format.h"
#include "verify/attachment_joint.h"
#include "verify/finger_reach.h"
#include "verify/mesh_topology.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

constexpr double kPi = std::numbers::pi;

double msSince(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

double norm(const Vec3& a) { return std::sqrt(dot(a, a)); }

// Keeps the `keep` offenders with the smallest amount, smallest first.
void keepWorst(std::vector<Offender>& worst, size_t keep, bool smallest_first) {
    std::sort(worst.begin(), worst.end(), [&](const Offender& a, const Offender& b) {
        return smallest_first ? a.amount < b.amount : a.amount > b.amount;
    });
    if (worst.size() > keep) worst.resize(keep);
}

// An edge two consistently oriented triangles share, with its interior
// dihedral angle (radians, in (0, 2 pi)).
struct EdgeAngle {
    uint32_t a = 0, b = 0;
    double theta = 0;
};

// The interior dihedral angle at every edge that exactly two consistently
// oriented triangles share; edges on a border, or shared by more than two
// triangles, get none (incident[v] counts every edge at v, so a vertex can
// tell whether all of its edges were measured). The edges are found around
// each vertex from its list of triangles (a handful on a terrain mesh), on
// the verifier's threads, and listed by their vertex pair, smaller vertex
// first: no sort of every triangle side (4 of the 6.7 s this check took on a
// 1000 x 1000 model). The angles are left in one list per thread, in order
// (joined they would be a second copy: 320 MB at 1000 x 1000). False for an
// empty mesh.
bool dihedralAngles(const Mesh& m, std::vector<std::vector<EdgeAngle>>& parts, std::vector<uint32_t>& incident) {
    const size_t nv = m.positions.size();
    // Each vertex's triangles, ascending (corner / 3), from the verifier's
    // one grouping of corners by vertex; a triangle with an index out of
    // range is left out.
    auto usable = [&](const std::array<uint32_t, 3>& q) { return q[0] < nv && q[1] < nv && q[2] < nv; };
    std::vector<uint8_t> in_range;
    if (!std::all_of(m.triangles.begin(), m.triangles.end(), usable)) {
        in_range.resize(m.triangles.size());
        for (size_t t = 0; t < m.triangles.size(); ++t) in_range[t] = usable(m.triangles[t]);
    }
    const VertexCorners corners = cornersByVertex(m, in_range.empty() ? nullptr : &in_range);
    const std::vector<uint32_t>& start = corners.start;
    auto triangleAt = [&](uint32_t e) { return corners.list[e] / 3; };
    incident.assign(nv, 0);
    const unsigned workers = detail::workerCount(0);
    parts.assign(workers, {});
    // One use of an edge x-y by a triangle around x: y, the triangle, and
    // whether it runs x -> y.
    struct Use {
        uint32_t y, t;
        bool forward;
    };
    auto work = [&](unsigned w) {
        // A closed mesh has 3/2 edges per triangle, each measured once: room
        // for a worker's share of them at once (no copying as the list grows;
        // pages never written are never touched).
        parts[w].reserve(m.triangles.size() * 3 / 2 / workers + 64);
        std::vector<Use> uses;
        const size_t from = nv * w / workers, to = nv * (w + 1) / workers;
        for (size_t x = from; x < to; ++x) {
            // Every side at x of the triangles around it, once: a side
            // x -> y or y -> x (y != x), in the order of the triangles and of
            // their sides; then grouped by y, that order kept in a group.
            uses.clear();
            for (uint32_t e = start[x]; e < start[x + 1]; ++e) {
                const uint32_t t = triangleAt(e);
                const auto& q = m.triangles[t];
                for (int k = 0; k < 3; ++k) {
                    const uint32_t p = q[k], n = q[(k + 1) % 3];
                    if (p == x && n != x) uses.push_back({n, t, true});
                    else if (n == x && p != x) uses.push_back({p, t, false});
                }
            }
            // Insertion (stable, and no buffer to allocate: a vertex has a dozen or two sides).
            for (size_t i = 1; i < uses.size(); ++i) {
                const Use u = uses[i];
                size_t k = i;
                for (; k > 0 && uses[k - 1].y > u.y; --k) uses[k] = uses[k - 1];
                uses[k] = u;
            }
            uint32_t distinct = 0;
            for (size_t g = 0; g < uses.size();) {
                const uint32_t y = uses[g].y;
                size_t g1 = g;
                while (g1 < uses.size() && uses[g1].y == y) ++g1;
                ++distinct;
                // The triangles using edge x-y (the first two), and which way each runs along it.
                const size_t used = g1 - g;
                const uint32_t tri[2] = {uses[g].t, used > 1 ? uses[g + 1].t : 0};
                const bool forward[2] = {uses[g].forward, used > 1 && uses[g + 1].forward};
                g = g1;
                if (y < x) continue;
                // Measured when one triangle runs x -> y and one y -> x.
                if (used != 2 || forward[0] == forward[1]) continue;
                const auto& t1 = m.triangles[tri[0]];
                const auto& t2 = m.triangles[tri[1]];
                const Vec3 n1 = cross(sub(m.positions[t1[1]], m.positions[t1[0]]), sub(m.positions[t1[2]], m.positions[t1[0]]));
                const Vec3 n2 = cross(sub(m.positions[t2[1]], m.positions[t2[0]]), sub(m.positions[t2[2]], m.positions[t2[0]]));
                const double l1 = norm(n1), l2 = norm(n2);
                if (l1 == 0 || l2 == 0) continue;  // a degenerate triangle: the solid checks report it
                uint32_t apex2 = t2[0];
                for (const uint32_t v : t2)
                    if (v != x && v != y) apex2 = v;
                const double c = std::clamp(dot(n1, n2) / (l1 * l2), -1.0, 1.0);
                const double phi = std::acos(c);
                // Convex when the other triangle's apex lies behind this one's plane.
                const bool convex = dot(n1, sub(m.positions[apex2], m.positions[x])) < 0;
                parts[w].push_back({uint32_t(x), y, convex ? kPi - phi : kPi + phi});
            }
            incident[x] = distinct;
        }
    };
    detail::runOnWorkers(workers, [&](unsigned w, const auto&) { work(w); });
    return !m.triangles.empty();
}

// Sharp points and knife edges: both read the interior dihedral angles.
void checkPointsAndEdges(const Mesh& m, const TactileOptions& o, TactileResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    Check points{"tactile_sharp_points", "no sharp points on the touched surface"};
    Check edges{"tactile_knife_edges", "no knife edges on the touched surface"};
    points.unit = "deg";
    edges.unit = "deg";
    std::vector<std::vector<EdgeAngle>> angles;
    std::vector<uint32_t> incident;
    if (!dihedralAngles(m, angles, incident)) {
        for (Check* c : {&points, &edges}) {
            c->status = CheckStatus::Skipped;
            c->note = "skipped: an empty mesh";
        }
    } else {
        double bed = std::numeric_limits<double>::infinity();
        for (const Vec3& p : m.positions) bed = std::min(bed, p.z);
        auto onBed = [&](uint32_t v) { return m.positions[v].z <= bed; };
        // A vertex's material fills the solid angle sum(dihedrals) - (n - 2) pi
        // (the area of its link, a spherical polygon whose angles are the
        // dihedral angles of its n edges).
        std::vector<double> sum(m.positions.size(), 0.0);
        std::vector<uint32_t> count(m.positions.size(), 0);
        const double knife = kKnifeEdgeDeg * kPi / 180;
        double sharpest_edge = 180;
        for (const auto& part : angles)
        for (const auto& [a, b, theta] : part) {
            sum[a] += theta;
            sum[b] += theta;
            ++count[a];
            ++count[b];
            if (onBed(a) && onBed(b)) continue;
            sharpest_edge = std::min(sharpest_edge, theta * 180 / kPi);
            if (theta < knife) {
                ++edges.count;
                const Vec3 mid{(m.positions[a].x + m.positions[b].x) / 2, (m.positions[a].y + m.positions[b].y) / 2,
                               (m.positions[a].z + m.positions[b].z) / 2};
                edges.worst.push_back({mid, theta * 180 / kPi,
                                       "faces meet at " + formatFixed(theta * 180 / kPi, 1) + " degrees along " +
                                           formatFixed(norm(sub(m.positions[a], m.positions[b])), 2) + " mm"});
            }
        }
        const double half = kSharpPointHalfAngleDeg * kPi / 180;
        const double limit_sr = 2 * kPi * (1 - std::cos(half));
        double sharpest_point = 360;
        for (uint32_t v = 0; v < m.positions.size(); ++v) {
            // Only where every edge of the vertex was measured (its link is a closed polygon).
            if (count[v] < 3 || count[v] != incident[v] || onBed(v)) continue;
            const double omega = sum[v] - double(count[v] - 2) * kPi;
            // As the half-angle of the cone of that solid angle, degrees.
            const double cone = std::acos(std::clamp(1 - omega / (2 * kPi), -1.0, 1.0)) * 180 / kPi;
            sharpest_point = std::min(sharpest_point, cone);
            if (omega < limit_sr) {
                ++points.count;
                points.worst.push_back({m.positions[v], cone,
                                        "a point as narrow as a cone of " + formatFixed(cone, 1) + " degrees (half-angle)"});
            }
        }
        keepWorst(points.worst, o.max_offenders, true);
        keepWorst(edges.worst, o.max_offenders, true);
        points.status = points.count ? CheckStatus::Fail : CheckStatus::Pass;
        edges.status = edges.count ? CheckStatus::Fail : CheckStatus::Pass;
        points.note = "narrowest point a cone of " + formatFixed(std::min(sharpest_point, 180.0), 1) +
                      " degrees (half-angle); limit " + formatFixed(kSharpPointHalfAngleDeg, 0) + " degrees";
        edges.note = "sharpest convex edge " + formatFixed(sharpest_edge, 1) + " degrees; limit " + formatFixed(kKnifeEdgeDeg, 0) +
                     " degrees";
    }
    const double ms = msSince(t0);
    for (Check* c : {&points, &edges}) {
        c->time_ms = ms;
        c->stage = "tactile_angles";
        r.checks.push_back(std::move(*c));
    }
    r.stages.push_back({"tactile_angles", ms});
}

// Samples of `top` where no value stands, from the Scene: the pits of kept
// cells without data (a hole there says "no data"), and everything off the
// data cells (the groove that separates the pillars from the scale or the
// plate beside them, the floor of a notch). Nothing is read at their
// bottom; the data tops are what a fingertip must reach. Empty without a
// Scene: then every pit counts.
std::vector<uint8_t> noValueSamples(const TopHeightField& top, const Scene* s) {
    constexpr double kRimMm = 0.01;
    std::vector<uint8_t> out;
    if (!s) return out;
    out.assign(top.z.size(), 1);
    // (x, y) lies so far inside the hexagon of (col, row) that the points
    // kRimMm from it lie inside too, by more than any rounding: those four
    // would find the same cell, and need not be looked up (most samples of
    // a top are such). In pitches, hexagon centred, across flats 1 in x
    // (hexCellAt's frame): inside is |dx| <= 1/2 and |dx| / 2 + |dy| sqrt(3)
    // / 2 <= 1/2, and a step of ex in x and ey in y moves those by at most
    // ex and ex / 2 + ey sqrt(3) / 2.
    const double ex = kRimMm / s->pitch_mm, ey = kRimMm / (s->pitch_mm * s->y_scale);
    constexpr double kSurely = 1e-9;  // pitches: far beyond the roundings of these few operations
    const auto wellInside = [&](double x, double y, int32_t col, int32_t row) {
        const LatticePoint ctr = hexCentre(s->grid, col, row);
        const double dx = std::fabs(x / s->pitch_mm - double(ctr.i) * 0.5);
        const double dy = std::fabs(y / (s->pitch_mm * s->y_scale) - double(ctr.j) / (2.0 * kSqrt3));
        return 0.5 - dx > ex + kSurely && 0.5 - 0.5 * dx - 0.5 * kSqrt3 * dy > 0.5 * ex + 0.5 * kSqrt3 * ey + kSurely;
    };
    for (int j = 0; j < top.ny; ++j)
        for (int i = 0; i < top.nx; ++i) {
            const double x = top.x0 + i * top.step, y = top.y0 + j * top.step;
            // A sample on a cell's rim (the grid anchors samples on whole
            // half millimetres, where walls can stand) reads the wall or
            // the floor below it, not the top: a data sample lies inside
            // the cell, a hundredth of a millimetre from every side.
            const auto cellAt = [&](double dx, double dy, int32_t& col, int32_t& row) {
                return hexCellAt(s->grid, (x + dx) / s->pitch_mm, (y + dy) / (s->pitch_mm * s->y_scale), col, row)
                           ? s->keptAt(col, row)
                           : -1;
            };
            int32_t col = 0, row = 0, c = 0, r = 0;
            const int32_t cell = cellAt(0, 0, col, row);
            if (cell < 0 || s->kind[size_t(cell)] != CellKind::Data) continue;
            if (wellInside(x, y, col, row) ||
                (cellAt(kRimMm, 0, c, r) == cell && cellAt(-kRimMm, 0, c, r) == cell && cellAt(0, kRimMm, c, r) == cell &&
                 cellAt(0, -kRimMm, c, r) == cell))
                out[size_t(j) * size_t(top.nx) + size_t(i)] = 0;
        }
    return out;
}

void checkFingerReach(const Mesh& m, const Scene* scene, const TactileOptions& o, TactileResult& r) {
    const auto t0 = std::chrono::steady_clock::now();
    Check c{"tactile_finger_reach", "a fingertip reaches the bottom of every pit and valley"};
    c.unit = "mm";
    const TopHeightField top = sampledTop(m, o.sample_mm, kAdultFingertipRadiusMm);
    const FingerReachResult reach =
        top.z.empty() ? FingerReachResult{}
                      : fingerReach(top, meshBounds(m).min.z, {kAdultFingertipRadiusMm, kChildFingertipRadiusMm},
                                    noValueSamples(top, scene));
    if (reach.fingers.size() != 2) {
        c.status = CheckStatus::Skipped;
        c.note = "skipped: an empty mesh";
    } else {
        const FingerReach& adult = reach.fingers[0];
        const FingerReach& child = reach.fingers[1];
        c.count = adult.places;
        c.worst = adult.worst;
        if (c.worst.size() > o.max_offenders) c.worst.resize(o.max_offenders);
        c.status = adult.places ? CheckStatus::Fail : CheckStatus::Pass;
        auto said = [](const FingerReach& f) {
            return std::to_string(f.places) + (f.places == 1 ? " place" : " places") + " (" + formatFixed(f.area_mm2, 1) +
                   " mm^2, deepest " + formatFixed(f.deepest_mm, 1) + " mm)";
        };
        c.note = "an adult's fingertip (" + formatFixed(2 * kAdultFingertipRadiusMm, 0) + " mm) leaves " + said(adult) +
                 " more than " + formatFixed(kUnreachedDepthMm, 1) + " mm deep unreached, a child's (" +
                 formatFixed(2 * kChildFingertipRadiusMm, 0) + " mm) " + said(child) +
                 (adult.no_value_area_mm2 > 0 ? "; where no value stands (pits of cells without data, the groove beside the "
                                                    "pillars: " + formatFixed(adult.no_value_area_mm2, 1) +
                                                    " mm^2 out of reach) nothing is read"
                                              : std::string()) +
                 "; top sampled every " + formatSignificant(reach.step_mm, 2) + " mm";
    }
    c.time_ms = msSince(t0);
    c.stage = "tactile_reach";
    r.stages.push_back({"tactile_reach", c.time_ms});
    r.checks.push_back(std::move(c));
}

void checkMarks(const Scene& s, const TactileOptions& o, TactileResult& r) {
    Check c{"tactile_marks", "the orientation marks are there, of a size a fingertip recognises"};
    c.unit = "mm";
    const PlacedMarks m = placedMarks(s);
    const bool has_notch = m.has_notch, has_triangle = m.has_triangle;
    const double notch = m.notch_depth_mm, long_leg = m.long_leg_mm, short_leg = m.short_leg_mm;
    const Vec3 at{m.corner_x_mm, m.corner_y_mm, s.zMm(s.floor_units)};
    auto miss = [&](const std::string& what, double amount) {
        ++c.count;
        c.worst.push_back({at, amount, what});
    };
    if (!has_notch && !has_triangle) miss("no orientation mark: the reader cannot tell which corner is the origin", 0);
    if (has_notch && notch < kMinNotchDepthMm)
        miss("the notch is " + formatFixed(notch, 2) + " mm deep, " + formatFixed(kMinNotchDepthMm - notch, 2) +
                 " mm short of " + formatFixed(kMinNotchDepthMm, 1) + " mm",
             notch);
    if (has_triangle && short_leg < kMinTriangleLegMm)
        miss("the triangle's shorter leg is " + formatFixed(short_leg, 1) + " mm, under " + formatFixed(kMinTriangleLegMm, 2) + " mm",
             short_leg);
    if (has_triangle && long_leg < kMinTriangleLongLegMm)
        miss("the triangle's longer leg is " + formatFixed(long_leg, 1) + " mm, under " + formatFixed(kMinTriangleLongLegMm, 1) + " mm",
             long_leg);
    if (c.worst.size() > o.max_offenders) c.worst.resize(o.max_offenders);
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.note = std::string(has_notch ? "notch " + formatFixed(notch, 1) + " mm deep" : "no notch") + ", " +
             (has_triangle ? "triangle legs " + formatFixed(long_leg, 1) + " x " + formatFixed(short_leg, 1) + " mm" : "no triangle") +
             " " + m.where;
    c.stage = "tactile_marks";
    r.checks.push_back(std::move(c));
}

// The top of kept cell k at its centre, mm.
double centreTopMm(const Scene& s, size_t k) { return s.zMm(centreTop(s, k)); }

void checkPillars(const Scene& s, const TactileOptions& o, TactileResult& r) {
    // A regular hexagon w across flats (side a = w / sqrt 3) bends like a
    // beam whose weaker section modulus is I / c = (5 sqrt(3) / 16 a^4) / a
    // = 5 / 48 w^3: a push F at height h stresses its foot F h / S, and it
    // breaks above the interlayer strength, so it may stand free up to
    // strength * S / F.
    const double w = s.pitch_mm;
    const double section_mm3 = 5.0 / 48.0 * w * w * w;
    const double free_max = kPrintedPlaInterlayerMpa * section_mm3 / kHandPushN;
    Check c{"tactile_slender_pillars", "no pillar slender enough to break under a hand"};
    c.unit = "mm";
    // Tenths of a millimetre; below them two significant digits: a 0.15 mm
    // pillar holds 0.0007 mm free, which one decimal writes as "0.0".
    const auto mm = [](double v) { return v >= 0.1 || v <= 0 ? formatFixed(v, 1) : formatSignificant(v, 2); };
    const double floor_mm = s.zMm(s.params.bottom == Bottom::Mirrored ? 0 : s.floor_units);
    double freest = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        // It stands free above its highest neighbour (the floor without one).
        double around = floor_mm;
        for (int e = 0; e < kHexCorners; ++e) {
            const int32_t n = s.keptNeighbour(k, e);
            if (n >= 0) around = std::max(around, centreTopMm(s, size_t(n)));
        }
        const double free = centreTopMm(s, k) - around;
        freest = std::max(freest, free);
        if (free > free_max) {
            ++c.count;
            const Vec3 at = s.point(hexCentre(s.grid, s.col[k], s.row[k]), centreTop(s, k));
            c.worst.push_back({at, free,
                               "cell (col " + std::to_string(s.col[k]) + ", row " + std::to_string(s.row[k]) + ") stands " +
                                   mm(free) + " mm above its neighbours, " + formatFixed(w, 2) +
                                   " mm across: more than " + mm(free_max) + " mm breaks under " +
                                   formatSignificant(kHandPushN, 3) + " N"});
        }
    }
    keepWorst(c.worst, o.max_offenders, false);
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.note = "highest free stand " + mm(freest) + " mm; a " + formatFixed(w, 2) + " mm pillar stands up to " +
             mm(free_max) + " mm free under a " + formatSignificant(kHandPushN, 3) + " N push";
    c.stage = "tactile_marks";
    r.checks.push_back(std::move(c));
}

void checkHeightSteps(const Scene& s, const TactileOptions& o, TactileResult& r) {
    Check c{"tactile_height_steps", "neighbouring values at least a felt step apart"};
    c.unit = "mm";
    if (const std::optional<OneHeight> one = featureOneHeight(s)) {
        // Every value at one height (a class map's classes, told apart by
        // the feel of their tops): what must be felt is what the feature
        // says, not steps between heights.
        c.status = one->felt ? CheckStatus::Pass : CheckStatus::Warn;
        c.count = one->felt ? 0 : 1;
        c.note = one->felt_note;
        c.stage = "tactile_marks";
        r.checks.push_back(std::move(c));
        return;
    }
    // A step a reader compares neighbours by: half a millimetre, or a layer
    // where layers are coarser (a step under one is rounded away).
    const double felt = std::max(kFeltHeightStepMm, o.layer_mm);
    int64_t pairs = 0, close = 0;
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.kind[k] != CellKind::Data) continue;
        for (int e = 0; e < 3; ++e) {  // east, north-east, north-west: each pair once
            const int32_t n = s.keptNeighbour(k, e);
            if (n < 0 || s.kind[size_t(n)] != CellKind::Data || s.value[k] == s.value[size_t(n)]) continue;
            ++pairs;
            const double dz = std::fabs(centreTopMm(s, k) - centreTopMm(s, size_t(n)));
            if (dz < felt - 1e-9) {
                ++close;
                if (c.worst.size() < 4 * o.max_offenders)
                    c.worst.push_back({s.point(hexCentre(s.grid, s.col[k], s.row[k]), centreTop(s, k)), dz,
                                       "cell (col " + std::to_string(s.col[k]) + ", row " + std::to_string(s.row[k]) +
                                           ") and its neighbour differ by " + formatSignificant(dz, 3) + " mm"});
            }
        }
    }
    keepWorst(c.worst, o.max_offenders, true);
    c.count = close;
    const double share = pairs ? 100.0 * double(close) / double(pairs) : 0.0;
    c.status = close ? CheckStatus::Warn : CheckStatus::Pass;
    c.note = formatFixed(share, 1) + " % of " + std::to_string(pairs) + " neighbouring pairs of different values differ by less than " +
             formatSignificant(felt, 3) + " mm (they feel the same: compare them against the scale or the key)" +
             (close ? "; a larger --height spreads them" : "") +
             "; by touch alone a reader tells about " + std::to_string(levelsReadWithoutScale(s.mapping.max_height_mm)) +
             " heights apart";
    c.stage = "tactile_marks";
    r.checks.push_back(std::move(c));
}

void checkBraille(const BrailleClaim& b, const TactileOptions& o, TactileResult& r) {
    Check c{"tactile_braille", "the braille dots print inside the standards' range"};
    c.unit = "mm";
    const BrailleStandard& st = b.standard;
    const double printed = printedDotHeightMm(st.dot_height_mm, o.layer_mm);
    const Vec3 at = b.first_dot_mm;
    const std::string layers = " at " + formatSignificant(o.layer_mm, 3) + " mm layers";
    if (printed < kMinPrintedDotHeightMm - 1e-9) {
        ++c.count;
        c.worst.push_back({at, printed,
                           "dots " + formatFixed(st.dot_height_mm, 2) + " mm high print " + formatFixed(printed, 2) + " mm" +
                               layers + ", under the " + formatFixed(kMinPrintedDotHeightMm, 2) +
                               " mm a reader expects: make the model with --layer " + formatSignificant(o.layer_mm, 3)});
    } else if (printed > kMaxBrailleDotHeightMm + 1e-9) {
        ++c.count;
        c.worst.push_back({at, printed,
                           "dots print " + formatFixed(printed, 2) + " mm high" + layers + ", over the " +
                               formatFixed(kMaxBrailleDotHeightMm, 2) + " mm of the highest standard"});
    }
    if (st.dot_pitch_mm - st.dot_base_mm < o.nozzle_mm) {
        ++c.count;
        c.worst.push_back({at, st.dot_pitch_mm - st.dot_base_mm,
                           "the gap between dots, " + formatFixed(st.dot_pitch_mm - st.dot_base_mm, 2) +
                               " mm, is under one width of the " + formatSignificant(o.nozzle_mm, 3) + " mm nozzle: neighbouring dots merge"});
    }
    if (st.dot_base_mm < kMinDotBaseNozzles * o.nozzle_mm) {
        ++c.count;
        c.worst.push_back({at, st.dot_base_mm,
                           "dots " + formatFixed(st.dot_base_mm, 2) + " mm across are under two widths of the " +
                               formatSignificant(o.nozzle_mm, 3) + " mm nozzle: they print as blobs"});
    }
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.note = std::to_string(b.dots) + " dots " + formatFixed(st.dot_base_mm, 2) + " mm across, " +
             formatFixed(st.dot_height_mm, 2) + " mm high, printing " + formatFixed(printed, 2) + " mm" + layers +
             " (range " + formatFixed(kMinPrintedDotHeightMm, 2) + "-" + formatFixed(kMaxBrailleDotHeightMm, 2) + " mm)";
    c.stage = "tactile_marks";
    r.checks.push_back(std::move(c));
}

}  // namespace

const std::vector<TactileThreshold>& tactileThresholds() {
    static const std::vector<TactileThreshold> table = [] {
        std::vector<TactileThreshold> t = {
            {"tactile_sharp_points", "narrowest point of the touched surface (cone half-angle)", kSharpPointHalfAngleDeg, "deg",
             "tsf's rule: a needle or spike reads as a prick, not a shape; a 20-degree cone (a sharpened pencil's tip is "
             "about 10) passes the corners of hexagons (120), of the tab's triangle (31) and of the scale (90)"},
            {"tactile_knife_edges", "smallest angle between two faces along a convex edge", kKnifeEdgeDeg, "deg",
             "tsf's rule: a blade is felt as a cut; a top tilted steeper than 60 degrees meets its wall under 30"},
            {"tactile_finger_reach", "adult fingertip radius", kAdultFingertipRadiusMm, "mm",
             "half the width of an adult index fingertip (about 16 mm across the pad)"},
            {"tactile_finger_reach", "child fingertip radius", kChildFingertipRadiusMm, "mm",
             "index finger diameter 9-22 mm, mean 15 mm, in children aged 3-10 (Ann. Anat. 192(3):156-161, 2010); the "
             "fingertip is narrower than the finger: 11 mm is taken"},
            {"tactile_finger_reach", "depth below a rigid fingertip that a pressing finger still reaches", kUnreachedDepthMm, "mm",
             "the fingertip's pulp yields about 2 mm under a light press of 1 N (Serina, Mote, Rempel, J. Biomech. "
             "30(10):1035-1040, 1997); deeper, the bottom is not felt and its value not read"},
            {"tactile_marks", "notch depth", kMinNotchDepthMm, "mm",
             "1/8 in, the smallest space between two elements a reader perceives (L. Hasty, Design principles for "
             "tactile graphics, '1/8th inch rule')"},
            {"tactile_marks", "triangle's shorter leg", kMinTriangleLegMm, "mm",
             "1/4 in, the smallest component read on its own (L. Hasty, ibid.); APH: symbols closer than 1/4 in are hard "
             "to tell apart"},
            {"tactile_marks", "triangle's longer leg", kMinTriangleLongLegMm, "mm",
             "1/2 in: shapes with sides under 1/2 in may not be recognisable (APH, Guidelines for Design of Tactile "
             "Graphics, 1997)"},
            {"tactile_slender_pillars", "push at a pillar's top", kHandPushN, "N",
             "tsf's rule: a hand leaning on the model, several times the 0.5-2 N fingers use to explore"},
            {"tactile_slender_pillars", "strength of printed PLA across its layers", kPrintedPlaInterlayerMpa, "MPa",
             "the low end of the interlayer strengths measured for FDM-printed PLA (Chacon et al., Materials & Design "
             "124:143-157, 2017: upright specimens, 20-50 MPa)"},
            {"tactile_height_steps", "smallest height step between neighbouring values a reader compares by", kFeltHeightStepMm,
             "mm",
             "3D-printed tactile graphics: heights >= 0.5 mm to detect, >= 1 mm for what matters (printdisability.org, "
             "Round Table on Information Access, 3D printing guidance); steps of 0.56 mm worked as levels on FDM maps "
             "(Wabinski, Moscicka, Touya, PLOS ONE 17(3):e0264564, 2022). A fingertip detects a 1 um edge (Johansson and "
             "LaMotte 1983), but detecting is not comparing. With coarser --layer, one layer"},
            {"tactile_height_steps", "heights a reader identifies without the scale", double(kLevelsReadWithoutScale), "",
             "three levels (0.56, 1.12, 1.68 mm) worked on FDM-printed maps (Wabinski et al. 2022); the summary and the "
             "key say so, not range / 0.5 mm"},
            {"cell size", "spacing under which neighbouring features merge", kMergeSpacingMm, "mm",
             "1/8 in, the smallest space between two elements a reader perceives (L. Hasty, '1/8th inch rule'); tsf "
             "never makes or advises cells under 3 mm by default"},
            {"tactile_braille", "lowest printed dot", kMinPrintedDotHeightMm, "mm",
             "0.019 in, the dot height of NLS Specification 800 (2008) 3.2 (paper braille)"},
            {"tactile_braille", "highest printed dot", kMaxBrailleDotHeightMm, "mm",
             "0.037 in, the top of the dot height range for tactile signs (2010 ADA Standards 703.3.1)"},
            {"tactile_braille", "narrowest dot base, in nozzle widths", kMinDotBaseNozzles, "",
             "tsf's rule: two perimeters side by side make a dome; fewer, a blob"},
        };
        // The features' own (gen/model/feature.h), after their check's rows.
        for (const FeatureThreshold& f : featureThresholds()) {
            auto at = t.end();
            for (auto it = t.begin(); it != t.end(); ++it)
                if (std::string(it->id) == f.check) at = it + 1;
            t.insert(at, {f.check, f.what, f.value, f.unit, f.source});
        }
        return t;
    }();
    return table;
}

namespace {

// What the features of the registry ask a hand to find (gen/model/feature.h:
// TactileClaim), as printed in whole layers. No check without a claim.
void checkFeatureClaims(const Scene& s, const TactileOptions& o, TactileResult& r) {
    Check c{"tactile_features", "what each feature asks a hand to find stands out as printed"};
    c.unit = "mm";
    size_t claims = 0;
    double least = INFINITY;
    const std::string layers = formatSignificant(o.layer_mm, 3) + " mm layers";
    for (const Feature* f : features()) {
        if (!f->tactile_claims) continue;
        for (const TactileClaim& t : f->tactile_claims(s)) {
            ++claims;
            const double rise = printedDotHeightMm(t.top_z_mm, o.layer_mm) - printedDotHeightMm(t.base_z_mm, o.layer_mm);
            least = std::min(least, rise);
            const Vec3 at{t.x_mm, t.y_mm, t.top_z_mm};
            if (rise < t.min_rise_mm - 1e-9) {
                ++c.count;
                c.worst.push_back({at, rise, t.what + " rises " + formatFixed(t.top_z_mm - t.base_z_mm, 2) + " mm and prints " +
                                                 formatFixed(rise, 2) + " mm at " + layers + ", under the " +
                                                 formatFixed(t.min_rise_mm, 2) + " mm a reader finds (" + t.source + ")"});
            }
            const double min_width = std::max(t.min_width_mm, kMinDotBaseNozzles * o.nozzle_mm);
            if (t.width_mm < min_width - 1e-9) {
                ++c.count;
                c.worst.push_back({at, t.width_mm, t.what + " is " + formatFixed(t.width_mm, 2) + " mm across, under " +
                                                       formatFixed(min_width, 2) + " mm (" + t.source + ")"});
            }
        }
    }
    if (claims == 0) return;
    keepWorst(c.worst, o.max_offenders, /*smallest_first=*/true);
    c.status = c.count ? CheckStatus::Fail : CheckStatus::Pass;
    c.note = std::to_string(claims) + " places; the least rise printed " + formatFixed(least, 2) + " mm at " + layers;
    c.stage = "tactile_marks";
    r.checks.push_back(std::move(c));
}

}  // namespace

Check checkSlenderPillars(const Scene& scene, const TactileOptions& options) {
    TactileResult r;
    checkPillars(scene, options, r);
    return std::move(r.checks.front());
}

TactileResult checkLegibility(const Mesh& mesh, const Scene& scene, const TactileOptions& options) {
    TactileResult r;
    checkFingerReach(mesh, &scene, options, r);
    checkPillars(scene, options, r);
    return r;
}

TactileResult checkTactile(const Mesh& mesh, const Scene* scene, const TactileOptions& options) {
    TactileResult r;
    checkPointsAndEdges(mesh, options, r);
    checkFingerReach(mesh, scene, options, r);
    if (scene) {
        checkMarks(*scene, options, r);
        checkPillars(*scene, options, r);
        checkHeightSteps(*scene, options, r);
        r.checks.push_back(checkAttachmentJoints(*scene, kHandPushN, kPrintedPlaInterlayerMpa, options.max_offenders));
    }
    if (scene)
        for (const BrailleClaim& b : featureBraille(*scene)) checkBraille(b, options, r);
    if (scene) checkFeatureClaims(*scene, options, r);
    return r;
}

}  // namespace tsf
