#include "gen/model/features/scale.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <map>
#include <sstream>
#include <tuple>

#include "gen/util/error.h"
#include "gen/field/hex_grid.h"
#include "gen/model/feature.h"
#include "gen/model/scene.h"
#include "gen/model/features/foot_contacts.h"
#include "gen/model/features/top_shapes.h"
#include "gen/util/number_format.h"

namespace tsf {
namespace {

// A multiple of the step as the number a person would write (0.1 * 3 -> 0.3).
double roundedMultiple(int64_t k, double step) {
    const double v = double(k) * step;
    const double decimals = std::max(0.0, -std::floor(std::log10(step)) + 1);
    const double scale = std::pow(10.0, decimals);
    const double r = std::round(v * scale) / scale;
    return std::isfinite(r) ? r : v;
}

}  // namespace

std::vector<ScaleLevel> scaleLevels(const ValueMapping& m, double step, double z_snap_mm, int max_steps,
                                    std::string* error) {
    std::vector<ScaleLevel> levels;
    std::string why;
    const int64_t min_riser = std::max<int64_t>(1, snapUnits(kScaleMinRiserMm, z_snap_mm));
    if (!(step > 0) || !std::isfinite(step) || !(m.value_max > m.baseline)) {
        why = "the values have no range to measure";
    } else {
        // Multiples of the step above the baseline, up to value_max (with a
        // relative allowance for the rounding of k * step).
        const double first = std::floor(m.baseline / step) + 1;
        const double count = std::floor((m.value_max - m.baseline) / step) + 2;
        if (std::fabs(first) > 1e15) {
            why = "the step " + formatSignificant(step) + " is too small for values as large as " + formatSignificant(m.baseline);
        } else if (count > double(max_steps) * 4 + 8) {
            why = "the step " + formatSignificant(step) + " makes about " + formatSignificant(std::floor(count)) + " steps; at most " +
                  std::to_string(max_steps) + " fit";
        } else {
            int64_t previous = 0;
            for (int64_t k = int64_t(first);; ++k) {
                const double v = roundedMultiple(k, step);
                if (v <= m.baseline) continue;
                if (v > m.value_max + 1e-9 * std::fabs(step)) break;
                const int64_t h = snapUnits(m.heightMm(v), z_snap_mm);
                if (h - previous < min_riser) {
                    if (levels.empty()) continue;  // too close to the floor: the foot stands for the baseline
                    why = "the levels " + formatSignificant(levels.back().value) + " and " + formatSignificant(v) + " differ by " +
                          formatSignificant(double(h - previous) * z_snap_mm) + " mm in height, less than the " +
                          formatSignificant(kScaleMinRiserMm) + " mm a finger tells apart";
                    break;
                }
                levels.push_back({v, h});
                previous = h;
            }
            if (why.empty() && levels.empty()) why = "no multiple of " + formatSignificant(step) + " lies in the values' range";
            if (why.empty() && int(levels.size()) > max_steps)
                why = "the step " + formatSignificant(step) + " makes " + std::to_string(levels.size()) + " steps; at most " +
                      std::to_string(max_steps) + " fit";
        }
    }
    if (error) *error = why;
    return levels;
}

namespace {

// The next 1, 2 or 5 x 10^k above `step`.
double nextNiceStep(double step) {
    const double decade = std::pow(10.0, std::floor(std::log10(step) + 1e-9));
    for (const double mantissa : {1.0, 2.0, 5.0, 10.0}) {
        const double next = roundedMultiple(1, mantissa * decade);
        if (next > step * (1 + 1e-9)) return next;
    }
    return roundedMultiple(1, 10 * decade);
}

}  // namespace

std::optional<double> chooseScaleStep(const ValueMapping& m, double z_snap_mm) {
    if (!(m.value_max > m.baseline)) return std::nullopt;
    const double range = m.value_max - m.baseline;
    // The smallest nice step at or above range / kScaleMaxAutoSteps, then larger ones.
    double decade = std::pow(10.0, std::floor(std::log10(range / kScaleMaxAutoSteps)));
    for (int tries = 0; tries < 12; ++tries, decade *= 10)
        for (const double mantissa : {1.0, 2.0, 5.0}) {
            const double step = roundedMultiple(1, mantissa * decade);
            if (step < range / kScaleMaxAutoSteps * (1 - 1e-12)) continue;
            if (step > range) return std::nullopt;
            std::string why;
            scaleLevels(m, step, z_snap_mm, kScaleMaxAutoSteps, &why);
            if (why.empty()) return step;
        }
    return std::nullopt;
}

void placeScale(Scene& s) {
    const ScaleRequest* request = s.params.requests.get<ScaleRequest>();
    if (!request || s.keptCount() == 0) return;
    const ScaleRequest& rq = *request;
    if (s.params.bottom == Bottom::Mirrored)
        throw InputError("--scale: the tactile scale stands on the floor of a flat model; a mirrored model has none. "
                         "Leave out --mirror, or leave out --scale");
    if (!(s.mapping.value_max > s.mapping.baseline))
        throw InputError("--scale: every value maps to one height (a constant field, or value_max at the baseline): "
                         "there is nothing to measure. Leave out --scale");
    SceneScale sc;
    sc.step_given = rq.step.has_value();
    std::string why;
    if (rq.step) {
        if (!(*rq.step > 0) || !std::isfinite(*rq.step))
            throw InputError("--scale-step: must be a number > 0, got " + formatSignificant(*rq.step));
        sc.step = *rq.step;
        scaleLevels(s.mapping, sc.step, s.z_snap_mm, kScaleMaxSteps, &why);
        if (!why.empty()) {
            const std::optional<double> fits = chooseScaleStep(s.mapping, s.z_snap_mm);
            throw InputError("--scale-step " + formatSignificant(sc.step) + ": " + why +
                             (fits ? "; --scale-step " + formatSignificant(*fits) + " (or leaving it out) works" : std::string()));
        }
    } else {
        const std::optional<double> step = chooseScaleStep(s.mapping, s.z_snap_mm);
        if (!step)
            throw InputError("--scale: the values' whole range rises " +
                             formatSignificant(s.mapping.heightMm(s.mapping.value_max)) + " mm, too little for steps " +
                             formatSignificant(kScaleMinRiserMm) + " mm apart; give a larger --height, or leave out --scale");
        sc.step = *step;
    }
    // What the features placed before it claim (the legend's plate): the
    // staircase keeps kScaleClearanceMm clear of each.
    const std::vector<FootprintClaim>& claims = s.claims;
    // Places the staircase for `step` along the east side; false (with
    // `blocked` saying what is in the way and `need_mm` the run it needs)
    // when no run there is long enough.
    std::string blocked;
    double need_mm = 0;
    int n = 0;
    auto tryStep = [&](double step) -> bool {
        const std::vector<ScaleLevel> levels = scaleLevels(s.mapping, step, s.z_snap_mm, kScaleMaxSteps, &why);
        if (!why.empty() || levels.empty()) return false;
        n = int(levels.size());
        // The foot's west face stands on a lattice line i_col: first the
        // easternmost hexagon edge of the kept cells, then lines further
        // west, up to kScaleMaxSetbackCells cells (an irregular outline
        // whose east side is ragged). On line i_col, the cells with their east
        // edge on it are the candidate contacts; a run [j0, j1] is clear when
        // every kept cell beside it has its east edge on or west of the line,
        // every cell on the line is one a foot may touch, and two contacts
        // one notch apart have a cell in the notch the foot may touch too
        // (further apart, the foot's west face stands free between them).
        // Of all clear runs the one with the most contacts (the firmest
        // joint) is taken, the easternmost and southernmost of equals.
        // `blocked` says what cuts the runs on the easternmost line.
        struct Cell {
            int32_t kept;
            int64_t east;  // lattice i of its east edge
            int64_t j;     // its centre's lattice j; its east edge spans j - 1 .. j + 1, the hexagon j - 2 .. j + 2
        };
        std::vector<Cell> cells;
        int64_t i_east = INT64_MIN;
        for (size_t k = 0; k < s.keptCount(); ++k) {
            const LatticePoint c = hexCentre(s.grid, s.col[k], s.row[k]);
            cells.push_back({int32_t(k), c.i + 1, c.j});
            i_east = std::max(i_east, c.i + 1);
        }
        std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.j < b.j || (a.j == b.j && a.east < b.east); });
        const double unit_y_mm = latticeY({0, 1}, s.pitch_mm, s.y_scale);  // one lattice j step
        need_mm = n * kScaleTreadMm;
        const int64_t need_j = int64_t(std::ceil(need_mm / unit_y_mm - 1e-9));
        struct Run {
            int64_t i_col = 0, j0 = 0, j1 = 0;
            std::vector<int32_t> contacts, fillers;
        };
        std::optional<Run> best;
        for (int64_t i_col = i_east; i_col >= i_east - 2 * kScaleMaxSetbackCells; --i_col) {
            std::vector<const Cell*> cand;  // on the line, south to north
            for (const Cell& c : cells)
                if (c.east == i_col) cand.push_back(&c);
            auto inBand = [&](int64_t j) {
                for (const Cell* c : cand)
                    if (j >= c->j - 1 && j <= c->j + 1) return true;
                return false;
            };
            auto yOf = [&](int64_t j) { return s.point(LatticePoint{i_col, j}, 0).y; };
            for (const Cell* start : cand) {
                if (!footCanTouch(s, start->kept)) continue;
                const int64_t j0 = std::max<int64_t>(0, start->j - 3);  // the middle of the gap below it
                if (inBand(j0)) continue;
                int64_t j1 = j0 + need_j;
                while (inBand(j1)) ++j1;
                bool clear = true;
                Run run{i_col, j0, j1, {}, {}};
                for (const Cell& c : cells) {
                    // Beside the run, or touching its ends with a tip: east of the line it would touch the foot.
                    if (c.j + 2 < j0 || c.j - 2 > j1) continue;
                    if (c.east > i_col) {
                        clear = false;
                        if (i_col == i_east) blocked = "the model's outline";
                        break;
                    }
                    if (c.east < i_col || c.j - 1 < j0 || c.j + 1 > j1) continue;
                    if (!footCanTouch(s, c.kept)) {
                        clear = false;
                        if (i_col == i_east) blocked = "cells without data, under a mark or culled";
                        break;
                    }
                    if (!run.contacts.empty()) {
                        const int64_t previous_j = hexCentre(s.grid, s.col[size_t(run.contacts.back())], s.row[size_t(run.contacts.back())]).j;
                        int32_t filler = -1;  // further apart than one notch: no filler
                        if (c.j - previous_j == 6) {
                            filler = keptAtCentre(s, i_col - 2, previous_j + 3);
                            if (!footCanTouch(s, filler)) {
                                clear = false;
                                if (i_col == i_east) blocked = "cells without data, under a mark or culled";
                                break;
                            }
                        }
                        run.fillers.push_back(filler);
                    }
                    run.contacts.push_back(c.kept);
                }
                if (!clear || run.contacts.empty()) continue;
                const double x0 = s.point(LatticePoint{i_col, j0}, 0).x;
                if (const FootprintClaim* hit = firstClaimHit(
                        claims, BoxMm{x0, x0 + kScaleGapMm + kScaleStepWidthMm, yOf(j0), yOf(j1)}, kScaleClearanceMm)) {
                    if (i_col == i_east) blocked = hit->what;
                    continue;
                }
                if (!best || run.contacts.size() > best->contacts.size()) best = std::move(run);
            }
        }
        if (best) {
            const int64_t i_col = best->i_col, j0 = best->j0, j1 = best->j1;
            auto yOf = [&](int64_t j) { return s.point(LatticePoint{i_col, j}, 0).y; };
            std::vector<int32_t> contacts = std::move(best->contacts), fillers = std::move(best->fillers);
            const double y1 = yOf(j1);
            sc.x0_i = i_col;
            sc.y0_j = j0;
            sc.y1_j = j1;
            sc.x0_mm = s.point(LatticePoint{i_col, j0}, 0).x;
            sc.xs_mm = snapXy(sc.x0_mm + kScaleGapMm);
            sc.x1_mm = snapXy(sc.xs_mm + kScaleStepWidthMm);
            sc.y0_mm = yOf(j0);
            sc.y1_mm = y1;
            sc.foot_top_units = s.floor_units;
            for (int i = 0; i < n; ++i) {
                ScaleStep st;
                st.value = levels[size_t(i)].value;
                st.top_units = s.floor_units + levels[size_t(i)].height_units;
                st.y_south_mm = i == 0 ? sc.y0_mm : sc.steps.back().y_north_mm;
                st.y_north_mm = i + 1 == n ? sc.y1_mm : snapXy(sc.y0_mm + (sc.y1_mm - sc.y0_mm) * (i + 1) / n);
                sc.steps.push_back(st);
            }
            sc.step = step;
            sc.contacts = std::move(contacts);
            sc.fillers = std::move(fillers);
            s.features.set(std::move(sc));
            return true;
        }
        return false;
    };
    if (tryStep(sc.step)) return;
    // A step tsf chose grows (the next nice number: fewer, taller steps)
    // until the staircase fits the east side; a step given is kept, and the
    // larger steps are tried only to name one that fits.
    const double first_need = need_mm;
    const int first_n = n;
    const std::string first_blocked = blocked;
    std::optional<double> larger;  // a larger step whose staircase fits
    const double range = s.mapping.value_max - s.mapping.baseline;
    for (double step = nextNiceStep(sc.step); step <= range; step = nextNiceStep(step)) {
        // At least two steps: one is no staircase to measure by.
        std::string level_why;
        if (scaleLevels(s.mapping, step, s.z_snap_mm, kScaleMaxSteps, &level_why).size() < 2) break;
        blocked.clear();
        if (tryStep(step)) {
            larger = step;
            break;
        }
    }
    if (larger && !sc.step_given) {
        s.notes.push_back("--scale: steps of " + formatSignificant(*larger) + " (" + std::to_string(n) + ") rather than " +
                          formatSignificant(first_need / kScaleTreadMm, 3) +
                          " steps: the model's east side holds no longer run clear of " +
                          (first_blocked.empty() ? std::string("its shape") : first_blocked));
        return;
    }
    s.features.reset<SceneScale>();
    need_mm = first_need;
    n = first_n;
    blocked = first_blocked;
    std::string leave_out;  // what to leave out when a claim cuts the run
    for (const FootprintClaim& c : claims)
        if (c.what == blocked) leave_out = c.leave_out + " or ";
    const std::string what = "--scale: the tactile scale needs " + formatSignificant(std::round(need_mm)) + " mm (" +
                             std::to_string(n) + " steps of " + formatSignificant(kScaleTreadMm) +
                             " mm) along the model's east side, and the run there is cut by " +
                             (blocked.empty() ? std::string("the model's shape") : blocked);
    if (larger)  // a step given: name the larger one that was tried and fits
        throw InputError(what + ". --scale-step " + formatSignificant(*larger) + " fits (tried), or leave out --scale-step");
    // No step fits, down to two: a larger one cannot help.
    throw InputError(what + ", and so is the run for two steps (" + formatSignificant(2 * kScaleTreadMm) + " mm)" +
                     (sc.step_given ? ": no --scale-step fits" : "") + ". Leave out " +
                     leave_out + "--scale");
}

