// How many threads the verifier's parallel stages use.
#pragma once

#include <algorithm>
#include <thread>

namespace tsf::detail {

/// `workers` when positive, else one per core (at least one).
inline unsigned workerCount(unsigned workers) {
    if (workers > 0) return workers;
    return std::max(1u, std::thread::hardware_concurrency());
}

}  // namespace tsf::detail
