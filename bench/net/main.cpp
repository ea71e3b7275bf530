// bench_net: the network figures of messd, each against bench_echo (the loopback floor) in
// the same run. Prints one line per figure; --json FILE writes them (docs/performance.md).
#include <cstdio>
#include <exception>
#include <memory>
#include <string>
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
  Report report(options.quick);
  std::unique_ptr<Context> context;
  try {
    context = std::make_unique<Context>(options, report);
    Context& ctx = *context;
    const std::string& c = options.command;
    if (c == "push" || c == "all") run_push(ctx);
    if (c == "stream" || c == "all") run_stream(ctx);
    if (c == "jog" || c == "all") run_jog(ctx);
    if (c == "rtt" || c == "all") run_rtt(ctx);
    if (c == "memory" || c == "all") run_memory(ctx);
    if (c == "load") run_load(ctx);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_net %s: %s\n", options.command.c_str(), e.what());
    if (context && !context->last_messd_log().empty())
      std::fprintf(stderr, "bench_net: the end of messd's log:\n%s\n", context->last_messd_log().c_str());
    if (report.empty()) return 1;  // nothing measured: could not run at all
    std::fprintf(stderr, "bench_net: the figures before the failure are kept\n");
    if (!options.json.empty()) {
      try {
        report.write_json(options.json);
      } catch (const std::exception& w) {
        std::fprintf(stderr, "bench_net: %s\n", w.what());
      }
    }
    return 1;
  }
  if (!options.json.empty()) {
    try {
      report.write_json(options.json);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "bench_net: %s\n", e.what());
      return 1;
    }
  }
  return 0;
}
