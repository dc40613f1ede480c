// A pairwise sum of many terms without a list of them all.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <utility>
#include <vector>

#include "gen/util/workers.h"

namespace tsf::detail {

/// The sum of term(0) .. term(n - 1) in the pairwise order: (0 + 1),
/// (2 + 3), ... level by level, the odd last one of a level carried to the
/// next. Its depth is log2(n): a lazy exact number records every operation,
/// and a running sum of a million terms is a million-deep chain that
/// overflows the stack when it is evaluated or freed.
///
/// The same bits as summing a list of all the terms that way, for any
/// number of workers, without the list (a 1000 x 1000 model's volume had
/// 13 million terms, 102 MiB): blocks of kBlock terms at multiples of
/// kBlock are whole subtrees of that order, summed on the workers; their
/// sums and the last block's terms then join as a binary counter does (two
/// subtrees of one size make one of twice the size), and the subtrees left
/// are added from the right, as the carried terms are.
template <class T, class Term>
T pairwiseSum(size_t n, unsigned workers, const Term& term) {
    constexpr size_t kBlock = size_t(1) << 14;
    // (sum, terms under it), sizes falling from the bottom of the stack.
    std::vector<std::pair<T, size_t>> stack;
    auto push = [&stack](T value, size_t size) {
        while (!stack.empty() && stack.back().second == size) {
            value = stack.back().first + value;
            size *= 2;
            stack.pop_back();
        }
        stack.emplace_back(std::move(value), size);
    };
    const size_t blocks = n / kBlock;
    std::vector<T> block_sums(blocks);
    if (blocks > 0) {
        std::atomic<size_t> next{0};
        runOnWorkers(std::max(1u, std::min(workers, unsigned(blocks))), [&](unsigned, const std::atomic<bool>& stop) {
            std::vector<T> level(kBlock);
            for (size_t b; !stop.load() && (b = next.fetch_add(1)) < blocks;) {
                for (size_t k = 0; k < kBlock; ++k) level[k] = term(b * kBlock + k);
                for (size_t width = kBlock; width > 1; width /= 2)
                    for (size_t i = 0; i < width / 2; ++i) level[i] = level[2 * i] + level[2 * i + 1];
                block_sums[b] = level[0];
            }
        });
    }
    for (size_t b = 0; b < blocks; ++b) push(std::move(block_sums[b]), kBlock);
    for (size_t k = blocks * kBlock; k < n; ++k) push(term(k), 1);
    if (stack.empty()) return T(0);
    while (stack.size() > 1) {
        T last = std::move(stack.back().first);
        stack.pop_back();
        stack.back().first = stack.back().first + last;
    }
    return stack.back().first;
}

}  // namespace tsf::detail
