#include "haptics/loop_clock.h"

#include <time.h>

#include <cerrno>
#include <chrono>
#include <cmath>

namespace tsf::haptics {

double SteadyLoopClock::now() noexcept {
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

void SteadyLoopClock::sleepUntil(double t_s) noexcept {
    const double wake = t_s - spin_s_;
    if (wake > now()) {
        // steady_clock is CLOCK_MONOTONIC on Linux, so its epoch matches.
        timespec ts;
        ts.tv_sec = time_t(std::floor(wake));
        ts.tv_nsec = long((wake - std::floor(wake)) * 1e9);
        if (ts.tv_nsec >= 1000000000L) {
            ts.tv_sec += 1;
            ts.tv_nsec -= 1000000000L;
        }
        while (clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr) == EINTR) {
        }
    }
    while (now() < t_s) {
    }
}

void FakeLoopClock::sleepUntil(double t_s) noexcept {
    if (t_s > now_s_) now_s_ = t_s;
    if (lateness_s) now_s_ += lateness_s(sleeps_);
    ++sleeps_;
}

}  // namespace tsf::haptics
