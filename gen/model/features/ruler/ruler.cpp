// The edge ruler: placement, body, read-back and checks. See ruler.h.
#include "gen/model/features/ruler/ruler.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "gen/field/hex_grid.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/error.h"
#include "gen/util/number_format.h"

namespace tsf {

const SceneRuler* sceneRuler(const Scene& s) { return s.features.get<SceneRuler>(); }

namespace {

struct Pt {
    double x = 0, y = 0;
};

std::vector<Pt> points(const std::vector<double>& xy) {
    std::vector<Pt> out;
    for (size_t k = 0; k + 1 < xy.size(); k += 2) out.push_back({xy[k], xy[k + 1]});
    return out;
}

Pt cornerMm(const Scene& s, size_t k, int e) {
    const Vec3 p = s.point(hexCorner(s.grid, s.col[k], s.row[k], e), 0);
    return {p.x, p.y};
}

std::vector<Pt> hexagonMm(const Scene& s, size_t k) {
    std::vector<Pt> out;
    for (int e = 0; e < kHexCorners; ++e) out.push_back(cornerMm(s, k, e));
    return out;
}

double segmentDistance(Pt a, Pt b, Pt c, Pt d) {
    const auto cross = [](Pt o, Pt p, Pt q) { return (p.x - o.x) * (q.y - o.y) - (p.y - o.y) * (q.x - o.x); };
    const double d1 = cross(c, d, a), d2 = cross(c, d, b), d3 = cross(a, b, c), d4 = cross(a, b, d);
    if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) return 0;
    const auto pointSeg = [](Pt p, Pt u, Pt v) {
        const double dx = v.x - u.x, dy = v.y - u.y, len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? std::clamp(((p.x - u.x) * dx + (p.y - u.y) * dy) / len2, 0.0, 1.0) : 0.0;
        return std::hypot(p.x - (u.x + t * dx), p.y - (u.y + t * dy));
    };
    return std::min({pointSeg(a, c, d), pointSeg(b, c, d), pointSeg(c, a, b), pointSeg(d, a, b)});
}

bool inside(const std::vector<Pt>& poly, Pt p) {
    bool in = false;
    for (size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++)
        if ((poly[i].y > p.y) != (poly[j].y > p.y) &&
            p.x < (poly[j].x - poly[i].x) * (p.y - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x)
            in = !in;
    return in;
}

// True when the two polygons overlap or come closer than gap_mm.
bool closerThan(const std::vector<Pt>& a, const std::vector<Pt>& b, double gap_mm) {
    for (size_t i = 0; i < a.size(); ++i)
        for (size_t j = 0; j < b.size(); ++j)
            if (segmentDistance(a[i], a[(i + 1) % a.size()], b[j], b[(j + 1) % b.size()]) < gap_mm) return true;
    return inside(a, b[0]) || inside(b, a[0]);
}

BoxMm boxOf(const std::vector<Pt>& poly) {
    BoxMm b{INFINITY, -INFINITY, INFINITY, -INFINITY};
    for (const Pt& p : poly) {
        b.x0 = std::min(b.x0, p.x);
        b.x1 = std::max(b.x1, p.x);
        b.y0 = std::min(b.y0, p.y);
        b.y1 = std::max(b.y1, p.y);
    }
    return b;
}

// The corners of pillar k a tooth stands against, in the tooth's
// counter-clockwise order (the pillar's own walls run the other way).
std::vector<int> contactCorners(bool south) { return south ? std::vector<int>{0, 5, 4} : std::vector<int>{4, 3}; }
// The pillar's walls it covers (hex_grid.h edges).
std::vector<int> contactEdges(bool south) { return south ? std::vector<int>{4, 5} : std::vector<int>{3}; }
// Neighbours that meet the tooth at one of those corners only: south, the
// pillars west and east in its row (a 60 degree corner between the tooth's
// side and their walls, which prints). West ones would leave a 30 degree
// slot narrower than a nozzle near the corner: a west tooth stands only
// against a pillar that sticks out west of the rows beside it.
std::vector<int> touchingNeighbours(bool south) { return south ? std::vector<int>{3, 0} : std::vector<int>{}; }
std::vector<int> freeNeighbours(bool south) { return south ? std::vector<int>{4, 5} : std::vector<int>{2, 3, 4}; }

// The tooth against pillar k, when it has room (see ruler.h); `placed` are
// the teeth placed before it.
std::optional<RulerTooth> toothAt(const Scene& s, int32_t k, bool south, const std::vector<RulerTooth>& placed) {
    const size_t kk = size_t(k);
    if (s.kind[kk] != CellKind::Data || (!s.drawn_by_face.empty() && s.drawn_by_face[kk])) return std::nullopt;
    for (const int e : freeNeighbours(south)) {
        int32_t nc, nr;
        hexNeighbour(s.col[kk], s.row[kk], e, nc, nr);
        if (s.keptAt(nc, nr) >= 0) return std::nullopt;  // inside the model, or in a notch of its outline
    }
    for (const int e : contactCorners(south))
        if (cornerTop(s, kk, e) < s.floor_units) return std::nullopt;  // a wall lower than the tooth
    std::vector<Pt> poly;
    for (const int e : contactCorners(south)) poly.push_back(cornerMm(s, kk, e));
    const double d = kRulerToothDepthMm;
    if (south) {
        const double y = snapXy(poly[1].y - d);  // below the tip
        poly.push_back({poly[2].x, y});
        poly.push_back({poly[0].x, y});
    } else {
        const double x = snapXy(poly[0].x - d);
        poly.push_back({x, poly[1].y});
        poly.push_back({x, poly[0].y});
    }
    const BoxMm box = boxOf(poly);
    if (firstClaimHit(s.claims, box, kRulerGapMm)) return std::nullopt;
    for (const RulerTooth& t : placed)
        if (closerThan(poly, points(t.xy), kRulerGapMm)) return std::nullopt;
    // Every other pillar near it keeps a slot that prints open.
    std::vector<int32_t> allowed{k};
    for (const int e : touchingNeighbours(south)) {
        int32_t nc, nr;
        hexNeighbour(s.col[kk], s.row[kk], e, nc, nr);
        allowed.push_back(s.keptAt(nc, nr));
    }
    for (int32_t r = s.row[kk] - 3; r <= s.row[kk] + 3; ++r)
        for (int32_t c = s.col[kk] - 3; c <= s.col[kk] + 3; ++c) {
            const int32_t other = s.grid.contains(c, r) ? s.keptAt(c, r) : -1;
            if (other < 0 || std::find(allowed.begin(), allowed.end(), other) != allowed.end()) continue;
            if (closerThan(poly, hexagonMm(s, size_t(other)), kRulerGapMm)) return std::nullopt;
        }
    // The ridge: the outer part of the footprint, kRulerCollarMm clear of
    // the pillar (south: of its bottom tip; west: of its west wall).
    const size_t n = poly.size();
    const Pt qa = poly[n - 2], qb = poly[n - 1];
    std::vector<Pt> ridge;
    if (south) {
        const double y = snapXy(poly[1].y - kRulerCollarMm);
        ridge = {{qa.x, y}, qa, qb, {qb.x, y}};
    } else {
        const double x = snapXy(poly[0].x - kRulerCollarMm);
        ridge = {{x, qa.y}, qa, qb, {x, qb.y}};
    }
    RulerTooth t;
    for (const Pt& p : ridge) {
        t.ridge.push_back(p.x);
        t.ridge.push_back(p.y);
    }
    t.south = south;
    t.kept = k;
    t.col = s.col[kk];
    t.row = s.row[kk];
    for (const Pt& p : poly) {
        t.xy.push_back(p.x);
        t.xy.push_back(p.y);
    }
    return t;
}

}  // namespace

void placeRuler(Scene& s) {
    const RulerRequest* rq = s.params.requests.get<RulerRequest>();
    if (!rq || s.keptCount() == 0) return;
    if (s.params.bottom == Bottom::Mirrored)
        throw InputError("--ruler: the ruler's teeth stand on the bed beside a flat model; a mirrored model has no "
                         "floor for them. Leave out --mirror, or leave out --ruler");
    if (rq->every && *rq->every < 2)
        throw InputError("--ruler " + std::to_string(*rq->every) +
                         ": at least 2 (teeth on neighbouring pillars would touch); leave out the number for teeth " +
                         formatSignificant(kRulerSpacingMm) + " mm apart");
    SceneRuler r;
    const double row_mm = 3 * latticeY({0, 1}, s.pitch_mm, s.y_scale);  // rows are 3 lattice j apart
    const auto every = [&](double apart_mm) {
        return rq->every ? *rq->every : std::max(2, int(std::ceil(kRulerSpacingMm / apart_mm - 1e-9)));
    };
    r.every_given = rq->every.has_value();
    r.every_x = every(s.pitch_mm);
    // Rows alternate east and west by half a cell: an even count keeps every
    // west line on rows that stick out west (a west tooth stands only there).
    r.every_y = every(row_mm);
    if (!rq->every) r.every_y += r.every_y % 2;
    r.spacing_x_mm = r.every_x * s.pitch_mm;
    r.spacing_y_mm = r.every_y * row_mm;
    r.top_units = s.floor_units + std::max<int64_t>(1, snapUnits(kRulerToothRiseMm, s.z_snap_mm));

    // The south-west pillar: the westernmost of the southernmost row (row 0 is north).
    int32_t south_row = -1, south_col = 0, north_row = std::numeric_limits<int32_t>::max();
    int64_t i_min = std::numeric_limits<int64_t>::max(), i_max = std::numeric_limits<int64_t>::min();
    for (size_t k = 0; k < s.keptCount(); ++k) {
        if (s.row[k] > south_row || (s.row[k] == south_row && s.col[k] < south_col)) {
            south_row = s.row[k];
            south_col = s.col[k];
        }
        north_row = std::min(north_row, s.row[k]);
        const int64_t i = hexCentre(s.grid, s.col[k], s.row[k]).i;
        i_min = std::min(i_min, i);
        i_max = std::max(i_max, i);
    }
    const int64_t i0 = hexCentre(s.grid, south_col, south_row).i;
    const int64_t step_i = 2 * int64_t(r.every_x);  // centres of a row are 2 lattice i apart
    // South: every line through a centre, west to east.
    for (int64_t line = -((i0 - i_min) / step_i); i0 + line * step_i <= i_max; ++line) {
        const int64_t i = i0 + line * step_i;
        ++r.lines_x;
        for (int32_t row = south_row; row >= north_row; --row) {
            const int64_t offset = i - hexCentre(s.grid, 0, row).i;
            if (offset % 2 != 0) continue;
            const int32_t k = s.grid.contains(int32_t(offset / 2), row) ? s.keptAt(int32_t(offset / 2), row) : -1;
            if (k < 0) continue;
            if (std::optional<RulerTooth> t = toothAt(s, k, /*south=*/true, r.teeth)) {
                t->ordinal = int32_t(line);
                r.teeth.push_back(std::move(*t));
            }
            break;  // the southernmost pillar on the line, with room or not
        }
    }
    // West: every every_y-th row, south to north, from the southernmost
    // row whose westernmost pillar sticks out west of the rows beside it.
    const auto westernmost = [&](int32_t row) {
        int32_t k = -1;
        for (int32_t c = 0; c < s.grid.cols && k < 0; ++c) k = s.keptAt(c, row);
        return k;
    };
    int32_t west_row = south_row;
    for (int32_t row = south_row; row >= north_row; --row) {
        const int32_t k = westernmost(row);
        if (k >= 0 && s.keptNeighbour(size_t(k), 2) < 0 && s.keptNeighbour(size_t(k), 4) < 0) {
            west_row = row;
            break;
        }
    }
    for (int32_t row = west_row, line = 0; row >= north_row; row -= r.every_y, ++line) {
        ++r.lines_y;
        const int32_t west = westernmost(row);
        if (west < 0) continue;
        if (std::optional<RulerTooth> t = toothAt(s, west, /*south=*/false, r.teeth)) {
            t->ordinal = line;
            r.teeth.push_back(std::move(*t));
        }
    }
    const auto count = [&](bool south) {
        return std::count_if(r.teeth.begin(), r.teeth.end(), [&](const RulerTooth& t) { return t.south == south; });
    };
    if (count(true) == 0 && count(false) == 0)
        throw InputError("--ruler: no tooth has room along the south or west edge (each needs a pillar rising to the "
                         "floor with " + formatSignificant(kRulerGapMm) + " mm clear around it, away from the "
                         "orientation tab and the legend). Leave out --ruler");
    for (const bool south : {true, false})
        if (count(south) < 2)
            s.notes.push_back(std::string("the ruler has ") + (count(south) ? "one tooth" : "no tooth") + " on the " +
                              (south ? "south" : "west") + " edge: the pillars there leave no room (the key says which "
                              "it has)");
    s.features.set(std::move(r));
}

JoinedBody meshRulerBody(const Scene& s, bool joined) {
    JoinedBody body;
    const SceneRuler* r = sceneRuler(s);
    if (!r) return body;
    const int64_t floor = s.floor_units, top = r->top_units;
    std::vector<Vec3>& pos = body.mesh.positions;
    const auto tri = [&](uint32_t a, uint32_t b, uint32_t c) { body.mesh.triangles.push_back({a, b, c}); };
    for (const RulerTooth& t : r->teeth) {
        // Footprint p0 .. p(n-1), counter-clockwise: the pillar's corners
        // p0 .. p(c-1), then the outer corners qa = p(n-2), qb = p(n-1);
        // the ridge ra (on the side p(c-1) -> qa), qa, qb, rb (on qb -> p0).
        const std::vector<Pt> poly = points(t.xy), ridge = points(t.ridge);
        const std::vector<int> corners = contactCorners(t.south);
        const uint32_t n = uint32_t(poly.size()), c = uint32_t(corners.size());
        const auto add = [&](Pt p, int64_t z, int64_t lattice) {
            pos.push_back({p.x, p.y, s.zMm(z)});
            body.lattice_id.push_back(lattice);
            return uint32_t(pos.size() - 1);
        };
        std::vector<uint32_t> lo(n), mid(n);
        for (uint32_t v = 0; v < n; ++v) {
            const int64_t lattice = v < c ? hexCornerId(s.grid, t.col, t.row, corners[v]) : -1;
            lo[v] = add(poly[v], 0, lattice);
            if (v < c) mid[v] = add(poly[v], floor, lattice);
        }
        const uint32_t ra_f = add(ridge[0], floor, -1), rb_f = add(ridge[3], floor, -1);
        const uint32_t ra_t = add(ridge[0], top, -1), qa_t = add(ridge[1], top, -1), qb_t = add(ridge[2], top, -1),
                       rb_t = add(ridge[3], top, -1);
        const uint32_t qa = lo[n - 2], qb = lo[n - 1];
        // Bottom: a fan from the second corner, which sees the whole
        // footprint (the bottom tip, or a corner of the rectangle).
        for (uint32_t v = 2; v < n; ++v) tri(lo[1], lo[(v + 1) % n], lo[v]);
        // The collar's top at the floor: the pillar's corners, then the ridge's inner edge.
        std::vector<uint32_t> collar(mid.begin(), mid.begin() + c);
        collar.push_back(ra_f);
        collar.push_back(rb_f);
        for (size_t v = 2; v < collar.size(); ++v) tri(collar[1], collar[v], collar[(v + 1) % collar.size()]);
        // The ridge's top.
        tri(ra_t, qa_t, qb_t);
        tri(ra_t, qb_t, rb_t);
        // Where it stands against the pillar: none when joined (the
        // pillar's wall gives way there), else the collar's face.
        if (!joined)
            for (uint32_t v = 0; v + 1 < c; ++v) {
                tri(lo[v], lo[v + 1], mid[v + 1]);
                tri(lo[v], mid[v + 1], mid[v]);
            }
        // The side from the pillar to qa: an L (the collar to the floor, the
        // ridge to its top), fanned from qa at the bed, which sees all of it.
        tri(qa, qa_t, ra_t);
        tri(qa, ra_t, ra_f);
        tri(qa, ra_f, mid[c - 1]);
        tri(qa, mid[c - 1], lo[c - 1]);
        // The outer face, from the bed to the ridge's top.
        tri(qa, qb, qb_t);
        tri(qa, qb_t, qa_t);
        // The side from qb back to the pillar, fanned from qb at the bed.
        tri(qb, lo[0], mid[0]);
        tri(qb, mid[0], rb_f);
        tri(qb, rb_f, rb_t);
        tri(qb, rb_t, qb_t);
        // The ridge's inner face, towards the pillar.
        tri(rb_f, ra_f, ra_t);
        tri(rb_f, ra_t, rb_t);
    }
    return body;
}

std::optional<Attachment> rulerAttachment(const Scene& s, Assembly assembly) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return std::nullopt;
    Attachment a;
    a.part = "ruler";
    if (assembly == Assembly::Parts) {
        a.own_part = meshRulerBody(s, /*joined=*/false).mesh;
        return a;
    }
    for (const RulerTooth& t : r->teeth)
        for (const int e : contactEdges(t.south)) a.walls.push_back({t.kept, e, 0, s.floor_units});
    a.joined = meshRulerBody(s, /*joined=*/true);
    return a;
}

