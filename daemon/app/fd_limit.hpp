// Room for every client's socket under the process's descriptor limit (RLIMIT_NOFILE):
// with max_clients above it, accept() would fail on every call instead of refusing politely.
#pragma once
#include <cstddef>
#include <string>

namespace imess::app {

inline constexpr std::size_t kOtherDescriptors = 64;  // files, pipes, timers, epoll, the listener, ports

struct FdLimitResult {
  std::size_t max_clients;  // possibly lowered
  std::string message;      // for the log; empty when nothing had to change
  bool lowered = false;     // max_clients had to be lowered (a warning)
};

// Pure arithmetic, for the tests: what to do with these limits.
FdLimitResult plan_fd_limit(std::size_t max_clients, unsigned long soft, unsigned long hard, unsigned long& new_soft);

// Raises the soft limit if needed and allowed, else lowers max_clients.
FdLimitResult fit_fd_limit(std::size_t max_clients);

}  // namespace imess::app
