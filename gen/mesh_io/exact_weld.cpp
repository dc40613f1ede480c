#include "gen/mesh_io/exact_weld.h"

#include <algorithm>
#include <atomic>
#include <bit>
#include <utility>

#include "gen/mesh_io/exact_vertex_index.h"
#include "gen/util/workers.h"

namespace tsf::mesh_io {
namespace {

constexpr uint32_t kEmpty = UINT32_MAX;
// About this many positions a bucket: its entries (16 bytes each) and its
// table (twice as many slots, 4 bytes each) stay in a core's L2 cache.
constexpr size_t kBucketSize = 8192;
constexpr int kMaxBucketBits = 16;

}  // namespace

WeldedPositions weldExact(std::vector<Vec3> points, unsigned workers) {
    WeldedPositions out;
    const size_t n = points.size();
    if (n == 0) return out;
    workers = n < detail::kMinItemsForThreads ? 1u : detail::workerCount(workers);

    // Each position's bucket, from the top bits of its hash (the table in a
    // bucket uses the low bits), counted per worker's range.
    const int bits = std::min(kMaxBucketBits, int(std::bit_width(std::max<size_t>(n / kBucketSize, 1))) - 1);
    const size_t buckets = size_t(1) << bits;
    auto bucketOf = [bits](uint64_t hash) { return bits ? size_t(hash >> (64 - bits)) : 0; };
    std::vector<std::vector<uint32_t>> counts(workers, std::vector<uint32_t>(buckets, 0));
    detail::runOnRanges(workers, n, [&](unsigned w, size_t begin, size_t end) {
        for (size_t i = begin; i < end; ++i) {
            points[i] = withoutNegativeZero(points[i]);
            ++counts[w][bucketOf(positionHash(points[i]))];
        }
    });
    // Where each worker's positions of each bucket go: buckets in order,
    // within one the workers' ranges in order, so a bucket lists its
    // positions by increasing index. Each entry carries its hash, so that a
    // bucket is welded from its own entries: the positions themselves are
    // read again only to confirm an equal hash.
    const std::vector<uint32_t> bucket_start = detail::slotsByRun(counts, buckets);
    struct Entry {
        uint64_t hash;
        uint32_t index;
    };
    std::vector<Entry> entries(n);
    detail::runOnRanges(workers, n, [&](unsigned w, size_t begin, size_t end) {
        std::vector<uint32_t>& next = counts[w];
        for (size_t i = begin; i < end; ++i) {
            const uint64_t h = positionHash(points[i]);
            entries[next[bucketOf(h)]++] = {h, uint32_t(i)};
        }
    });

    // In each bucket, each position's first equal (the smallest index, as
    // the bucket is in index order).
    std::vector<uint32_t> first(n);
    std::atomic<size_t> next_bucket{0};
    detail::runOnWorkers(workers, [&](unsigned, const std::atomic<bool>&) {
        std::vector<uint32_t> slots;  // kEmpty or an entry of the bucket
        for (size_t b; (b = next_bucket.fetch_add(1)) < buckets;) {
            const uint32_t from = bucket_start[b], to = bucket_start[b + 1];
            const size_t size = std::bit_ceil(std::max<size_t>(2 * size_t(to - from), 16));
            slots.assign(size, kEmpty);
            const size_t mask = size - 1;
            for (uint32_t k = from; k < to; ++k) {
                const Entry e = entries[k];
                size_t s = size_t(e.hash) & mask;
                for (; slots[s] != kEmpty; s = (s + 1) & mask) {
                    const Entry& f = entries[slots[s]];
                    if (f.hash == e.hash && points[f.index] == points[e.index]) break;
                }
                if (slots[s] == kEmpty) slots[s] = k;
                first[e.index] = entries[slots[s]].index;
            }
        }
    });
    std::vector<Entry>().swap(entries);

    // Numbered in order of first appearance; a repeat takes its first's
    // number (first[i] <= i: numbered already).
    out.index_of.resize(n);
    uint32_t next = 0;
    for (size_t i = 0; i < n; ++i)
        if (first[i] == i) out.index_of[i] = next++;
        else out.index_of[i] = out.index_of[first[i]];
    if (next == n) {
        out.positions = std::move(points);
    } else {
        out.positions.reserve(next);
        for (size_t i = 0; i < n; ++i)
            if (first[i] == i) out.positions.push_back(points[i]);
    }
    return out;
}

}  // namespace tsf::mesh_io