std::optional<int64_t> scaleTopAt(const Scene& s, double x, double y) {
    if (!sceneScale(s)) return std::nullopt;
    const SceneScale& sc = *sceneScale(s);
    if (x < sc.x0_mm || x > sc.x1_mm || y < sc.y0_mm || y > sc.y1_mm) return std::nullopt;
    if (x <= sc.xs_mm) return sc.foot_top_units;
    for (const ScaleStep& st : sc.steps)
        if (y <= st.y_north_mm) return st.top_units;
    return sc.steps.empty() ? sc.foot_top_units : sc.steps.back().top_units;
}

namespace {

// Builds the scale's closed surface. Columns of vertices: 0 = the west face
// (x0: the corners y0, every contact's two corners, y1), 1 = the steps' west
// face (xs), 2 = the east face (x1); 1 and 2 at y0, each step boundary, y1.
class ScaleBuilder {
public:
    ScaleBuilder(const Scene& s, bool joined) : s_(s), sc_(*sceneScale(s)), joined_(joined) {
        west_.push_back({sc_.y0_mm, -1});
        for (const int32_t k : sc_.contacts) {
            const size_t kk = size_t(k);
            for (int corner = 0; corner < 2; ++corner)  // lower-right, upper-right: south to north
                west_.push_back({s.point(hexCorner(s.grid, s.col[kk], s.row[kk], corner), 0).y,
                                 hexCornerId(s.grid, s.col[kk], s.row[kk], corner)});
        }
        west_.push_back({sc_.y1_mm, -1});
        ys_.push_back(sc_.y0_mm);
        for (const ScaleStep& st : sc_.steps) ys_.push_back(st.y_north_mm);
    }

