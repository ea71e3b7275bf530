// bench_rt's command line.
#pragma once
#include <optional>
#include <string>

namespace imess::bench {

struct Options {
  bool loop = false, base = false;  // what to measure (`all`: both)
  bool quick = false;
  std::optional<double> seconds;     // S of every part, whole seconds (default: loop 60 / quick 3, base 60 / quick 2)
  std::string json;                  // --json FILE
  std::string messd;                 // --messd PATH ("" the build's)
  std::optional<std::string> load_cmd;  // --load-cmd "... {port} ... {seconds}" ("" no loaded run)
  std::optional<double> period_us;   // --period-us: messd's motion.period_us (default: messd's own)
  double step_len_us = 5, step_space_us = 5;  // the drive's minimum step length and space
  bool cyclictest = true;            // --no-cyclictest: measure messd alone (floor unavailable)

  double loop_seconds() const { return seconds.value_or(quick ? 3 : 60); }
  double base_seconds() const { return seconds.value_or(quick ? 2 : 60); }
};

// Parses argv; on a bad command line prints the usage to stderr and returns nullopt.
std::optional<Options> parse_options(int argc, char** argv);

}  // namespace imess::bench
