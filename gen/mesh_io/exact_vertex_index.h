// ExactVertexIndex: gives equal positions one index, and only equal ones.
//
// Two positions are the same vertex when all three coordinates are equal as
// doubles (so -0.0 and +0.0 are the same value; nothing else that differs in
// any bit is). There is no tolerance: vertices 1e-12 mm apart stay two
// vertices, as topology must be built, not guessed (docs/design.md).
// Open-addressing hash table; insert is O(1) expected. Internal to
// gen/mesh_io/ (the readers use it through MeshAssembler).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf::mesh_io {

/// The splitmix64 finaliser: every input bit affects every output bit.
inline uint64_t mixBits(uint64_t h) {
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return h;
}

/// `p` with -0.0 made +0.0 and every other value unchanged (x + 0.0): the
/// one form in which the index and weldExact store and hash a position.
inline Vec3 withoutNegativeZero(const Vec3& p) { return {p.x + 0.0, p.y + 0.0, p.z + 0.0}; }

/// The hash both the index and weldExact (exact_weld.h) give a position
/// (-0.0 already made +0.0): every bit of every coordinate counts.
inline uint64_t positionHash(const Vec3& p) {
    return mixBits(std::bit_cast<uint64_t>(p.x) ^
                   mixBits(std::bit_cast<uint64_t>(p.y) ^ mixBits(std::bit_cast<uint64_t>(p.z))));
}

class ExactVertexIndex {
public:
    /// expected_count: how many distinct positions to reserve room for.
    explicit ExactVertexIndex(size_t expected_count = 0);

    /// Index of the position equal to p, appending p if it is new.
    /// p must not contain NaN (a bug: callers reject NaN first). Stored
    /// positions have -0.0 replaced by +0.0. The caller keeps the count below
    /// 2^32 - 1 (size() tells).
    uint32_t insert(const Vec3& p);
    /// insert(p[i]) for i = 0 .. n-1 in order, its index in out[i]: the
    /// same indices, with the table's slots and positions of a few at a
    /// time fetched from memory together (on a large mesh the table is far
    /// larger than the caches, and one by one each insert waits for its own
    /// two misses).
    void insertBatch(const Vec3* p, size_t n, uint32_t* out);

    size_t size() const { return positions_.size(); }
    const std::vector<Vec3>& positions() const { return positions_; }
    std::vector<Vec3> takePositions() { return std::move(positions_); }

private:
    void rehash(size_t slot_count);
    size_t slotOf(const Vec3& p) const;
    uint32_t insertHashed(const Vec3& p, uint64_t hash);  // p already without -0.0

    std::vector<Vec3> positions_;
    std::vector<uint32_t> slots_;  ///< kEmptySlot or an index into positions_
    size_t mask_ = 0;
};

}  // namespace tsf::mesh_io