    JoinedBody build() {
        const int64_t floor = sc_.foot_top_units;
        const size_t n = sc_.steps.size();
        // Bottom and the floor strip's top: the west column zipped with the steps' west column.
        zipPlane(0, /*up=*/false);
        zipPlane(floor, /*up=*/true);
        for (size_t i = 1; i <= n; ++i) {
            const int64_t z = top(i);
            quad(v(1, i - 1, 0), v(1, i, 0), v(2, i, 0), v(2, i - 1, 0));  // bottom, facing down
            quad(v(1, i - 1, z), v(2, i - 1, z), v(2, i, z), v(1, i, z));  // tread, facing up
            // The east face (outward +x) from 0 to the tread.
            wall(chain(2, i - 1, 0, z), chain(2, i, 0, z));
            // The steps' west face (outward -x) from the floor to the tread.
            wall(chain(1, i, floor, z), chain(1, i - 1, floor, z));
            // The riser up to the next step (outward -y).
            if (i < n) wall(chain(1, i, z, top(i + 1)), chain(2, i, z, top(i + 1)));
        }
        // South face (outward -y): the foot, then the first step.
        wall(westChain(0, 0, floor), chain(1, 0, 0, floor));
        wall(chain(1, 0, 0, top(1)), chain(2, 0, 0, top(1)));
        // North face (outward +y): the last step, then the foot.
        wall(chain(2, n, 0, top(n)), chain(1, n, 0, top(n)));
        wall(chain(1, n, 0, floor), westChain(west_.size() - 1, 0, floor));
        // West face (outward -x), north to south, but where it touches the
        // model (west_ is y0, then each contact's two corners, then y1).
        for (size_t a = west_.size() - 1; a > 0; --a) {
            const bool contact = a % 2 == 0 && a + 1 < west_.size();
            const bool notch = a % 2 == 1 && a >= 3 && a + 1 < west_.size() && sc_.fillers[(a - 3) / 2] >= 0;
            if (notch) {
                addNotch((a - 3) / 2, floor);
                continue;
            }
            if (contact && joined_) continue;
            wall(westChain(a, 0, floor), westChain(a - 1, 0, floor));
        }
        return std::move(body_);
    }

private:
    // The notch between contact n (0-based) and the next: A, D on the west
    // face (contact n's upper-right corner, the next one's lower-right), B
    // its top tip, C the next one's bottom tip; its walls are the model's.
    void addNotch(size_t n, int64_t floor) {
        const size_t a = 2 * n + 2, d = a + 1;
        const Scene& s = s_;
        auto corner = [&](int32_t k, int e, int64_t z) {
            const auto key = std::make_tuple(3 + e, size_t(k), z);
            const auto it = ids_.find(key);
            if (it != ids_.end()) return it->second;
            const uint32_t id = uint32_t(body_.mesh.positions.size());
            body_.mesh.positions.push_back(s.point(hexCorner(s.grid, s.col[size_t(k)], s.row[size_t(k)], e), z));
            body_.lattice_id.push_back(hexCornerId(s.grid, s.col[size_t(k)], s.row[size_t(k)], e));
            ids_[key] = id;
            return id;
        };
        const int32_t lower = sc_.contacts[n], upper = sc_.contacts[n + 1];
        for (const int64_t z : {int64_t(0), floor}) {
            const uint32_t A = v(0, a, z), D = v(0, d, z), B = corner(lower, 2, z), C = corner(upper, 5, z);
            if (z == floor) {
                tri(A, D, C);
                tri(A, C, B);
            } else {
                tri(A, C, D);
                tri(A, B, C);
            }
        }
        if (joined_) return;
        const Chain A{{0, v(0, a, 0)}, {floor, v(0, a, floor)}}, D{{0, v(0, d, 0)}, {floor, v(0, d, floor)}};
        const Chain B{{0, corner(lower, 2, 0)}, {floor, corner(lower, 2, floor)}};
        const Chain C{{0, corner(upper, 5, 0)}, {floor, corner(upper, 5, floor)}};
        wall(D, C);
        wall(C, B);
        wall(B, A);
    }

