// EventSignal: how the motion loop tells the io side "events are waiting" without waiting
// itself. The core calls notify() at the end of a cycle that pushed events; the default does
// nothing (tests in virtual time pop the ring themselves).
#pragma once

namespace imess::core {

class EventSignal {
 public:
  virtual ~EventSignal() = default;
  // Real-time: called from cycle(); must not allocate, lock, log, throw or block.
  virtual void notify() noexcept {}
};

}  // namespace imess::core
