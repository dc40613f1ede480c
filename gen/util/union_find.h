// UnionFind: disjoint sets over 0..n-1 (connected pieces of a mesh, holes,
// planar regions, vertex fans).
//
// Path halving; the root of a set is always its smallest member, so results
// that list sets by root come out in the order of their first members, the
// same on every run.
#pragma once

#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace tsf {

class UnionFind {
public:
    explicit UnionFind(size_t n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), uint32_t(0)); }

    /// The root (smallest member) of x's set.
    uint32_t find(uint32_t x) {
        while (parent_[x] != x) {
            parent_[x] = parent_[parent_[x]];  // path halving
            x = parent_[x];
        }
        return x;
    }

    /// Joins the sets of a and b; false if they were one set already.
    bool unite(uint32_t a, uint32_t b) {
        a = find(a);
        b = find(b);
        if (a == b) return false;
        if (a < b) parent_[b] = a;
        else parent_[a] = b;
        return true;
    }

    /// True if x is the root of its set (each set has exactly one).
    bool isRoot(uint32_t x) const { return parent_[x] == x; }

    size_t size() const { return parent_.size(); }

private:
    std::vector<uint32_t> parent_;
};

}  // namespace tsf