    struct WestPoint {
        double y_mm;
        int64_t lattice;  // -1: the scale's own corner
    };
    using Chain = std::vector<std::pair<int64_t, uint32_t>>;  // (z units, vertex) ascending

    int64_t top(size_t i) const { return sc_.steps[i - 1].top_units; }

    // Vertex of column col (0 west, 1 steps' west, 2 east) at point index i and height z.
    uint32_t v(int col, size_t i, int64_t z) {
        const auto key = std::make_tuple(col, i, z);
        const auto it = ids_.find(key);
        if (it != ids_.end()) return it->second;
        const uint32_t id = uint32_t(body_.mesh.positions.size());
        if (col == 0) {
            body_.mesh.positions.push_back({sc_.x0_mm, west_[i].y_mm, s_.zMm(z)});
            body_.lattice_id.push_back(west_[i].lattice);
        } else {
            body_.mesh.positions.push_back({col == 1 ? sc_.xs_mm : sc_.x1_mm, ys_[i], s_.zMm(z)});
            body_.lattice_id.push_back(-1);
        }
        ids_[key] = id;
        return id;
    }

    // The heights used at column col (1 or 2), point i: 0, the floor (column
    // 1), and the treads on either side.
    std::vector<int64_t> heights(int col, size_t i) const {
        std::vector<int64_t> z{0};
        if (col == 1) z.push_back(sc_.foot_top_units);
        if (i >= 1) z.push_back(top(i));
        if (i < sc_.steps.size()) z.push_back(top(i + 1));
        std::sort(z.begin(), z.end());
        z.erase(std::unique(z.begin(), z.end()), z.end());
        return z;
    }
    Chain chain(int col, size_t i, int64_t lo, int64_t hi) {
        Chain c;
        for (const int64_t z : heights(col, i))
            if (z >= lo && z <= hi) c.push_back({z, v(col, i, z)});
        return c;
    }
    Chain westChain(size_t a, int64_t lo, int64_t hi) { return {{lo, v(0, a, lo)}, {hi, v(0, a, hi)}}; }

