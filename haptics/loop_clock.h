// LoopClock: the time source and sleeper of the haptic loop, so the loop's
// scheduling logic can be tested with a fake clock and simulations can run
// faster than real time.
//
//   SteadyLoopClock  std::chrono::steady_clock (CLOCK_MONOTONIC); sleeps with
//                    clock_nanosleep to an absolute deadline, optionally
//                    spinning for the last spin_s to cut wake-up jitter.
//   FakeLoopClock    virtual time: sleepUntil() jumps to the deadline (plus a
//                    configurable lateness), now() never moves by itself;
//                    advance() lets a test spend time inside a tick.
// Both are noexcept and allocation-free in now() and sleepUntil().
#pragma once

#include <cstdint>
#include <functional>

namespace tsf::haptics {

class LoopClock {
public:
    virtual ~LoopClock() = default;
    /// Seconds since an arbitrary, fixed origin.
    virtual double now() noexcept = 0;
    /// Returns at or after t_s (immediately if t_s has passed).
    virtual void sleepUntil(double t_s) noexcept = 0;
};

class SteadyLoopClock final : public LoopClock {
public:
    /// spin_s: busy-wait this long before each deadline instead of sleeping
    /// (0 = sleep all the way; spinning costs a core but cuts jitter).
    explicit SteadyLoopClock(double spin_s = 0.0) : spin_s_(spin_s) {}
    double now() noexcept override;
    void sleepUntil(double t_s) noexcept override;

private:
    double spin_s_;
};

class FakeLoopClock final : public LoopClock {
public:
    double now() noexcept override { return now_s_; }
    void sleepUntil(double t_s) noexcept override;
    /// Moves time forward (a test's way to make a tick slow).
    void advance(double dt_s) noexcept { now_s_ += dt_s; }
    /// Lateness added to the k-th wake-up (k counts sleepUntil calls from 0);
    /// set before the loop starts. Empty = always on time.
    std::function<double(uint64_t)> lateness_s;

private:
    double now_s_ = 0.0;
    uint64_t sleeps_ = 0;
};

}  // namespace tsf::haptics
