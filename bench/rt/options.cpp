// bench_rt's command line: a subcommand, then options.
#include "options.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string_view>

namespace imess::bench {

namespace {
const char* kUsage =
    "usage: bench_rt loop|base|all [--quick] [--seconds S] [--json FILE] [--messd PATH]\n"
    "                [--load-cmd \"CMD {port} {seconds}\"] [--period-us N] [--step-len-us U] [--step-space-us U]\n"
    "                [--no-cyclictest]\n"
    "  loop  messd's motion-loop wake-up latency against cyclictest at the same period and priority,\n"
    "        idle and while --load-cmd runs against messd (S: 60 s, --quick 3 s)\n"
    "  base  the step/dir base thread's wake-up jitter at 25 and 50 us against cyclictest, the step\n"
    "        rate it allows and the cost of a base tick (S: 60 s, --quick 2 s)\n"
    "  all   both\n";

bool number(const char* text, double& out) {
  char* end = nullptr;
  out = std::strtod(text, &end);
  return end != text && *end == '\0' && out > 0;
}
}  // namespace

std::optional<Options> parse_options(int argc, char** argv) {
  Options o;
  auto fail = [](const std::string& why) -> std::optional<Options> {
    std::fprintf(stderr, "bench_rt: %s\n%s", why.c_str(), kUsage);
    return std::nullopt;
  };
  if (argc < 2) return fail("which measurement? loop, base or all");
  const std::string_view what = argv[1];
  if (what == "-h" || what == "--help") {
    std::printf("%s", kUsage);
    std::exit(0);
  }
  if (what == "loop") o.loop = true;
  else if (what == "base") o.base = true;
  else if (what == "all") o.loop = o.base = true;
  else return fail("unknown measurement '" + std::string(what) + "'");
  for (int i = 2; i < argc; ++i) {
    const std::string_view a = argv[i];
    auto value = [&]() -> const char* { return i + 1 < argc ? argv[++i] : nullptr; };
    double v = 0;
    if (a == "--quick") {
      o.quick = true;
    } else if (a == "--no-cyclictest") {
      o.cyclictest = false;
    } else if (a == "--seconds" || a == "--period-us" || a == "--step-len-us" || a == "--step-space-us") {
      const char* t = value();
      if (!t || !number(t, v)) return fail(std::string(a) + " takes a positive number");
      if (a == "--seconds" && v != std::floor(v)) return fail("--seconds takes whole seconds (cyclictest's -D)");
      if (a == "--seconds") o.seconds = v;
      else if (a == "--period-us") o.period_us = v;
      else if (a == "--step-len-us") o.step_len_us = v;
      else o.step_space_us = v;
    } else if (a == "--json" || a == "--messd" || a == "--load-cmd") {
      const char* t = value();
      if (!t) return fail(std::string(a) + " takes a value");
      if (a == "--json") o.json = t;
      else if (a == "--messd") o.messd = t;
      else o.load_cmd = t;
    } else {
      return fail("unknown option '" + std::string(a) + "'");
    }
  }
  return o;
}

}  // namespace imess::bench
