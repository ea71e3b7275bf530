// IntervalStats: the motion loop's wake-up latency and overruns over a measuring interval
// that any thread may restart (`Stats Reset`) and read (`Stats Interval`, `Stats Hist`)
// while the loop runs. The loop thread is the only writer. A restart reaches it as a
// generation number it compares once a cycle; readers copy the counts under a sequence
// count and copy again when a cycle wrote meanwhile. The loop never waits, allocates or locks.
#pragma once
#include <array>
#include <atomic>
#include <cstdint>

#include "imess/core/latency_histogram.hpp"

namespace imess::core {

// A copy of the interval, for the non-real-time side.
struct IntervalSnapshot {
  std::array<std::uint32_t, kLatencyBuckets> buckets{};  // wake-up latency, 1 µs buckets
  std::uint64_t cycles = 0;                              // the samples: the sum of the buckets
  std::uint64_t overruns = 0;                            // cycles that ended after the next deadline
  double latency_max_us = 0;
  double percentile(double p) const noexcept {
    return bucket_percentile(buckets.data(), buckets.size(), cycles, latency_max_us, p);
  }
};

class IntervalStats {
 public:
  // Loop thread, once a cycle (~10 ns; a pending restart first clears the 20 KB of counts,
  // ~2 µs, in the cycle after the request): the cycle's wake-up latency, and whether it
  // ended after the next deadline.
  void record(double latency_us, bool overrun) noexcept;

  // Any thread: the interval starts again at the loop's next cycle.
  void request_restart() noexcept { requested_.fetch_add(1, std::memory_order_release); }
  // Any thread: true once the loop has started the interval asked for last.
  bool restarted() const noexcept {
    return applied_.load(std::memory_order_acquire) == requested_.load(std::memory_order_acquire);
  }
  // Any thread: copies the interval. A copy that a cycle wrote into is taken again (up to a
  // few hundred times; a reader preempted throughout keeps the last copy: its counts are
  // then still each a cycle's, summed to `cycles`, but may mix two cycles). True when the
  // copy is of one moment, false for that last resort.
  bool snapshot(IntervalSnapshot& out) const noexcept;

 private:
  static_assert(std::atomic<double>::is_always_lock_free, "the loop must not lock to store a double");
  std::array<std::atomic<std::uint32_t>, kLatencyBuckets> buckets_{};
  std::atomic<std::uint64_t> overruns_{0};
  std::atomic<double> max_{0};
  std::atomic<std::uint64_t> sequence_{0};  // odd while the loop writes
  std::atomic<std::uint64_t> requested_{0}, applied_{0};
};

}  // namespace imess::core