std::optional<BoxMm> rulerBoxMm(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r || r->teeth.empty()) return std::nullopt;
    std::vector<Pt> all;
    for (const RulerTooth& t : r->teeth)
        for (const Pt& p : points(t.xy)) all.push_back(p);
    return boxOf(all);
}

std::optional<int64_t> rulerTopAt(const Scene& s, double x, double y) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return std::nullopt;
    for (const RulerTooth& t : r->teeth) {
        const std::vector<Pt> poly = points(t.xy);
        const BoxMm b = boxOf(poly);
        if (x < b.x0 || x > b.x1 || y < b.y0 || y > b.y1) continue;
        // On the rim counts: a read-back sample on an edge sees the top.
        const auto within = [&](const std::vector<Pt>& q) {
            if (inside(q, {x, y})) return true;
            for (size_t i = 0; i < q.size(); ++i)
                if (segmentDistance({x, y}, {x, y}, q[i], q[(i + 1) % q.size()]) < 1e-9) return true;
            return false;
        };
        if (within(points(t.ridge))) return r->top_units;
        if (within(poly)) return s.floor_units;
    }
    return std::nullopt;
}

ProbeSet rulerProbes(const Scene& s) {
    ProbeSet set{"ruler", "every tooth of the edge ruler: its ridge and its collar", {}};
    const SceneRuler* r = sceneRuler(s);
    if (!r) return set;
    for (const RulerTooth& t : r->teeth) {
        const std::vector<Pt> p = points(t.xy), ridge = points(t.ridge);
        const std::string what = std::string(t.south ? "the south" : "the west") + " tooth of " +
                                 (t.south ? "column " + std::to_string(t.col) : "row " + std::to_string(t.row));
        // The ridge's middle, and the collar half way from the pillar to it
        // (south: below the tip; west: beside the wall's middle).
        set.probes.push_back({what + ", its ridge", 0.25 * (ridge[0].x + ridge[1].x + ridge[2].x + ridge[3].x),
                              0.25 * (ridge[0].y + ridge[1].y + ridge[2].y + ridge[3].y), false, s.zMm(r->top_units)});
        const Pt collar = t.south ? Pt{p[1].x, 0.5 * (p[1].y + ridge[0].y)}
                                  : Pt{0.5 * (p[0].x + ridge[0].x), 0.5 * (p[0].y + p[1].y)};
        set.probes.push_back({what + ", its collar", collar.x, collar.y, false, s.zMm(s.floor_units)});
    }
    return set;
}

