// Locking the process's memory for a real-time loop (mlockall), only where every later
// allocation stays possible: as root, or with no RLIMIT_MEMLOCK. Under a limit, locking
// succeeds while the process is small and later allocations (a client's buffers, a thread's
// stack) then fail with EAGAIN — worse than page faults.
#pragma once

#include <string>

namespace imess::core {

struct MemoryLock {
  bool locked = false;
  std::string note;  // what was done and why, for the start-up log
};

MemoryLock lock_memory();

}  // namespace imess::core
