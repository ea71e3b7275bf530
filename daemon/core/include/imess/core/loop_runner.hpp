// LoopRunner: runs MotionCore::cycle in its own thread at a fixed period with absolute
// deadlines (clock_nanosleep TIMER_ABSTIME), SCHED_FIFO and mlockall when permitted, and
// measures its own wake-up latency, cycle time and overruns: since the start (summarised once
// a second) and over a measuring interval that clients restart (IntervalStats).
#pragma once
#include <atomic>
#include <string>
#include <thread>

#include "imess/core/interval_stats.hpp"
#include "imess/core/latency_histogram.hpp"
#include "imess/core/motion_core.hpp"

namespace imess::core {

// CLOCK_MONOTONIC, the clock the runner sleeps on.
class MonotonicClock final : public hal::Clock {
 public:
  Nanos now() const noexcept override;
};

// Loop time (the simulated machine's "sim.time": "loop"): the clock stands between motion
// cycles and moves on one period per cycle, however late the cycle wakes. A simulated
// machine on it sees a host that never stalls (tests on loaded machines); it runs behind
// the wall clock by the stalls. Read from any thread, advanced by the LoopRunner.
class LoopClock final : public hal::Clock {
 public:
  explicit LoopClock(Nanos start) noexcept : now_(start.count()) {}
  Nanos now() const noexcept override { return Nanos(now_.load(std::memory_order_acquire)); }
  Nanos advance(Nanos period) noexcept {
    return Nanos(now_.fetch_add(period.count(), std::memory_order_acq_rel) + period.count());
  }

 private:
  std::atomic<std::int64_t> now_;
};

struct LoopStats {
  double period_us = 0;
  std::uint64_t cycles = 0, overruns = 0;
  double latency_p50_us = 0, latency_p99_us = 0, latency_p999_us = 0, latency_max_us = 0;
  double cycle_p99_us = 0, cycle_max_us = 0;  // time spent inside cycle()
  bool realtime = false;                       // SCHED_FIFO granted
};

class LoopRunner {
 public:
  static constexpr int kPriority = 80;  // SCHED_FIFO priority of the motion loop, when granted
  LoopRunner(MotionCore& core, const MonotonicClock& clock, Nanos period);
  ~LoopRunner();
  LoopRunner(const LoopRunner&) = delete;
  LoopRunner& operator=(const LoopRunner&) = delete;

  // Locks memory and starts the thread; returns what real-time support was granted, in words.
  std::string start(bool want_realtime);
  // Before start(): each cycle runs at loop time (LoopClock) instead of its wake-up time, and
  // the cycles come `speed` times a period of wall time (sim.speed: the simulated machine's
  // clock runs that many times faster than the wall's; 1 is real speed).
  void use_loop_time(LoopClock* clock, int speed = 1) noexcept {
    loop_time_ = clock;
    wall_period_ = period_ / (speed < 1 ? 1 : speed);
  }
  void stop();
  // Since the start, summarised once a second (Stats).
  const LoopStats& stats() noexcept { return stats_.read(); }
  // The measuring interval (Stats Reset, Stats Interval, Stats Hist): any thread.
  void restart_interval() noexcept { interval_.request_restart(); }
  bool interval_restarted() const noexcept { return interval_.restarted(); }  // the loop has begun it
  void interval(IntervalSnapshot& out) const noexcept { (void)interval_.snapshot(out); }
  double period_us() const noexcept { return std::chrono::duration<double, std::micro>(period_).count(); }
  bool realtime() const noexcept { return realtime_.load(std::memory_order_relaxed); }

 private:
  void run() noexcept;

  MotionCore& core_;
  const MonotonicClock& clock_;
  LoopClock* loop_time_ = nullptr;
  Nanos period_;
  Nanos wall_period_ = period_;  // the wall time between cycles: the period, shorter in loop time at sim.speed > 1
  std::atomic<bool> running_{false};
  std::thread thread_;
  std::atomic<bool> realtime_{false};
  LatencyHistogram latency_, cycle_time_;
  std::uint64_t overruns_ = 0;
  IntervalStats interval_;
  TripleBuffer<LoopStats> stats_;
};

}  // namespace imess::core
