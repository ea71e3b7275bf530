// bench_net's command line: a subcommand and its options. A value out of range or an option
// the subcommand does not take is a UsageError saying what is accepted.
#pragma once
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace imess::bench {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Options {
  std::string command;  // push stream jog rtt memory load all
  std::string json;     // --json FILE
  bool quick = false;
  std::string messd;  // --messd PATH (default: messd beside bench_net)
  std::string echo;   // --echo PATH (default: bench_echo beside bench_net)
  int port = 0;       // --port P: use a running messd
  int pid = 0;        // --pid PID of it (CPU and memory figures)
  std::optional<int> samples;          // --samples N: per latency figure
  std::optional<double> seconds;       // --seconds S: stream window, load duration
  std::optional<double> soak_seconds;  // --soak-seconds T: memory churn
  std::optional<int> clients;          // --clients N: stream, load
  double lines_per_s = 10000;          // --lines-per-s R: load
  unsigned seed = 1;                   // --seed N: random phases
  bool realtime = false;               // --rt: messd may take SCHED_FIFO and mlockall
  bool help = false;
};

// Throws UsageError.
Options parse_options(const std::vector<std::string>& args);
std::string usage_text();

}  // namespace imess::bench