void checkRuler(const Scene& s) {
    const SceneRuler* r = sceneRuler(s);
    if (!r) return;
    const auto fail = [](const std::string& what) { throw InputError("scene: ruler: " + what); };
    if (s.params.bottom != Bottom::Flat) fail("the teeth stand on a flat model only");
    if (!(r->top_units > s.floor_units)) fail("the ridges must stand above the floor");
    if (r->teeth.empty()) fail("no teeth");
    for (const RulerTooth& t : r->teeth) {
        if (t.kept < 0 || size_t(t.kept) >= s.keptCount()) fail("a tooth stands against a cell that is not kept");
        const size_t k = size_t(t.kept);
        if (s.col[k] != t.col || s.row[k] != t.row) fail("a tooth names another cell than the one it stands against");
        const std::vector<int> corners = contactCorners(t.south);
        if (t.xy.size() != 2 * (corners.size() + 2)) fail("a tooth's footprint has the wrong number of corners");
        if (t.ridge.size() != 8) fail("a tooth's ridge must have four corners");
        const std::vector<Pt> p = points(t.xy);
        for (size_t v = 0; v < corners.size(); ++v) {
            const Pt c = cornerMm(s, k, corners[v]);
            if (p[v].x != c.x || p[v].y != c.y) fail("a tooth does not meet its pillar at the pillar's corners");
            if (cornerTop(s, k, corners[v]) < s.floor_units) fail("a tooth's collar rises above the wall it stands against");
        }
        for (const int e : freeNeighbours(t.south))
            if (s.keptNeighbour(k, e) >= 0) fail("a tooth stands against a wall inside the model or in a notch");
    }
}

}  // namespace tsf