    void tri(uint32_t a, uint32_t b, uint32_t c) { body_.mesh.triangles.push_back({a, b, c}); }
    void quad(uint32_t a, uint32_t b, uint32_t c, uint32_t d) {
        tri(a, b, c);
        tri(a, c, d);
    }

    // A vertical wall between chain l (at the start of the edge, seen with the
    // outside in front, l on the left) and chain r: the zipper of the direct
    // mesher, one point from each side per triangle, the lower next first.
    void wall(const Chain& l, const Chain& r) {
        size_t li = 0, ri = 0;
        while (li + 1 < l.size() || ri + 1 < r.size()) {
            const bool left = ri + 1 == r.size() || (li + 1 < l.size() && l[li + 1].first <= r[ri + 1].first);
            if (left) {
                tri(l[li].second, r[ri].second, l[li + 1].second);
                ++li;
            } else {
                tri(l[li].second, r[ri].second, r[ri + 1].second);
                ++ri;
            }
        }
    }

    // The horizontal strip [x0, xs] x [y0, y1] at height z: the west column
    // zipped with the steps' west column by y; up: facing +z.
    void zipPlane(int64_t z, bool up) {
        size_t a = 0, b = 0;
        const size_t na = west_.size(), nb = ys_.size();
        auto t = [&](uint32_t p, uint32_t q, uint32_t r) { up ? tri(p, q, r) : tri(p, r, q); };
        while (a + 1 < na || b + 1 < nb) {
            const bool west = b + 1 == nb || (a + 1 < na && west_[a + 1].y_mm <= ys_[b + 1]);
            if (west) {
                t(v(0, a, z), v(1, b, z), v(0, a + 1, z));
                ++a;
            } else {
                t(v(0, a, z), v(1, b, z), v(1, b + 1, z));
                ++b;
            }
        }
    }

