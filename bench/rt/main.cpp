// bench_rt: real-time figures of messd against the machine's own floor (cyclictest at the
// same period and priority, in the same run): the motion loop's wake-up latency idle and
// loaded, and the step/dir base thread's jitter, the step rate it allows and a tick's cost.
// Wall clock throughout. Prints one line per figure; --json writes them (bench contract).
#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "measurements.hpp"
#include "options.hpp"
#include "report.hpp"

int main(int argc, char** argv) {
  using namespace imess::bench;
  const auto options = parse_options(argc, argv);
  if (!options) return 2;
  Report report("rt", options->quick);
  report.setup()["wall_clock"] = true;
  bool ok = true;
  try {
    if (options->loop) ok = run_loop(*options, report) && ok;
    if (options->base) ok = run_base(*options, report) && ok;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_rt: %s\n", e.what());
    ok = false;
  }
  if (!options->json.empty() && !report.write(options->json)) return 1;
  return ok ? 0 : 1;
}
