// /proc/<pid>/stat, /proc/<pid>/task/*/stat and comm, /proc/<pid>/status readers.
#include "proc_stats.hpp"

#include <sys/resource.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

namespace imess::bench {

namespace {
// utime + stime (fields 14 and 15) of a stat file, in seconds. The name (field 2) may hold
// blanks and parentheses, so the fields are counted after its last ')'.
std::optional<double> stat_cpu_s(const std::string& path) {
  std::ifstream f(path);
  std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
  const auto close = text.rfind(')');
  if (text.empty() || close == std::string::npos) return std::nullopt;
  std::istringstream fields(text.substr(close + 1));
  std::vector<std::string> v;
  for (std::string w; fields >> w;) v.push_back(w);
  if (v.size() < 13) return std::nullopt;  // v[0] is field 3 (state): utime v[11], stime v[12]
  const double ticks = std::stod(v[11]) + std::stod(v[12]);
  return ticks / static_cast<double>(sysconf(_SC_CLK_TCK));
}

std::string first_line(const std::string& path) {
  std::ifstream f(path);
  std::string line;
  std::getline(f, line);
  return line;
}
}  // namespace

std::optional<double> process_cpu_s(int pid) {
  if (pid <= 0) return std::nullopt;
  return stat_cpu_s("/proc/" + std::to_string(pid) + "/stat");
}

namespace {
// Sums `value(task directory)` over the threads of `pid` named `name` (or, with `except`, all
// the others); nullopt when the process is gone.
template <typename Value>
std::optional<double> sum_over_threads(int pid, const std::string& name, bool except, Value value) {
  if (pid <= 0) return std::nullopt;
  std::error_code ec;
  std::filesystem::directory_iterator it("/proc/" + std::to_string(pid) + "/task", ec);
  if (ec) return std::nullopt;
  double sum = 0;
  for (const auto& task : it) {
    const bool named = first_line(task.path().string() + "/comm") == name;
    if (named == except) continue;
    if (auto v = value(task.path().string())) sum += *v;
  }
  return sum;
}
}  // namespace

std::optional<double> threads_cpu_s(int pid, const std::string& name, bool except) {
  return sum_over_threads(pid, name, except, [](const std::string& task) { return stat_cpu_s(task + "/stat"); });
}

std::optional<double> threads_wakeups(int pid, const std::string& name, bool except) {
  return sum_over_threads(pid, name, except, [](const std::string& task) -> std::optional<double> {
    std::ifstream f(task + "/status");
    for (std::string line; std::getline(f, line);)
      if (line.rfind("voluntary_ctxt_switches:", 0) == 0) return std::stod(line.substr(24));
    return std::nullopt;
  });
}

std::optional<double> rss_kib(int pid) {
  if (pid <= 0) return std::nullopt;
  std::ifstream f("/proc/" + std::to_string(pid) + "/status");
  for (std::string line; std::getline(f, line);)
    if (line.rfind("VmRSS:", 0) == 0) return std::stod(line.substr(6));
  return std::nullopt;
}

double own_cpu_s() {
  rusage u{};
  getrusage(RUSAGE_SELF, &u);
  auto s = [](const timeval& t) { return static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_usec) / 1e6; };
  return s(u.ru_utime) + s(u.ru_stime);
}

}  // namespace imess::bench
