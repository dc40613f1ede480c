// ColumnGrid: the verifier's index of a mesh's triangles by where they stand
// over the bed, for first hits of rays and for the pairs of triangles that
// may touch (the broad phase of the self-intersection test).
//
// Why a grid and not a tree: a terrain model is mostly vertical walls and
// horizontal tops over a lattice, so a uniform grid of columns over x, y
// holds a handful of triangles in each column; it is built in two linear
// passes (counting, then filling), where a tree sorts. It is built from the
// mesh's own coordinates only (never from the Scene that made it), and it
// trusts nothing about the mesh: a triangle of any shape or slope, however
// far from the lattice, is listed in every column its footprint meets.
//
// Footprints: a small triangle (its box over at most 16 columns) is listed
// in every column its bounding box meets; a larger one in the columns its
// projection on x, y meets, row by row (the part of the triangle in a row's
// band of y, widened by a margin), not in every column of its box: the long
// thin triangles of a flat bottom meet few columns of their box. The margin,
// a millionth of the model's size (0.15 um on a 150 mm model), is far
// larger than the rounding of the footprints' arithmetic, so a point of a
// triangle is always in a column that lists it, even on a column's edge.
//
// Pairs: two triangles are candidates when a column lists both and their
// closed bounding boxes overlap (touching counts); each is reported once, in
// the first column (row by row, west to east) that lists both. Every pair
// that touches or intersects is among them: the point they share is in a
// column that lists both.
//
// Rays: the columns along the ray's projection, nearest first (Amanatides
// and Woo's grid walk); a vertical ray reads one column. Each triangle is
// tested with the watertight test shared with the tree
// (verify/detail/ray_triangle.h), so both casters answer alike; the walk
// stops at the first column whose far side lies beyond the nearest hit.
// Each column lists its walls (two corners over one point) first and its
// flat triangles (one z) last: a vertical ray skips the walls and a
// horizontal one the flat triangles, which that test cannot report as hit
// (exactly: see firstHit), and a column whose z range the ray's z misses is
// skipped whole; a horizontal ray steps through a block of 8 x 8 columns
// unread when its z misses the block's range. Ties at one distance go to the
// lower mesh index.
//
// Built on the worker threads from 20 000 triangles, in the same order as
// on one. At most 2^32 listings (a std::length_error beyond: some 1.1
// billion triangles).
//
// Triangles with an out-of-range index or a non-finite corner are left out.
// Units: millimetres, model frame. Queries are const and may run
// concurrently. The grid reads the mesh in place: the mesh must outlive it
// and not change while it lives; a temporary mesh is refused at compile time.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <optional>
#include <vector>

#include "gen/geometry/mesh.h"
#include "gen/util/default_init_allocator.h"
#include "verify/ray_hit.h"

namespace tsf {

class ColumnGrid {
public:
    /// `triangles_per_column`: how many triangles a column holds on average
    /// (the grid's size follows from it); fewer means more columns to walk
    /// and list, more means more triangles tested per column.
    /// The rays the grid will be asked about. Vertical: it lists no walls
    /// (two corners over one point, which no vertical ray can hit), a grid
    /// for reading heights back that is built in less time; it refuses a
    /// ray that is not vertical and the pairs (std::logic_error).
    enum class Rays : uint8_t { Any, Vertical };
    explicit ColumnGrid(const Mesh& mesh, double triangles_per_column = kTrianglesPerColumn, Rays rays = Rays::Any);
    explicit ColumnGrid(Mesh&&, double = kTrianglesPerColumn, Rays = Rays::Any) = delete;  ///< read in place: the mesh must outlive the grid

    /// The nearest hit of the ray origin + s * direction, s >= 0, ignoring
    /// triangle `skip` (-1: none) and anything farther than max_distance_mm;
    /// nullopt if nothing is hit, or the direction is zero or not finite.
    std::optional<RayHit> firstHit(const Vec3& origin, const Vec3& direction, int64_t skip = -1,
                                   double max_distance_mm = std::numeric_limits<double>::infinity()) const;