    const Scene& s_;
    const SceneScale& sc_;
    const bool joined_;
    std::vector<WestPoint> west_;
    std::vector<double> ys_;
    std::map<std::tuple<int, size_t, int64_t>, uint32_t> ids_;
    JoinedBody body_;
};

}  // namespace

JoinedBody meshScaleBody(const Scene& s, bool joined) {
    if (!sceneScale(s) || sceneScale(s)->steps.empty()) return {};
    return ScaleBuilder(s, joined).build();
}

std::optional<BoxMm> scaleBoxMm(const Scene& s) {
    if (!sceneScale(s)) return std::nullopt;
    return BoxMm{sceneScale(s)->x0_mm, sceneScale(s)->x1_mm, sceneScale(s)->y0_mm, sceneScale(s)->y1_mm};
}

std::optional<Attachment> scaleAttachment(const Scene& s, Assembly assembly) {
    if (!sceneScale(s)) return std::nullopt;
    Attachment a;
    a.part = "scale";
    if (assembly == Assembly::Parts) {
        a.own_part = meshScaleBody(s, /*joined=*/false).mesh;  // touching the pillars' east walls
        return a;
    }
    const std::vector<int32_t>& c = sceneScale(s)->contacts;
    const auto cover = [&](int32_t k, int e) { a.walls.push_back({k, e, 0, s.floor_units}); };
    const std::vector<int32_t>& f = sceneScale(s)->fillers;  // -1: two contacts further apart than a notch
    for (size_t n = 0; n < c.size(); ++n) {
        cover(c[n], 0);
        if (n + 1 < c.size() && f[n] >= 0) cover(c[n], 1);
        if (n > 0 && f[n - 1] >= 0) cover(c[n], 5);
    }
    for (const int32_t k : f)
        if (k >= 0) cover(k, 0);
    a.joined = meshScaleBody(s, /*joined=*/true);
    return a;
}

