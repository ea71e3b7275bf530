// The measuring interval of the motion loop: single writer, sequence-counted readers.
#include "imess/core/interval_stats.hpp"

namespace imess::core {

void IntervalStats::record(double latency_us, bool overrun) noexcept {
  const std::uint64_t s = sequence_.load(std::memory_order_relaxed);
  sequence_.store(s + 1, std::memory_order_relaxed);
  std::atomic_thread_fence(std::memory_order_release);  // readers see "odd" before any count changes
  const std::uint64_t wanted = requested_.load(std::memory_order_acquire);
  if (wanted != applied_.load(std::memory_order_relaxed)) {
    for (auto& b : buckets_) b.store(0, std::memory_order_relaxed);
    overruns_.store(0, std::memory_order_relaxed);
    max_.store(0, std::memory_order_relaxed);
    applied_.store(wanted, std::memory_order_release);
  }
  auto& b = buckets_[latency_bucket(latency_us)];
  b.store(b.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);  // one writer: no read-modify-write
  if (overrun) overruns_.store(overruns_.load(std::memory_order_relaxed) + 1, std::memory_order_relaxed);
  if (latency_us > max_.load(std::memory_order_relaxed)) max_.store(latency_us, std::memory_order_relaxed);
  sequence_.store(s + 2, std::memory_order_release);
}

bool IntervalStats::snapshot(IntervalSnapshot& out) const noexcept {
  for (int attempt = 0; attempt < 500; ++attempt) {
    const std::uint64_t before = sequence_.load(std::memory_order_acquire);
    std::uint64_t cycles = 0;
    for (std::size_t i = 0; i < buckets_.size(); ++i) {
      out.buckets[i] = buckets_[i].load(std::memory_order_relaxed);
      cycles += out.buckets[i];
    }
    out.cycles = cycles;
    out.overruns = overruns_.load(std::memory_order_relaxed);
    out.latency_max_us = max_.load(std::memory_order_relaxed);
    std::atomic_thread_fence(std::memory_order_acquire);
    if ((before & 1) == 0 && sequence_.load(std::memory_order_relaxed) == before) return true;
  }
  return false;
}

}  // namespace imess::core
