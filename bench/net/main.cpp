// bench_net: the network figures of messd, each against bench_echo (the loopback floor) in
// the same run. Prints one line per figure; --json FILE writes them (docs/performance.md).
#include <csignal>
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "context.hpp"
#include "figures.hpp"
#include "options.hpp"
#include "report.hpp"

using namespace imess::bench;

int main(int argc, char** argv) {
  Options options;
  try {
    options = parse_options(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const UsageError& e) {
    std::fprintf(stderr, "bench_net: %s\n", e.what());
    return 2;
  }
  if (options.help) {
    std::fputs(usage_text().c_str(), stdout);
    return 0;
  }
  // A reader of stdout that went away (`| head`) must not kill bench_net before it stops its
  // servers and writes its JSON: the write fails instead.
  std::signal(SIGPIPE, SIG_IGN);
  Report report(options.quick);
  std::unique_ptr<Context> context;
  try {
    context = std::make_unique<Context>(options, report);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_net: %s\n", e.what());
    return 1;
  }
  const std::vector<std::pair<std::string, void (*)(Context&)>> runners{
      {"push", run_push}, {"stream", run_stream}, {"jog", run_jog}, {"rtt", run_rtt}, {"memory", run_memory}, {"load", run_load}, {"scan", run_scan}};
  int failed = 0;
  for (const auto& [name, run] : runners) {
    if (options.command != name && !(options.command == "all" && name != "load")) continue;
    try {
      run(*context);
    } catch (const std::exception& e) {
      // The figures measured so far stay; this command's missing ones are said in a figure of
      // its own, and the next command of `all` still runs.
      ++failed;
      std::fprintf(stderr, "bench_net %s: %s\n", name.c_str(), e.what());
      if (const auto log = context->last_messd_log(); !log.empty()) std::fprintf(stderr, "bench_net: the end of messd's log:\n%s\n", log.c_str());
      report.add({name + ".failed", name + " could not finish", name + " stopped before all its figures: " + e.what(), std::nullopt, "", "",
                  std::nullopt, std::nullopt});
    }
  }
  if (!options.json.empty()) {
    try {
      report.write_json(options.json);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_net: %s\n", e.what());
      return 1;
    }
  }
  // Exit 1 only when nothing could be measured at all (the bench contract).
  return report.measured() ? 0 : 1;
}