ProbeSet scaleProbes(const Scene& s) {
    ProbeSet set{"scale", "every step of the tactile scale at its value's height", {}};
    if (!sceneScale(s)) return set;
    std::vector<SurfaceProbe>& out = set.probes;
    const SceneScale& sc = *sceneScale(s);
    out.push_back({"the scale's foot (the floor)", 0.5 * (sc.x0_mm + sc.xs_mm), 0.5 * (sc.y0_mm + sc.y1_mm),
                   false, s.zMm(sc.foot_top_units)});
    for (const ScaleStep& st : sc.steps)
        out.push_back({"the step for " + formatSignificant(st.value), 0.5 * (sc.xs_mm + sc.x1_mm),
                       0.5 * (st.y_south_mm + st.y_north_mm), false, s.zMm(st.top_units)});
    return set;
}

// The tactile scale as placeScale leaves it (gen/model/features/scale.h): what the mesher
// relies on to join it without a boolean operation.
void checkScale(const Scene& s) {
    if (!sceneScale(s)) return;
    const auto fail = [](const std::string& what) { throw InputError("scene: " + what); };
    const auto cellName = [&](size_t k) {
        return "cell (" + std::to_string(s.col[k]) + ", " + std::to_string(s.row[k]) + ")";
    };
    const SceneScale& sc = *sceneScale(s);
    if (s.params.bottom != Bottom::Flat) fail("scale: a tactile scale stands on a flat model only");
    if (sc.steps.empty()) fail("scale: no steps");
    if (sc.contacts.empty() || sc.fillers.size() + 1 != sc.contacts.size())
        fail("scale: it must touch at least one cell, with one filler between each two contacts");
    if (!(sc.x0_mm < sc.xs_mm && sc.xs_mm < sc.x1_mm && sc.y0_mm < sc.y1_mm)) fail("scale: its footprint is empty");
    if (sc.foot_top_units != s.floor_units) fail("scale: its foot's top must be the floor");
    int64_t below = sc.foot_top_units;
    double south = sc.y0_mm;
    for (const ScaleStep& st : sc.steps) {
        if (!(st.top_units > below)) fail("scale: every step must stand above the one before it (and the floor)");
        if (!(st.y_south_mm == south && st.y_north_mm > st.y_south_mm))
            fail("scale: the steps must follow one another from y0 northwards");
        below = st.top_units;
        south = st.y_north_mm;
    }
    if (south != sc.y1_mm) fail("scale: the last step must end at y1");
    for (size_t n = 0; n < sc.fillers.size(); ++n) {
        const auto centreJ = [&](int32_t k) { return hexCentre(s.grid, s.col[size_t(k)], s.row[size_t(k)]).j; };
        const int32_t lower = sc.contacts[n], upper = sc.contacts[n + 1];
        if (lower < 0 || upper < 0 || size_t(lower) >= s.keptCount() || size_t(upper) >= s.keptCount()) continue;  // below
        if ((sc.fillers[n] >= 0) != (centreJ(upper) - centreJ(lower) == 6))
            fail("scale: a filler must stand in the notch between two contacts one notch apart, and only there");
    }
    for (const std::vector<int32_t>* list : {&sc.contacts, &sc.fillers})
        for (const int32_t k : *list) {
            if (k == -1 && list == &sc.fillers) continue;  // contacts further apart: no notch to fill
            if (k < 0 || size_t(k) >= s.keptCount()) fail("scale: a touched cell is not a kept cell");
            for (int e = 0; e < kHexCorners; ++e)
                if (cornerTop(s, size_t(k), e) < s.floor_units)
                    fail("scale: " + cellName(size_t(k)) + " is below the floor where the foot touches it");
        }
    for (const int32_t k : sc.contacts)
        if (hexCentre(s.grid, s.col[size_t(k)], s.row[size_t(k)]).i + 1 != sc.x0_i)
            fail("scale: " + cellName(size_t(k)) + " does not touch the foot's west face");
}

const SceneScale* sceneScale(const Scene& s) { return s.features.get<SceneScale>(); }

}  // namespace tsf
