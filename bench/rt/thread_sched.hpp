// The scheduling each thread of a process actually has (/proc/PID/task/TID/stat and comm):
// how bench_rt tells whether messd's loop and cyclictest's thread got SCHED_FIFO at their priority.
#pragma once
#include <sys/types.h>

#include <string>
#include <vector>

namespace imess::bench {

struct ThreadSched {
  pid_t tid = 0;
  std::string name;
  int policy = 0;       // SCHED_OTHER 0, SCHED_FIFO 1, SCHED_RR 2
  int rt_priority = 0;  // 1–99 under SCHED_FIFO / SCHED_RR
};

std::vector<ThreadSched> threads_of(pid_t pid);
// Whether a thread of `pid` (named `name`, or any when empty) runs SCHED_FIFO at `priority`.
bool has_fifo_thread(pid_t pid, int priority, const std::string& name = "");

}  // namespace imess::bench
