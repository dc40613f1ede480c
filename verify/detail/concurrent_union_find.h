// ConcurrentUnionFind: disjoint sets over 0..n-1 that several threads join at
// once (the triangles' components in analyzeTopology, verify/mesh_topology.h).
// The one-thread UnionFind is gen/util/union_find.h; both keep a set's
// smallest member as its root, so they give the same sets and roots.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>

namespace tsf::detail {

/// Union-find that several threads may unite in at once (lock-free): a root
/// is linked under the smaller root by compare-and-swap, and path halving
/// only ever moves a parent to a smaller member, so the root of a set is
/// still its smallest member and the sets, once every thread is done, are
/// the same whatever the order of the unions.
class ConcurrentUnionFind {
public:
    explicit ConcurrentUnionFind(size_t n) : parent_(new std::atomic<uint32_t>[n]), size_(n) {
        for (size_t i = 0; i < n; ++i) parent_[i].store(uint32_t(i), std::memory_order_relaxed);
    }

    /// The root of x's set as some thread last saw it; once the unions are
    /// done (every thread joined), the smallest member of x's set.
    uint32_t find(uint32_t x) {
        for (;;) {
            uint32_t p = parent_[x].load(std::memory_order_relaxed);
            if (p == x) return x;
            const uint32_t g = parent_[p].load(std::memory_order_relaxed);
            if (g != p) parent_[x].compare_exchange_weak(p, g, std::memory_order_relaxed);  // halving; may lose a race
            x = g;
        }
    }

    /// Joins the sets of a and b.
    void unite(uint32_t a, uint32_t b) {
        for (;;) {
            a = find(a);
            b = find(b);
            if (a == b) return;
            if (a > b) std::swap(a, b);
            uint32_t expected = b;  // b is still a root: link it under a
            if (parent_[b].compare_exchange_strong(expected, a, std::memory_order_relaxed)) return;
        }
    }

    size_t size() const { return size_; }

private:
    std::unique_ptr<std::atomic<uint32_t>[]> parent_;
    size_t size_;
};

}  // namespace tsf::detail
