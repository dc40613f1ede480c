#include "gen/model/concave_hull.h"

#include <algorithm>
#include <deque>
#include <limits>

namespace tsf {
namespace {

constexpr int32_t kFar = std::numeric_limits<int32_t>::max();

// Calls f(neighbour index) for each neighbour of `cell` inside the grid; returns
// whether the cell touches the outside of the grid.
template <class F>
bool forNeighbours(const HexGrid& g, int64_t cell, F f) {
    const int32_t c = int32_t(cell % g.cols), r = int32_t(cell / g.cols);
    bool border = false;
    for (int k = 0; k < kHexCorners; ++k) {
        int32_t nc, nr;
        hexNeighbour(c, r, k, nc, nr);
        if (!g.contains(nc, nr)) {
            border = true;
            continue;
        }
        f(g.index(nc, nr));
    }
    return border;
}

// Hex-step distance from every cell to the nearest cell where `source` is
// set; with `outside_is_source`, beyond the grid counts as a source (a
// border cell is then 1 step away).
std::vector<int32_t> stepsTo(const HexGrid& g, const std::vector<uint8_t>& source, bool outside_is_source) {
    const int64_t n = g.cellCount();
    std::vector<int32_t> d(size_t(n), kFar);
    std::deque<int64_t> queue;
    for (int64_t i = 0; i < n; ++i)
        if (source[size_t(i)]) {
            d[size_t(i)] = 0;
            queue.push_back(i);
        }
    if (outside_is_source)
        for (int64_t i = 0; i < n; ++i)
            if (d[size_t(i)] > 1 && forNeighbours(g, i, [](int64_t) {})) {
                d[size_t(i)] = 1;
                queue.push_back(i);
            }
    // Sources at 0 come first; border cells at 1 after them: the queue stays ordered.
    std::stable_sort(queue.begin(), queue.end(), [&](int64_t a, int64_t b) { return d[size_t(a)] < d[size_t(b)]; });
    while (!queue.empty()) {
        const int64_t i = queue.front();
        queue.pop_front();
        forNeighbours(g, i, [&](int64_t j) {
            if (d[size_t(j)] > d[size_t(i)] + 1) {
                d[size_t(j)] = d[size_t(i)] + 1;
                queue.push_back(j);
            }
        });
    }
    return d;
}

// Joins the piece of the first kept cell to the nearest other piece with a
// shortest path through `allowed` cells. Returns false if none is reachable.
bool joinNearest(const HexGrid& g, std::vector<uint8_t>& keep, const std::vector<int32_t>& piece,
                 const std::vector<uint8_t>& allowed) {
    const int64_t n = g.cellCount();
    int32_t home = -1;
    for (int64_t i = 0; i < n && home < 0; ++i) home = piece[size_t(i)];
    std::vector<int64_t> from(size_t(n), -2);  // -2 unseen, -1 start
    std::deque<int64_t> queue;
    for (int64_t i = 0; i < n; ++i)
        if (piece[size_t(i)] == home) {
            from[size_t(i)] = -1;
            queue.push_back(i);
        }
    while (!queue.empty()) {
        const int64_t i = queue.front();
        queue.pop_front();
        int64_t found = -1;
        forNeighbours(g, i, [&](int64_t j) {
            if (found >= 0 || from[size_t(j)] != -2 || !allowed[size_t(j)]) return;
            from[size_t(j)] = i;
            if (keep[size_t(j)] && piece[size_t(j)] != home) found = j;
            else queue.push_back(j);
        });
        if (found >= 0) {
            for (int64_t k = from[size_t(found)]; k >= 0 && from[size_t(k)] != -1; k = from[size_t(k)]) keep[size_t(k)] = 1;
            return true;
        }
    }
    return false;
}

}  // namespace

std::vector<uint8_t> concaveKeep(const HexGrid& g, const std::vector<uint8_t>& anchor,
                                 const std::vector<uint8_t>& convex_keep, int radius) {
    const size_t n = size_t(g.cellCount());
    std::vector<uint8_t> keep(n, 0);
    // 2. Closing: dilate, then erode (beyond the grid is outside the dilation).
    const std::vector<int32_t> to_anchor = stepsTo(g, anchor, false);
    std::vector<uint8_t> outside(n, 0);
    for (size_t i = 0; i < n; ++i) outside[i] = to_anchor[i] > radius;
    const std::vector<int32_t> to_outside = stepsTo(g, outside, true);
    for (size_t i = 0; i < n; ++i) keep[i] = anchor[i] || (to_outside[i] > radius && convex_keep[i]);
    // 4. One piece.
    std::vector<int32_t> piece;
    while (labelCellComponents(g, keep, piece) > 1)
        if (!joinNearest(g, keep, piece, convex_keep)) break;
    // 5. One rim: fill what empty cells beyond the grid cannot reach.
    std::vector<uint8_t> open(n, 0);
    std::vector<int64_t> stack;
    for (int64_t i = 0; i < int64_t(n); ++i)
        if (!keep[size_t(i)] && forNeighbours(g, i, [](int64_t) {})) {
            open[size_t(i)] = 1;
            stack.push_back(i);
        }
    while (!stack.empty()) {
        const int64_t i = stack.back();
        stack.pop_back();
        forNeighbours(g, i, [&](int64_t j) {
            if (!keep[size_t(j)] && !open[size_t(j)]) {
                open[size_t(j)] = 1;
                stack.push_back(j);
            }
        });
    }
    for (size_t i = 0; i < n; ++i)
        if (!open[i]) keep[i] = 1;
    return keep;
}

}  // namespace tsf
