// ColumnGrid: footprints row by row, a counting build, pairs in their first
// common column, rays by a grid walk. See column_grid.h.
#include "verify/column_grid.h"

#include <algorithm>
#include <array>
#include <atomic>
#include <chrono>
#include <cmath>
#include <exception>
#include <stdexcept>

#include "verify/detail/ray_triangle.h"
#include "gen/util/workers.h"

namespace tsf {
namespace {

using detail::V3;

constexpr uint32_t kNone = UINT32_MAX;
constexpr double kInf = std::numeric_limits<double>::infinity();
// At most this many columns a side: a grid of 4096 x 4096 is 64 MB of
// column starts; finer columns would hold less than a triangle each on any
// model the verifier can hold.
constexpr int32_t kMaxSide = 4096;
// Footprints are widened by this share of the model's size (see the header).
constexpr double kMarginShare = 1e-6;
// A triangle whose box meets at most this many columns is listed in all of
// them (a footprint, cheaper to find, and a pair's first common column is
// then found from the two boxes alone); a larger one only in the columns its
// shadow meets, row by row (the long thin triangles of a flat bottom).
constexpr int64_t kBoxedColumns = 16;
// Columns a side of a block (see block_z_).
constexpr int32_t kBlockColumns = 8;
// Columns a worker takes at a time in the pair walk.
constexpr uint32_t kColumnsPerTask = 256;

bool finite(const Vec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The nearest float at or below (above) d: a float range holds the double one.
float floatDown(double d) {
    if (d < -double(std::numeric_limits<float>::max())) return -std::numeric_limits<float>::infinity();
    float f = float(d);
    if (double(f) > d) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float floatUp(double d) {
    if (d > double(std::numeric_limits<float>::max())) return std::numeric_limits<float>::infinity();
    float f = float(d);
    if (double(f) < d) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct Box3 {
    double lo[3], hi[3];
};

}  // namespace

int32_t ColumnGrid::binX(double x) const {
    const double u = (x - x0_) * inv_x_;  // monotone in x: so is the column
    if (!(u > 0)) return 0;
    return u >= double(nx_) ? nx_ - 1 : int32_t(u);
}

int32_t ColumnGrid::binY(double y) const {
    const double u = (y - y0_) * inv_y_;
    if (!(u > 0)) return 0;
    return u >= double(ny_) ? ny_ - 1 : int32_t(u);
}

void ColumnGrid::rowRange(uint32_t t, int32_t& r0, int32_t& r1) const {
    const auto& q = triangles_[t];
    const double lo = std::min({positions_[q[0]].y, positions_[q[1]].y, positions_[q[2]].y});
    const double hi = std::max({positions_[q[0]].y, positions_[q[1]].y, positions_[q[2]].y});
    r0 = binY(lo - margin_);
    r1 = binY(hi + margin_);
}

bool ColumnGrid::span(uint32_t t, int32_t r, int32_t& c0, int32_t& c1) const {
    // The triangle's part in row r's band, widened by the margin: its x range
    // comes from the corners inside the band and the edges' crossings of the
    // band's two lines. A crossing is computed only for an edge that spans
    // more than the margin in y there, where its rounding is far below the
    // margin; a flatter edge's crossing lies between its ends, one of which
    // is in the band or the edge does not reach the needed part of it.
    const auto& q = triangles_[t];
    const Vec3* p[3] = {&positions_[q[0]], &positions_[q[1]], &positions_[q[2]]};
    // A small triangle (most of them) takes the columns of its box.
    const BoxColumns box = boxColumns(t);
    if (box.boxed) {
        c0 = box.c0;
        c1 = box.c1;
        return true;
    }
    const double lo = r == 0 ? -kInf : y0_ + double(r) * step_y_ - margin_;
    const double hi = r == ny_ - 1 ? kInf : y0_ + double(r + 1) * step_y_ + margin_;
    double x_lo = kInf, x_hi = -kInf;
    for (int i = 0; i < 3; ++i)
        if (p[i]->y >= lo && p[i]->y <= hi) {
            x_lo = std::min(x_lo, p[i]->x);
            x_hi = std::max(x_hi, p[i]->x);
        }
    for (int i = 0; i < 3; ++i) {
        const Vec3 &a = *p[i], &b = *p[(i + 1) % 3];
        for (const double line : {lo, hi}) {
            if (!std::isfinite(line) || !((a.y < line && b.y > line) || (a.y > line && b.y < line))) continue;
            const double s = std::clamp((line - a.y) / (b.y - a.y), 0.0, 1.0);
            const double x = a.x + s * (b.x - a.x);
            x_lo = std::min(x_lo, x);
            x_hi = std::max(x_hi, x);
        }
    }
    if (x_lo > x_hi) return false;
    c0 = binX(x_lo - margin_);
    c1 = binX(x_hi + margin_);
    return true;
}

ColumnGrid::ColumnGrid(const Mesh& mesh, double triangles_per_column, Rays rays) : rays_(rays) {
    const auto t0 = std::chrono::steady_clock::now();
    positions_ = mesh.positions.data();
    triangles_ = mesh.triangles.data();
    const size_t nv = mesh.positions.size(), nt = mesh.triangles.size();
    // Sized, not filled: the pass below writes every element, on the threads.
    first_bin_.resize(nt);
    z_range_.resize(nt);
    UninitializedVector<uint8_t> usable(nt);
    const unsigned workers = nt < 20000 ? 1u : detail::workerCount(0);
    auto forWorkers = [&](const auto& fn) { detail::runOnWorkers(workers, [&](unsigned w, const auto&) { fn(w); }); };
    // The usable triangles, their z ranges and the box of x, y, on the
    // worker threads (a contiguous range of triangles each).
    struct Extent {
        double x_min = kInf, x_max = -kInf, y_min = kInf, y_max = -kInf;
        size_t listed = 0;
    };
    std::vector<Extent> extents(workers);
    forWorkers([&](unsigned w) {
        Extent& e = extents[w];
        for (size_t t = nt * w / workers; t < nt * (w + 1) / workers; ++t) {
            const auto& q = mesh.triangles[t];
            first_bin_[t] = kNone;
            usable[t] = 0;
            z_range_[t] = {0.0f, 0.0f};
            if (q[0] >= nv || q[1] >= nv || q[2] >= nv) continue;
            if (!finite(mesh.positions[q[0]]) || !finite(mesh.positions[q[1]]) || !finite(mesh.positions[q[2]])) continue;
            usable[t] = 1;
            ++e.listed;
            const double z_lo = std::min({mesh.positions[q[0]].z, mesh.positions[q[1]].z, mesh.positions[q[2]].z});
            const double z_hi = std::max({mesh.positions[q[0]].z, mesh.positions[q[1]].z, mesh.positions[q[2]].z});
            z_range_[t] = {floatDown(z_lo), floatUp(z_hi)};
            for (int i = 0; i < 3; ++i) {
                const Vec3& v = mesh.positions[q[i]];
                e.x_min = std::min(e.x_min, v.x);
                e.x_max = std::max(e.x_max, v.x);
                e.y_min = std::min(e.y_min, v.y);
                e.y_max = std::max(e.y_max, v.y);
            }
        }
    });
    double x_min = kInf, x_max = -kInf, y_min = kInf, y_max = -kInf;
    for (const Extent& e : extents) {
        x_min = std::min(x_min, e.x_min);
        x_max = std::max(x_max, e.x_max);
        y_min = std::min(y_min, e.y_min);
        y_max = std::max(y_max, e.y_max);
        listed_ += e.listed;
    }
    if (listed_ == 0) {
        start_.assign(1, 0);
        build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        return;
    }
    const double w = x_max - x_min, d = y_max - y_min;
    const double size = std::max({w, d, std::fabs(x_min), std::fabs(x_max), std::fabs(y_min), std::fabs(y_max), 1.0});
    margin_ = kMarginShare * size;
    // Square columns, about triangles_per_column triangles each on average.
    const double wanted = std::max(1.0, double(listed_) / std::max(0.5, triangles_per_column));
    const double side = w > 0 && d > 0 ? std::sqrt(w * d / wanted) : std::max(w, d) / wanted;
    auto count = [&](double extent) {
        if (!(side > 0) || !(extent > 0)) return int32_t(1);
        return int32_t(std::clamp(std::ceil(extent / side), 1.0, double(kMaxSide)));
    };
    nx_ = count(w);
    ny_ = count(d);
    x0_ = x_min;
    y0_ = y_min;
    step_x_ = w > 0 ? w / nx_ : 1.0;
    step_y_ = d > 0 ? d / ny_ : 1.0;
    inv_x_ = 1.0 / step_x_;
    inv_y_ = 1.0 / step_y_;

    // Two passes over the footprints, each on the verifier's threads (a
    // contiguous range of triangles each): count per column, then fill. Each
    // column lists its walls first (two corners over one point), then its
    // other sloped or vertical triangles, then its flat ones (every corner at
    // one z): no vertical ray can hit a wall, no horizontal one a flat
    // triangle (see firstHit). Each part in ascending triangle order, as one
    // thread would list them.
    const size_t columns = size_t(nx_) * size_t(ny_);
    // Per worker and part (0 wall, 1 other, 2 flat): a count per column,
    // then where that worker's next entry of that part goes.
    constexpr int kParts = 3;
    std::vector<std::array<std::vector<uint32_t>, kParts>> at(workers);
    std::vector<uint8_t> part_of(nt, 0);
    auto forFootprint = [&](uint32_t t, const auto& fn) {
        int32_t r0, r1;
        rowRange(t, r0, r1);
        for (int32_t r = r0; r <= r1; ++r) {
            int32_t c0, c1;
            if (!span(t, r, c0, c1)) continue;
            const size_t row = size_t(r) * size_t(nx_);
            fn(row + size_t(c0), row + size_t(c1));
        }
    };
    forWorkers([&](unsigned w) {
        for (auto& count : at[w]) count.assign(columns, 0);
        for (size_t t = nt * w / workers; t < nt * (w + 1) / workers; ++t) {
            if (!usable[t]) continue;
            part_of[t] = z_range_[t][0] == z_range_[t][1] && isFlat(uint32_t(t)) ? 2 : isWall(uint32_t(t)) ? 0 : 1;
            if (part_of[t] == 0 && rays_ == Rays::Vertical) {
                usable[t] = 0;  // a wall: no vertical ray meets it
                continue;
            }
            std::vector<uint32_t>& count = at[w][part_of[t]];
            forFootprint(uint32_t(t), [&](size_t first, size_t last) {
                if (first_bin_[t] == kNone) first_bin_[t] = uint32_t(first);
                for (size_t bin = first; bin <= last; ++bin) ++count[bin];
            });
        }
    });
    start_.assign(columns + 1, 0);
    flat_start_.assign(columns, 0);
    other_start_.assign(columns, 0);
    uint64_t total = 0;
    for (size_t bin = 0; bin < columns; ++bin) {
        start_[bin] = uint32_t(total);
        for (int part = 0; part < kParts; ++part) {
            if (part == 1) other_start_[bin] = uint32_t(total);
            if (part == 2) flat_start_[bin] = uint32_t(total);
            for (unsigned w = 0; w < workers; ++w) {
                const uint32_t n = at[w][part][bin];
                at[w][part][bin] = uint32_t(total);
                total += n;
            }
        }
        if (total > UINT32_MAX) throw std::length_error("the column grid would list more than 2^32 triangles");
    }
    start_[columns] = uint32_t(total);
    entries_.resize(total);
    forWorkers([&](unsigned w) {
        for (size_t t = nt * w / workers; t < nt * (w + 1) / workers; ++t) {
            if (!usable[t]) continue;
            std::vector<uint32_t>& next = at[w][part_of[t]];
            forFootprint(uint32_t(t), [&](size_t first, size_t last) {
                for (size_t bin = first; bin <= last; ++bin) entries_[next[bin]++] = uint32_t(t);
            });
        }
    });
    std::vector<std::array<std::vector<uint32_t>, kParts>>().swap(at);
    // Each column's range of z over its sloped and vertical triangles, and
    // over all of them: a ray whose z over the column misses it skips the
    // column at once (inside a solid, a horizontal ray passes under every
    // wall between the tops above it).
    constexpr float kFloatInf = std::numeric_limits<float>::infinity();
    const std::array<float, 2> nothing{kFloatInf, -kFloatInf};
    column_z_.assign(columns, std::array<std::array<float, 2>, 2>{nothing, nothing});
    detail::runOnRanges(workers, columns, [&](unsigned, size_t from, size_t to) {
        for (size_t bin = from; bin < to; ++bin)
            for (uint32_t e = start_[bin]; e < start_[bin + 1]; ++e) {
                const auto& zr = z_range_[entries_[e]];
                for (int part = e < flat_start_[bin] ? 0 : 1; part < 2; ++part) {
                    column_z_[bin][part][0] = std::min(column_z_[bin][part][0], zr[0]);
                    column_z_[bin][part][1] = std::max(column_z_[bin][part][1], zr[1]);
                }
            }
    });
    // Blocks of kBlockColumns x kBlockColumns columns keep the range of z of
    // their columns' non-flat triangles: a horizontal ray at a z outside it
    // steps through the block without reading a column (through the air
    // over a model, a cache miss a column).
    block_nx_ = (nx_ + kBlockColumns - 1) / kBlockColumns;
    const int32_t block_ny = (ny_ + kBlockColumns - 1) / kBlockColumns;
    block_z_.assign(size_t(block_nx_) * size_t(block_ny), nothing);
    for (int32_t r = 0; r < ny_; ++r)
        for (int32_t c = 0; c < nx_; ++c) {
            auto& b = block_z_[size_t(r / kBlockColumns) * size_t(block_nx_) + size_t(c / kBlockColumns)];
            const auto& z = column_z_[size_t(r) * size_t(nx_) + size_t(c)][0];
            b[0] = std::min(b[0], z[0]);
            b[1] = std::max(b[1], z[1]);
        }
    build_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

bool ColumnGrid::isWall(uint32_t t) const {
    const auto& q = triangles_[t];
    const Vec3 &a = positions_[q[0]], &b = positions_[q[1]], &c = positions_[q[2]];
    auto over = [](const Vec3& u, const Vec3& v) { return u.x == v.x && u.y == v.y; };
    return over(a, b) || over(b, c) || over(c, a);
}

bool ColumnGrid::isFlat(uint32_t t) const {
    const auto& q = triangles_[t];
    return positions_[q[0]].z == positions_[q[1]].z && positions_[q[1]].z == positions_[q[2]].z;
}

ColumnGrid::BoxColumns ColumnGrid::boxColumns(double x_lo, double x_hi, double y_lo, double y_hi) const {
    BoxColumns b;
    b.c0 = binX(x_lo - margin_);
    b.c1 = binX(x_hi + margin_);
    b.r0 = binY(y_lo - margin_);
    b.r1 = binY(y_hi + margin_);
    b.boxed = int64_t(b.c1 - b.c0 + 1) * int64_t(b.r1 - b.r0 + 1) <= kBoxedColumns;
    return b;
}

ColumnGrid::BoxColumns ColumnGrid::boxColumns(uint32_t t) const {
    const auto& q = triangles_[t];
    const Vec3 &p0 = positions_[q[0]], &p1 = positions_[q[1]], &p2 = positions_[q[2]];
    return boxColumns(std::min({p0.x, p1.x, p2.x}), std::max({p0.x, p1.x, p2.x}), std::min({p0.y, p1.y, p2.y}),
                      std::max({p0.y, p1.y, p2.y}));
}

bool ColumnGrid::firstCommon(uint32_t a, uint32_t b, uint32_t bin) const {
    // No column before both triangles' first ones lists both: when `bin` is
    // the later of the two first columns, it is the first common one.
    if (bin == std::max(first_bin_[a], first_bin_[b])) return true;

    const int32_t row = int32_t(bin / uint32_t(nx_));
    for (int32_t r = int32_t(std::max(first_bin_[a], first_bin_[b]) / uint32_t(nx_)); r <= row; ++r) {
        int32_t a0, a1, b0, b1;
        if (!span(a, r, a0, a1) || !span(b, r, b0, b1)) continue;
        if (std::max(a0, b0) > std::min(a1, b1)) continue;
        return uint32_t(r) * uint32_t(nx_) + uint32_t(std::max(a0, b0)) == bin;
    }
    return false;
}

void ColumnGrid::forEachOverlappingPair(const std::function<void(unsigned, uint32_t, uint32_t)>& visit,
                                        unsigned workers, bool share_no_vertex) const {
    if (rays_ == Rays::Vertical) throw std::logic_error("ColumnGrid: a grid for vertical rays lists no walls, so no pairs");
    const size_t columns = start_.size() - 1;
    if (columns == 0 || entries_.empty()) return;
    workers = std::max(1u, std::min(detail::workerCount(workers), unsigned((columns + kColumnsPerTask - 1) / kColumnsPerTask)));
    std::atomic<size_t> next{0};
    detail::runOnWorkers(workers, [&](unsigned worker, const std::atomic<bool>& stop) {
        std::vector<Box3> boxes;
        std::vector<BoxColumns> box_columns;
        std::vector<uint8_t> columns_known;  // box_columns[i] computed (only for triangles of a visited pair)
        std::vector<uint32_t> by_z;          // the column's boxes by lowest z
        for (size_t task; !stop.load() && (task = next.fetch_add(kColumnsPerTask)) < columns;) {
            const size_t end = std::min(columns, task + kColumnsPerTask);
            for (size_t bin = task; bin < end; ++bin) {
                const uint32_t first = start_[bin], n = start_[bin + 1] - first;
                if (n < 2) continue;
                boxes.resize(n);
                box_columns.resize(n);
                columns_known.assign(n, 0);
                for (uint32_t i = 0; i < n; ++i) {
                    const auto& q = triangles_[entries_[first + i]];
                    const Vec3 &p0 = positions_[q[0]], &p1 = positions_[q[1]], &p2 = positions_[q[2]];
                    Box3& box = boxes[i];
                    box = {{std::min({p0.x, p1.x, p2.x}), std::min({p0.y, p1.y, p2.y}), std::min({p0.z, p1.z, p2.z})},
                           {std::max({p0.x, p1.x, p2.x}), std::max({p0.y, p1.y, p2.y}), std::max({p0.z, p1.z, p2.z})}};
                }
                // Sweep and prune along z: the column's boxes by their
                // lowest z, so that each box meets only the boxes that start
                // below its top, not every other box of the column (a
                // 1000 x 1000 model's columns list 15 triangles on average;
                // their tops and walls stand at many heights).
                by_z.resize(n);
                for (uint32_t i = 0; i < n; ++i) by_z[i] = i;
                for (uint32_t k = 1; k < n; ++k) {  // insertion: a column holds a few dozen at most
                    const uint32_t i = by_z[k];
                    const double z = boxes[i].lo[2];
                    uint32_t m = k;
                    for (; m > 0 && boxes[by_z[m - 1]].lo[2] > z; --m) by_z[m] = by_z[m - 1];
                    by_z[m] = i;
                }
                for (uint32_t p = 0; p + 1 < n; ++p) {
                    const Box3& u = boxes[by_z[p]];
                    for (uint32_t q = p + 1; q < n; ++q) {
                        const Box3& v = boxes[by_z[q]];
                        // v starts at or above u's lowest z: they overlap in
                        // z exactly when v starts at or below u's top, and so
                        // does none of the boxes after v once v does not.
                        if (v.lo[2] > u.hi[2]) break;
                        if (u.lo[0] > v.hi[0] || v.lo[0] > u.hi[0] || u.lo[1] > v.hi[1] || v.lo[1] > u.hi[1]) continue;
                        // The pair in the column's own order, as before the sweep.
                        const uint32_t i = std::min(by_z[p], by_z[q]), j = std::max(by_z[p], by_z[q]);
                        const auto& qi = triangles_[entries_[first + i]];
                        if (share_no_vertex) {
                            const auto& qj = triangles_[entries_[first + j]];
                            if (qi[0] == qj[0] || qi[0] == qj[1] || qi[0] == qj[2] || qi[1] == qj[0] || qi[1] == qj[1] ||
                                qi[1] == qj[2] || qi[2] == qj[0] || qi[2] == qj[1] || qi[2] == qj[2])
                                continue;
                        }
                        const uint32_t a = entries_[first + i], b = entries_[first + j];
                        for (const uint32_t k : {i, j})
                            if (!columns_known[k]) {
                                box_columns[k] = boxColumns(boxes[k].lo[0], boxes[k].hi[0], boxes[k].lo[1], boxes[k].hi[1]);
                                columns_known[k] = 1;
                            }
                        const BoxColumns &ca = box_columns[i], &cb = box_columns[j];
                        // Two boxes of columns meet in a box: its first column
                        // is the later first row and the later first column.
                        const bool first_here =
                            ca.boxed && cb.boxed
                                ? bin == size_t(std::max(ca.r0, cb.r0)) * size_t(nx_) + size_t(std::max(ca.c0, cb.c0))
                                : firstCommon(a, b, uint32_t(bin));
                        if (first_here) visit(worker, a, b);
                    }
                }
            }
        }
    });
}

std::optional<RayHit> ColumnGrid::firstHit(const Vec3& origin, const Vec3& direction, int64_t skip,
                                           double max_distance_mm) const {
    if (rays_ == Rays::Vertical && (direction.x != 0 || direction.y != 0))
        throw std::logic_error("ColumnGrid: a grid for vertical rays lists no walls; asked for a ray that is not vertical");
    if (entries_.empty() || !finite(origin) || !finite(direction)) return std::nullopt;
    if (direction.x == 0 && direction.y == 0 && direction.z == 0) return std::nullopt;
    const V3 o{origin.x, origin.y, origin.z}, d{direction.x, direction.y, direction.z};
    const detail::RaySetup ray = detail::raySetup(o, d);
    const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    double best_t = max_distance_mm / len;  // a hit exactly at the limit still counts
    uint32_t best = kNone;
    V3 best_point{};
    // The triangles of column (c, r) that the ray's z can reach while over
    // it, between parameters t0 and t1 (widened by a part in a million of
    // the z range, far beyond the rounding of o.z + t * d.z).
    auto testColumn = [&](int32_t c, int32_t r, double t0, double t1) {
        const size_t bin = size_t(r) * size_t(nx_) + size_t(c);
        t1 = std::min(t1, best_t);
        double z_lo = -kInf, z_hi = kInf;
        const bool bounded = std::isfinite(t0) && std::isfinite(t1);  // a vertical ray is not: it reads one column whole
        if (bounded) {
            const double za = o[2] + t0 * d[2], zb = o[2] + t1 * d[2];
            const double pad = 1e-6 * (std::fabs(za) + std::fabs(zb) + std::fabs(zb - za)) + 1e-300;
            z_lo = std::min(za, zb) - pad;
            z_hi = std::max(za, zb) + pad;
        }
        // A horizontal ray meets no flat triangle: in the watertight test its
        // three edge functions are one height times differences that sum to
        // zero, so they have mixed signs or are all zero (no area).
        if (bounded) {
            const auto& column_z = column_z_[bin][d[2] == 0 ? 0 : 1];
            if (double(column_z[0]) > z_hi || double(column_z[1]) < z_lo) return;
        }
        // A vertical ray meets no wall (two corners over one point): the
        // edge functions of those two corners are the same products, so the
        // third is zero and the other two are each other's negation.
        const uint32_t begin = d[0] == 0 && d[1] == 0 ? other_start_[bin] : start_[bin];
        const uint32_t end = d[2] == 0 ? flat_start_[bin] : start_[bin + 1];
        for (uint32_t e = begin; e < end; ++e) {
            const uint32_t t = entries_[e];
            if (int64_t(t) == skip) continue;
            if (bounded && (double(z_range_[t][0]) > z_hi || double(z_range_[t][1]) < z_lo)) continue;
            const auto& q = triangles_[t];
            const Vec3 &a = positions_[q[0]], &b = positions_[q[1]], &c3 = positions_[q[2]];
            V3 hit;
            const double s = detail::hitTriangle(ray, {a.x, a.y, a.z}, {b.x, b.y, b.z}, {c3.x, c3.y, c3.z}, best_t, hit);
            if (s >= 0 && (s < best_t || (s == best_t && (best == kNone || t < best)))) {
                best_t = s;
                best = t;
                best_point = hit;
            }
        }
    };
    // The grid's box, widened by the margin: nothing listed lies outside it.
    const double gx0 = x0_ - margin_, gx1 = x0_ + nx_ * step_x_ + margin_;
    const double gy0 = y0_ - margin_, gy1 = y0_ + ny_ * step_y_ + margin_;
    if (d[0] == 0 && d[1] == 0) {
        if (o[0] < gx0 || o[0] > gx1 || o[1] < gy0 || o[1] > gy1) return std::nullopt;
        testColumn(binX(o[0]), binY(o[1]), -kInf, kInf);
    } else {
        // The part of the ray over the grid's box, then column by column.
        double t_in = 0, t_out = best_t;
        for (int k = 0; k < 2; ++k) {
            const double lo = k == 0 ? gx0 : gy0, hi = k == 0 ? gx1 : gy1;
            if (d[k] == 0) {
                if (o[k] < lo || o[k] > hi) return std::nullopt;
                continue;
            }
            double ta = (lo - o[k]) / d[k], tb = (hi - o[k]) / d[k];
            if (ta > tb) std::swap(ta, tb);
            t_in = std::max(t_in, ta);
            t_out = std::min(t_out, tb);
        }
        if (!(t_in <= t_out)) return std::nullopt;
        int32_t c = binX(o[0] + t_in * d[0]), r = binY(o[1] + t_in * d[1]);
        const int32_t step_c = d[0] > 0 ? 1 : -1, step_r = d[1] > 0 ? 1 : -1;
        // Ray parameters where it crosses the next column line in x and in y.
        auto nextLine = [&](int k, int32_t cell) {
            if (d[k] == 0) return kInf;
            const double origin_k = k == 0 ? x0_ : y0_, step = k == 0 ? step_x_ : step_y_;
            const double line = origin_k + double(d[k] > 0 ? cell + 1 : cell) * step;
            return (line - o[k]) / d[k];
        };
        double next_x = nextLine(0, c), next_y = nextLine(1, r);
        double t_enter = t_in;
        // A horizontal ray's one z, widened as testColumn widens it.
        const double z_pad = 1e-6 * 2 * std::fabs(o[2]) + 1e-300;
        int64_t checked_block = -1;
        for (;;) {
            if (d[2] == 0) {
                const int64_t block = int64_t(r / kBlockColumns) * block_nx_ + c / kBlockColumns;
                if (block != checked_block) {
                    checked_block = block;
                    const auto& bz = block_z_[size_t(block)];
                    if (double(bz[0]) > o[2] + z_pad || double(bz[1]) < o[2] - z_pad) {
                        // Step through the block: every column in it would be skipped.
                        bool out = false;
                        while (int64_t(r / kBlockColumns) * block_nx_ + c / kBlockColumns == block) {
                            const double t_exit = std::min({next_x, next_y, t_out});
                            t_enter = t_exit;
                            if (t_exit >= t_out) {
                                out = true;
                                break;
                            }
                            if (next_x <= next_y) {
                                c += step_c;
                                if (c < 0 || c >= nx_) {
                                    out = true;
                                    break;
                                }
                                next_x = nextLine(0, c);
                            } else {
                                r += step_r;
                                if (r < 0 || r >= ny_) {
                                    out = true;
                                    break;
                                }
                                next_y = nextLine(1, r);
                            }
                        }
                        if (out) break;
                        continue;
                    }
                }
            }
            const double t_exit = std::min({next_x, next_y, t_out});
            // The walk's parameters are a column's within rounding; a margin
            // of a column's tenth keeps every z the ray has over it.
            const double slack = 0.1 * std::min(step_x_ / std::max(std::fabs(d[0]), 1e-300),
                                                step_y_ / std::max(std::fabs(d[1]), 1e-300));
            testColumn(c, r, std::max(0.0, t_enter - slack), t_exit + slack);
            t_enter = t_exit;
            if (best != kNone && best_t <= t_exit) break;
            if (t_exit >= t_out) break;
            if (next_x <= next_y) {
                c += step_c;
                if (c < 0 || c >= nx_) break;
                next_x = nextLine(0, c);
            } else {
                r += step_r;
                if (r < 0 || r >= ny_) break;
                next_y = nextLine(1, r);
            }
        }
    }
    if (best == kNone) return std::nullopt;
    RayHit h;
    h.point_mm = {best_point[0], best_point[1], best_point[2]};
    h.distance_mm = best_t * len;
    h.triangle = best;
    return h;
}

}  // namespace tsf
