// BaseTickObserver: what the base thread tells about each tick when one is attached (the
// benchmark bench_rt attaches one; messd does not): how late the thread woke and how late
// base_tick() returned, in ns after the tick's deadline. Called in the base thread:
// an implementation must be real-time (noexcept, no allocation, no lock, no system call).
#pragma once
#include <cstdint>

namespace imess::app {

class BaseTickObserver {
 public:
  virtual ~BaseTickObserver() = default;
  // overrun: the tick ended after the next deadline (that period is not caught up).
  virtual void tick(std::int64_t woke_late_ns, std::int64_t done_late_ns, bool overrun) noexcept = 0;
};

}  // namespace imess::app
