// Reads the policy and real-time priority of a process's threads from /proc.
#include "thread_sched.hpp"

#include <sched.h>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace imess::bench {

std::vector<ThreadSched> threads_of(pid_t pid) {
  std::vector<ThreadSched> out;
  std::error_code ec;
  const std::filesystem::path tasks = "/proc/" + std::to_string(pid) + "/task";
  for (const auto& entry : std::filesystem::directory_iterator(tasks, ec)) {
    ThreadSched t;
    t.tid = static_cast<pid_t>(std::stol(entry.path().filename().string()));
    std::ifstream(entry.path() / "comm") >> t.name;
    std::string stat;
    std::getline(std::ifstream(entry.path() / "stat"), stat);
    const auto close = stat.rfind(')');  // the name may hold blanks and parentheses
    if (close == std::string::npos) continue;
    std::istringstream fields(stat.substr(close + 2));
    std::string f;
    // After "(comm) " comes field 3 (state); rt_priority is field 40, policy field 41.
    for (int n = 3; n <= 41 && fields >> f; ++n) {
      if (n == 40) t.rt_priority = std::stoi(f);
      if (n == 41) t.policy = std::stoi(f);
    }
    out.push_back(t);
  }
  return out;
}

bool has_fifo_thread(pid_t pid, int priority, const std::string& name) {
  for (const auto& t : threads_of(pid))
    if ((name.empty() || t.name == name) && t.policy == SCHED_FIFO && t.rt_priority == priority) return true;
  return false;
}

}  // namespace imess::bench
