// BaseThread: runs a driver's base-period routine (step pulse making) in its own thread
// with absolute deadlines, SCHED_FIFO above the motion loop when permitted; counts
// overruns. Used with real port hardware; the simulator runs the routine in virtual time.
// A BaseTickObserver attached before start() sees every tick's wake-up and end (bench_rt).
#pragma once
#include <atomic>
#include <string>
#include <thread>

#include "base_tick_observer.hpp"
#include "imess/hal/base_rate.hpp"

namespace imess::app {

class BaseThread {
 public:
  static constexpr int kPriority = 85;  // SCHED_FIFO, above the motion loop (LoopRunner::kPriority)
  explicit BaseThread(hal::BaseRateDriver& driver) : driver_(driver) {}
  ~BaseThread() { stop(); }
  BaseThread(const BaseThread&) = delete;
  BaseThread& operator=(const BaseThread&) = delete;

  // Starts the thread; returns what real-time support was granted, in words.
  std::string start(bool want_realtime);
  // Before start(): every tick is reported to `observer` (null: none, as in messd).
  void observe(BaseTickObserver* observer) noexcept { observer_ = observer; }
  void stop();
  unsigned long overruns() const noexcept { return overruns_.load(std::memory_order_relaxed); }
  unsigned long ticks() const noexcept { return ticks_.load(std::memory_order_relaxed); }

 private:
  void run() noexcept;
  hal::BaseRateDriver& driver_;
  BaseTickObserver* observer_ = nullptr;
  std::atomic<bool> running_{false};
  std::atomic<unsigned long> overruns_{0}, ticks_{0};
  std::thread thread_;
};

}  // namespace imess::app
