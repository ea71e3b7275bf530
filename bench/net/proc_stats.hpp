// What /proc says about a server process: CPU time (utime + stime, whole process or the
// threads of one name) and resident memory (VmRSS).
#pragma once
#include <cstdint>
#include <optional>
#include <string>

namespace imess::bench {

// Seconds of CPU (user + system) the process used so far; nullopt when /proc has no such pid.
std::optional<double> process_cpu_s(int pid);
// The same summed over the process' threads whose name (comm) is `name`, or over all threads
// except those when `except` is set.
std::optional<double> threads_cpu_s(int pid, const std::string& name, bool except);
// Voluntary context switches (a thread blocking: each is a sleep and a wake-up), summed as
// threads_cpu_s sums.
std::optional<double> threads_wakeups(int pid, const std::string& name, bool except);
// Resident set, KiB (VmRSS of /proc/<pid>/status).
std::optional<double> rss_kib(int pid);
// This program's own CPU seconds (getrusage), to show the clients were not the bottleneck.
double own_cpu_s();

// CPU % of one core between two readings: 100 * cpu seconds / wall seconds.
inline double cpu_percent(double cpu_s, double wall_s) { return wall_s > 0 ? 100.0 * cpu_s / wall_s : 0; }

}  // namespace imess::bench
