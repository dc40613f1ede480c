// Work split over threads: how many, and running on them (the verifier's
// parallel stages, the mesher's passes, welding positions), and the slots of
// a counting sort counted on them.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <system_error>
#include <thread>
#include <vector>

namespace tsf::detail {

/// `workers` when positive, else one per core (at least one).
inline unsigned workerCount(unsigned workers) {
    if (workers > 0) return workers;
    return std::max(1u, std::thread::hardware_concurrency());
}

/// Calls fn(worker, stop) for every worker in [0, workers): worker 0 on the
/// calling thread, the others on threads of their own, and joins them. The
/// first exception fn throws is rethrown here once every worker is done;
/// `stop` turns true as soon as one is thrown, so that a long loop can end
/// early. When no more threads can be started, the workers left run on the
/// calling thread after worker 0: a worker must never wait for another.
template <class Fn>
void runOnWorkers(unsigned workers, Fn&& fn) {
    std::atomic<bool> stop{false};
    std::exception_ptr error;  // written once, by the worker that set `stop`
    auto guarded = [&](unsigned worker) {
        try {
            fn(worker, static_cast<const std::atomic<bool>&>(stop));
        } catch (...) {
            if (!stop.exchange(true)) error = std::current_exception();
        }
    };
    std::vector<std::thread> pool;
    pool.reserve(workers);
    unsigned started = 1;
    try {
        for (; started < workers; ++started) pool.emplace_back(guarded, started);
    } catch (const std::system_error&) {
        // No thread to be had (a process or system limit): the workers not
        // started run here, after worker 0, each once as on its own thread.
    }
    guarded(0);
    for (unsigned w = started; w < workers; ++w) guarded(w);
    for (std::thread& t : pool) t.join();
    if (error) std::rethrow_exception(error);
}

/// Below this many items a pass over them runs on one thread: a thread
/// costs more than it saves.
inline constexpr size_t kMinItemsForThreads = size_t(1) << 16;

/// Splits [0, n) into `workers` runs of consecutive indices, in order, and
/// calls fn(worker, begin, end) for each on runOnWorkers; one run on the
/// calling thread when n < kMinItemsForThreads. A pass whose runs' findings
/// are joined in worker order gives what one pass in index order gives.
template <class Fn>
void runOnRanges(unsigned workers, size_t n, Fn&& fn) {
    const unsigned runs = n < kMinItemsForThreads ? 1u : workers;
    runOnWorkers(runs, [&](unsigned w, const std::atomic<bool>&) { fn(w, n * w / runs, n * (w + 1) / runs); });
}

/// The slots of a counting sort whose items were counted run by run (see
/// runOnRanges): `counts[w][k]` is how many items of key k run w holds, for
/// keys 0 .. keys-1, and becomes the slot of the first of them; keys are in
/// order and, within a key, the runs in order, so runs that then place their
/// items in their own order (counts[w][k]++) list every key's items as one
/// pass in index order would. Returns where each key's items start, and the
/// total at [keys].
inline std::vector<uint32_t> slotsByRun(std::vector<std::vector<uint32_t>>& counts, size_t keys) {
    std::vector<uint32_t> start(keys + 1, 0);
    uint32_t at = 0;
    for (size_t k = 0; k < keys; ++k) {
        start[k] = at;
        for (std::vector<uint32_t>& run : counts) {
            const uint32_t n = run[k];
            run[k] = at;
            at += n;
        }
    }
    start[keys] = at;
    return start;
}

}  // namespace tsf::detail
