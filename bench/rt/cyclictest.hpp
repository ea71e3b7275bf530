// Cyclictest: the machine's floor — rt-tests' cyclictest run at a period and SCHED_FIFO
// priority for a number of wake-ups, its 1 µs histogram (-h) read back. Optional: when it
// is not installed the floor is "unavailable".
#pragma once
#include <sys/types.h>

#include <string>

#include "histogram.hpp"

namespace imess::bench {

class Cyclictest {
 public:
  static std::string find();  // its path on PATH, "" when not installed
  // Starts `cyclictest` for `seconds` (whole); output kept in work_dir.
  // false: could not start (error() says why).
  bool start(const std::string& binary, double interval_us, int priority, double seconds, const std::string& work_dir);
  // While it runs: looks whether its measuring thread has SCHED_FIFO at the priority.
  void check_priority();
  // Waits for it to end (killed after timeout_s) and reads the histogram; false: error().
  bool finish(double timeout_s);

  const Histogram& histogram() const { return histogram_; }
  int max_us() const { return max_us_; }         // cyclictest's own "Max Latencies" (whole µs, truncated)
  bool priority_seen() const { return priority_seen_; }
  const std::string& error() const { return error_; }
  std::string command_line() const { return command_; }

 private:
  pid_t pid_ = -1;
  int priority_ = 0;
  bool priority_seen_ = false;
  Histogram histogram_;
  int max_us_ = 0;
  std::string out_path_, err_path_, error_, command_;
};

}  // namespace imess::bench