    /// Calls visit(worker, a, b) once for every unordered pair of distinct
    /// triangles (mesh indices) listed in a common column whose closed
    /// bounding boxes overlap: every pair that touches or intersects is
    /// among them. Runs on up to `workers` threads (0: one per core);
    /// `worker` is the calling thread's number in [0, workers). An exception
    /// thrown by `visit` stops the walk and is rethrown here once every
    /// thread is done. `share_no_vertex`: only the pairs that share no
    /// vertex index (the self-intersection test decides the others from the
    /// fans around each vertex, verify/detail/vertex_fans.h).
    void forEachOverlappingPair(const std::function<void(unsigned worker, uint32_t a, uint32_t b)>& visit,
                                unsigned workers = 0, bool share_no_vertex = false) const;

    size_t triangleCount() const { return listed_; }   ///< triangles usable (listed, or walls left out of a Vertical grid)
    Rays rays() const { return rays_; }
    int32_t columns() const { return nx_; }             ///< along x
    int32_t rows() const { return ny_; }                ///< along y
    size_t entries() const { return entries_.size(); }  ///< (column, triangle) listings
    double buildMs() const { return build_ms_; }
    /// The south-west corner of column (c, r) (x, y in mm; z = 0): where
    /// four columns meet when 0 < c < columns() and 0 < r < rows().
    Vec3 columnCorner(int32_t c, int32_t r) const { return {x0_ + double(c) * step_x_, y0_ + double(r) * step_y_, 0}; }

    static constexpr double kTrianglesPerColumn = 4.0;

private:
    int32_t binX(double x) const;
    int32_t binY(double y) const;
    /// Columns c0..c1 of row r that triangle t's footprint meets; false if none.
    bool span(uint32_t t, int32_t r, int32_t& c0, int32_t& c1) const;
    void rowRange(uint32_t t, int32_t& r0, int32_t& r1) const;
    /// Is `bin` (listing both) the first column, row-major, listing both a and b?
    bool firstCommon(uint32_t a, uint32_t b, uint32_t bin) const;
    bool isFlat(uint32_t t) const;  ///< every corner at one z
    bool isWall(uint32_t t) const;  ///< two corners over one point of x, y
    /// The columns and rows triangle t's box meets (widened by the margin);
    /// `boxed`: few enough that the triangle is listed in all of them.
    struct BoxColumns {
        int32_t c0, c1, r0, r1;
        bool boxed;
    };
    BoxColumns boxColumns(uint32_t t) const;
    BoxColumns boxColumns(double x_lo, double x_hi, double y_lo, double y_hi) const;

    const Vec3* positions_ = nullptr;
    const std::array<uint32_t, 3>* triangles_ = nullptr;
    double x0_ = 0, y0_ = 0;       // the grid's south-west corner (mm)
    double step_x_ = 1, step_y_ = 1;  // a column's size (mm)
    double inv_x_ = 1, inv_y_ = 1;
    double margin_ = 0;            // footprints' margin (mm)
    int32_t nx_ = 0, ny_ = 0;
    size_t listed_ = 0;
    UninitializedVector<uint32_t> first_bin_;  // per mesh triangle: the first column listing it (row-major), or UINT32_MAX
    std::vector<uint32_t> start_;      // per column: where its triangles start in entries_ (nx * ny + 1)
    UninitializedVector<uint32_t> entries_;  // mesh triangle indices, column by column (every one written by the fill)
    std::vector<uint32_t> other_start_;  // per column: where its triangles other than walls start in entries_
    std::vector<uint32_t> flat_start_; // per column: where its flat triangles start in entries_
    // Per column: the z range of its sloped and vertical triangles [0] and of
    // all its triangles [1] (floats rounded outwards; empty: +inf, -inf).
    std::vector<std::array<std::array<float, 2>, 2>> column_z_;
    // Per block of 8 x 8 columns: the z range of its columns' non-flat
    // triangles (a horizontal ray outside it passes the block unread).
    std::vector<std::array<float, 2>> block_z_;
    int32_t block_nx_ = 0;
    // Per mesh triangle: its z range as floats rounded outwards, so that a
    // ray along a column tests only the triangles its z passes there (the
    // grid's answer to a tree's boxes in z: a horizontal ray through a
    // solid crosses many columns of tops and walls it cannot hit).
    UninitializedVector<std::array<float, 2>> z_range_;
    double build_ms_ = 0;
    Rays rays_ = Rays::Any;
};

}  // namespace tsf
