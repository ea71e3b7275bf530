// TickRecorder: the base thread's observer in bench_rt — every tick's wake-up and end
// lateness into preallocated arrays (raw samples, ns), its overruns, and the most port reads
// and writes one tick made. Real-time like the thread it observes: no allocation, no lock.
#pragma once
#include <algorithm>
#include <atomic>
#include <cstdint>
#include <vector>

#include "base_tick_observer.hpp"
#include "counting_port.hpp"

namespace imess::bench {

class TickRecorder final : public app::BaseTickObserver {
 public:
  // Room for `capacity` ticks, touched now so that the thread never faults a page in.
  TickRecorder(std::size_t capacity, const CountingPort& port)
      : woke_(capacity, 0), done_(capacity, 0), port_(port) {}

  void record(bool on) noexcept { recording_.store(on, std::memory_order_release); }

  void tick(std::int64_t woke_late_ns, std::int64_t done_late_ns, bool overrun) noexcept override {
    const std::uint64_t r = port_.reads(), w = port_.writes();
    const std::uint64_t dr = r - last_reads_, dw = w - last_writes_;
    last_reads_ = r;
    last_writes_ = w;
    if (!recording_.load(std::memory_order_acquire)) return;
    if (count_ < woke_.size()) {
      woke_[count_] = clamp(woke_late_ns);
      done_[count_] = clamp(done_late_ns);
      ++count_;
    }
    overruns_ += overrun ? 1 : 0;
    reads_ += dr;
    writes_ += dw;
    max_reads_ = std::max(max_reads_, dr);
    max_writes_ = std::max(max_writes_, dw);
  }

  // After the thread stopped: the samples (ns after the deadline).
  std::vector<std::int32_t> woke() const { return {woke_.begin(), woke_.begin() + static_cast<long>(count_)}; }
  std::vector<std::int32_t> done() const { return {done_.begin(), done_.begin() + static_cast<long>(count_)}; }
  std::uint64_t ticks() const { return count_; }
  std::uint64_t overruns() const { return overruns_; }
  std::uint64_t reads() const { return reads_; }
  std::uint64_t writes() const { return writes_; }
  std::uint64_t max_reads() const { return max_reads_; }
  std::uint64_t max_writes() const { return max_writes_; }

 private:
  static std::int32_t clamp(std::int64_t ns) noexcept {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(ns, INT32_MIN, INT32_MAX));
  }
  std::vector<std::int32_t> woke_, done_;
  const CountingPort& port_;
  std::atomic<bool> recording_{false};
  std::size_t count_ = 0;
  std::uint64_t overruns_ = 0, reads_ = 0, writes_ = 0, max_reads_ = 0, max_writes_ = 0;
  std::uint64_t last_reads_ = 0, last_writes_ = 0;
};

}  // namespace imess::bench
