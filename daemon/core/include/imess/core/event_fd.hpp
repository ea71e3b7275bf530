// EventFd: an EventSignal over a Linux eventfd. The loop's notify() is one non-blocking
// 8-byte write (a counter add in the kernel, no allocation); the io thread waits on fd().
#pragma once
#include <cstdint>

#include "imess/core/event_signal.hpp"

namespace imess::core {

class EventFd final : public EventSignal {
 public:
  EventFd();  // set-up: throws std::runtime_error when the kernel refuses an eventfd
  ~EventFd() override;
  EventFd(const EventFd&) = delete;
  EventFd& operator=(const EventFd&) = delete;

  // Real-time: adds 1 to the counter. A full counter (never in practice: the reader clears
  // it) makes the write fail with EAGAIN, which is fine: the reader is woken already.
  void notify() noexcept override;
  // io side: clears the counter; returns how many notifications it held (0: none).
  std::uint64_t drain() noexcept;
  int fd() const noexcept { return fd_; }

 private:
  int fd_ = -1;
};

}  // namespace imess::core
