#include "gen/mesh_io/exact_vertex_index.h"

#include <algorithm>
#include <cassert>
#include <cmath>

namespace tsf::mesh_io {
namespace {

constexpr uint32_t kEmptySlot = UINT32_MAX;
constexpr size_t kMinSlots = 64;

// The table is grown before it is half full, which keeps linear probes short.
constexpr size_t kMaxLoadNumerator = 1;
constexpr size_t kMaxLoadDenominator = 2;

size_t slotCountFor(size_t count) {
    size_t slots = kMinSlots;
    while (slots * kMaxLoadNumerator / kMaxLoadDenominator <= count) slots *= 2;
    return slots;
}

}  // namespace

ExactVertexIndex::ExactVertexIndex(size_t expected_count) {
    positions_.reserve(expected_count);
    rehash(slotCountFor(expected_count));
}

size_t ExactVertexIndex::slotOf(const Vec3& p) const { return static_cast<size_t>(positionHash(p)) & mask_; }

void ExactVertexIndex::rehash(size_t slot_count) {
    slots_.assign(slot_count, kEmptySlot);
    mask_ = slot_count - 1;
    for (size_t i = 0; i < positions_.size(); ++i) {
        size_t s = slotOf(positions_[i]);
        while (slots_[s] != kEmptySlot) s = (s + 1) & mask_;
        slots_[s] = static_cast<uint32_t>(i);
    }
}

uint32_t ExactVertexIndex::insert(const Vec3& p_in) {
    assert(!std::isnan(p_in.x) && !std::isnan(p_in.y) && !std::isnan(p_in.z));
    const Vec3 p = withoutNegativeZero(p_in);
    return insertHashed(p, positionHash(p));
}

uint32_t ExactVertexIndex::insertHashed(const Vec3& p, uint64_t hash) {
    size_t s = static_cast<size_t>(hash) & mask_;
    while (slots_[s] != kEmptySlot) {
        if (positions_[slots_[s]] == p) return slots_[s];
        s = (s + 1) & mask_;
    }
    const auto index = static_cast<uint32_t>(positions_.size());
    positions_.push_back(p);
    slots_[s] = index;
    if (positions_.size() * kMaxLoadDenominator > slots_.size() * kMaxLoadNumerator) rehash(slots_.size() * 2);
    return index;
}

void ExactVertexIndex::insertBatch(const Vec3* in, size_t n, uint32_t* out) {
    constexpr size_t kBatch = 32;
    Vec3 p[kBatch];
    uint64_t hash[kBatch];
    for (size_t from = 0; from < n; from += kBatch) {
        const size_t m = std::min(kBatch, n - from);
        // Hints only: a slot or position fetched for nothing costs a load.
        for (size_t i = 0; i < m; ++i) {
            const Vec3& q = in[from + i];
            assert(!std::isnan(q.x) && !std::isnan(q.y) && !std::isnan(q.z));
            p[i] = withoutNegativeZero(q);
            hash[i] = positionHash(p[i]);
            __builtin_prefetch(&slots_[static_cast<size_t>(hash[i]) & mask_]);
        }
        for (size_t i = 0; i < m; ++i)
            if (const uint32_t v = slots_[static_cast<size_t>(hash[i]) & mask_]; v != kEmptySlot)
                __builtin_prefetch(&positions_[v]);
        for (size_t i = 0; i < m; ++i) out[from + i] = insertHashed(p[i], hash[i]);
    }
}

}  // namespace tsf::mesh_io
