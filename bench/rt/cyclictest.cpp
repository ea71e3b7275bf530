// Runs cyclictest as a child process and parses its histogram output:
//   "000012 000345" per bucket (µs, count), then "# Max Latencies: 00031",
//   "# Histogram Overflows: 00000" (wake-ups past the histogram's range).
#include "cyclictest.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <thread>
#include <vector>

#include "imess/core/latency_histogram.hpp"
#include "thread_sched.hpp"

namespace imess::bench {

std::string Cyclictest::find() {
  const char* path = std::getenv("PATH");
  std::stringstream dirs(path ? path : "/usr/bin:/bin:/usr/sbin:/sbin");
  std::string dir;
  while (std::getline(dirs, dir, ':')) {
    const std::string candidate = (dir.empty() ? "." : dir) + "/cyclictest";
    if (access(candidate.c_str(), X_OK) == 0) return candidate;
  }
  return "";
}

bool Cyclictest::start(const std::string& binary, double interval_us, int priority, double seconds,
                       const std::string& work_dir) {
  priority_ = priority;
  out_path_ = work_dir + "/cyclictest.out";
  err_path_ = work_dir + "/cyclictest.err";
  // Histogram range: messd's (latency_bucket: 0 … 5000 µs, the last bucket everything longer).
  const int range = static_cast<int>(core::kLatencyBuckets) - 1;
  // -q: only the summary; -m: mlockall as messd; --default-system: leave power management as
  // messd meets it (cyclictest would otherwise hold /dev/cpu_dma_latency at 0 for the whole
  // machine, messd too, while it runs). -D: a duration, not a count of wake-ups: a thread
  // that misses periods skips them, and a count would then take longer than the seconds.
  std::vector<std::string> args{binary, "-q", "-m", "--default-system", "--policy=fifo",
                                "-p", std::to_string(priority), "-i", std::to_string(std::lround(interval_us)),
                                "-D", std::to_string(std::lround(seconds)), "-h", std::to_string(range)};
  command_.clear();
  for (const auto& a : args) command_ += (command_.empty() ? "" : " ") + a;
  pid_ = fork();
  if (pid_ < 0) {
    error_ = "fork failed";
    return false;
  }
  if (pid_ == 0) {
    const int out = open(out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int err = open(err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (out >= 0) dup2(out, STDOUT_FILENO);
    if (err >= 0) dup2(err, STDERR_FILENO);
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    execv(binary.c_str(), argv.data());
    _exit(127);
  }
  return true;
}

void Cyclictest::check_priority() {
  if (pid_ > 0 && has_fifo_thread(pid_, priority_)) priority_seen_ = true;
}

bool Cyclictest::finish(double timeout_s) {
  if (pid_ <= 0) return false;
  int st = 0;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(timeout_s);
  while (waitpid(pid_, &st, WNOHANG) == 0) {
    if (std::chrono::steady_clock::now() > deadline) {
      kill(pid_, SIGKILL);
      waitpid(pid_, &st, 0);
      pid_ = -1;
      error_ = "cyclictest did not end within " + std::to_string(static_cast<int>(timeout_s)) + " s";
      return false;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  pid_ = -1;
  std::ifstream out(out_path_);
  std::string line;
  long overflows = 0;
  bool any = false;
  while (std::getline(out, line)) {
    long us = 0, count = 0;
    if (line.rfind("# Max Latencies:", 0) == 0) {
      max_us_ = std::atoi(line.c_str() + 16);
    } else if (line.rfind("# Histogram Overflows:", 0) == 0) {
      overflows = std::atol(line.c_str() + 22);
    } else if (line[0] != '#' && std::sscanf(line.c_str(), "%ld %ld", &us, &count) == 2) {
      any = true;
      if (count > 0) histogram_.add(static_cast<double>(us), static_cast<std::uint32_t>(count));
    }
  }
  if (overflows > 0) histogram_.add(static_cast<double>(core::kLatencyBuckets), static_cast<std::uint32_t>(overflows));
  histogram_.set_max(max_us_);
  if (!any || !WIFEXITED(st) || WEXITSTATUS(st) != 0) {
    std::ifstream err(err_path_);
    std::stringstream text;
    text << err.rdbuf();
    std::string e = text.str();
    while (!e.empty() && (e.back() == '\n' || e.back() == ' ')) e.pop_back();
    for (auto& ch : e)
      if (ch == '\n') ch = ' ';  // one line: it is printed in place of the figures
    error_ = "cyclictest " + std::string(WIFEXITED(st) ? "exited with " + std::to_string(WEXITSTATUS(st))
                                                         : "was killed by signal " + std::to_string(WTERMSIG(st))) +
             (e.empty() ? "" : ": " + e.substr(0, 300));
    return false;
  }
  return true;
}

}  // namespace imess::bench
