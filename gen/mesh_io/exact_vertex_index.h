// ExactVertexIndex: gives equal positions one index, and only equal ones.
//
// Two positions are the same vertex when all three coordinates are equal as
// doubles (so -0.0 and +0.0 are the same value; nothing else that differs in
// any bit is). There is no tolerance: vertices 1e-12 mm apart stay two
// vertices, as topology must be built, not guessed (docs/design.md).
// Open-addressing hash table; insert is O(1) expected. Internal to
// gen/mesh_io/ (the readers use it through MeshAssembler).
#pragma once

#include <cstdint>
#include <vector>

#include "gen/geometry/mesh.h"

namespace tsf::mesh_io {

/// The hash both the index and weldExact (exact_weld.h) give a position
/// (-0.0 already made +0.0): every bit of every coordinate counts.
uint64_t positionHash(const Vec3& p);

class ExactVertexIndex {
public:
    /// expected_count: how many distinct positions to reserve room for.
    explicit ExactVertexIndex(size_t expected_count = 0);

    /// Index of the position equal to p, appending p if it is new.
    /// p must not contain NaN (a bug: callers reject NaN first). Stored
    /// positions have -0.0 replaced by +0.0. The caller keeps the count below
    /// 2^32 - 1 (size() tells).
    uint32_t insert(const Vec3& p);

    size_t size() const { return positions_.size(); }
    const std::vector<Vec3>& positions() const { return positions_; }
    std::vector<Vec3> takePositions() { return std::move(positions_); }

private:
    void rehash(size_t slot_count);
    size_t slotOf(const Vec3& p) const;

    std::vector<Vec3> positions_;
    std::vector<uint32_t> slots_;  ///< kEmptySlot or an index into positions_
    size_t mask_ = 0;
};

}  // namespace tsf::mesh_io
