#include "imess/core/memory_lock.hpp"

#include <sys/mman.h>
#include <sys/resource.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <string>

namespace imess::core {
namespace {
// CAP_IPC_LOCK (bit 14) in the effective set: locking is then not bounded by RLIMIT_MEMLOCK
// (root, or `setcap cap_ipc_lock+ep messd`).
bool may_lock_unbounded() {
  std::ifstream status("/proc/self/status");
  for (std::string line; std::getline(status, line);)
    if (line.rfind("CapEff:", 0) == 0) return (std::stoull(line.substr(7), nullptr, 16) >> 14) & 1u;
  return geteuid() == 0;
}
}  // namespace

MemoryLock lock_memory() {
  rlimit limit{};
  const bool unlimited = getrlimit(RLIMIT_MEMLOCK, &limit) == 0 && limit.rlim_cur == RLIM_INFINITY;
  if (!unlimited && !may_lock_unbounded())
    return {false, "memory not locked: no CAP_IPC_LOCK and RLIMIT_MEMLOCK is " + std::to_string(limit.rlim_cur / 1024) +
                       " KiB (locking under a limit makes later allocations fail); pages may fault in the loop"};
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0)
    return {false, std::string("mlockall not permitted (") + std::strerror(errno) + "): pages may fault in the loop"};
  return {true, "memory locked (mlockall)"};
}

}  // namespace imess::core
