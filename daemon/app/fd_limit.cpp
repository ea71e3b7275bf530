// Raise RLIMIT_NOFILE's soft limit to what max_clients needs, or cap max_clients to it.
#include "fd_limit.hpp"

#include <sys/resource.h>

namespace imess::app {

FdLimitResult plan_fd_limit(std::size_t max_clients, unsigned long soft, unsigned long hard, unsigned long& new_soft) {
  const unsigned long needed = max_clients + kOtherDescriptors;
  new_soft = soft;
  if (soft >= needed) return {max_clients, {}};
  if (hard >= needed) {
    new_soft = needed;
    return {max_clients, "descriptor limit raised from " + std::to_string(soft) + " to " + std::to_string(needed) +
                             " for " + std::to_string(max_clients) + " clients"};
  }
  new_soft = hard;
  std::size_t fit = hard > kOtherDescriptors ? hard - kOtherDescriptors : 1;
  return {fit,
          "max_clients lowered from " + std::to_string(max_clients) + " to " + std::to_string(fit) +
              ": the descriptor limit (RLIMIT_NOFILE, hard " + std::to_string(hard) + ") leaves room for no more; raise it "
              "(ulimit -n, LimitNOFILE= in a systemd unit) to serve more",
          true};
}

FdLimitResult fit_fd_limit(std::size_t max_clients) {
  rlimit lim{};
  if (getrlimit(RLIMIT_NOFILE, &lim) != 0) return {max_clients, {}};
  unsigned long new_soft = 0;
  auto hard = lim.rlim_max == RLIM_INFINITY ? ~0ul : static_cast<unsigned long>(lim.rlim_max);
  auto result = plan_fd_limit(max_clients, static_cast<unsigned long>(lim.rlim_cur), hard, new_soft);
  if (new_soft != lim.rlim_cur) {
    const auto soft = static_cast<unsigned long>(lim.rlim_cur);
    lim.rlim_cur = new_soft;
    if (setrlimit(RLIMIT_NOFILE, &lim) != 0)
      result = plan_fd_limit(max_clients, soft, soft, new_soft);  // cannot raise: fit into what we have
  }
  return result;
}

}  // namespace imess::app
