#include "gen/mesh_io/exact_vertex_index.h"

#include <bit>
#include <cassert>
#include <cmath>

namespace tsf::mesh_io {
namespace {

constexpr uint32_t kEmptySlot = UINT32_MAX;
constexpr size_t kMinSlots = 64;

// The table is grown before it is half full, which keeps linear probes short.
constexpr size_t kMaxLoadNumerator = 1;
constexpr size_t kMaxLoadDenominator = 2;

uint64_t mix(uint64_t h) {
    // splitmix64 finaliser: every input bit affects every output bit.
    h ^= h >> 30;
    h *= 0xbf58476d1ce4e5b9ULL;
    h ^= h >> 27;
    h *= 0x94d049bb133111ebULL;
    h ^= h >> 31;
    return h;
}

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

uint64_t positionHash(const Vec3& p) {
    return mix(std::bit_cast<uint64_t>(p.x) ^ mix(std::bit_cast<uint64_t>(p.y) ^ mix(std::bit_cast<uint64_t>(p.z))));
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
    // x + 0.0 turns -0.0 into +0.0 and leaves every other value unchanged.
    const Vec3 p{p_in.x + 0.0, p_in.y + 0.0, p_in.z + 0.0};
    size_t s = slotOf(p);
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

}  // namespace tsf::mesh_io
