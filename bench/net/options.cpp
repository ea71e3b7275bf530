// Parsing bench_net's command line, with the accepted forms in every error.
#include "options.hpp"

#include <charconv>
#include <cmath>
#include <map>
#include <set>

namespace imess::bench {

namespace {
const std::set<std::string> kCommands{"push", "stream", "jog", "rtt", "memory", "load", "scan", "all"};

// The options each subcommand takes besides the common ones.
const std::map<std::string, std::set<std::string>> kOwn{
    {"push", {"--samples"}},
    {"stream", {"--seconds", "--clients"}},
    {"jog", {"--samples"}},
    {"rtt", {"--samples"}},
    {"memory", {"--soak-seconds"}},
    {"load", {"--seconds", "--clients", "--lines-per-s"}},
    {"scan", {"--samples"}},
    {"all", {"--samples", "--seconds", "--soak-seconds"}},
};
const std::set<std::string> kCommon{"--json", "--quick", "--messd", "--echo", "--port", "--pid", "--seed", "--rt", "--help", "-h"};

double number(const std::string& option, const std::string& text, double lo, double hi, bool whole) {
  double v = 0;
  const char* end = text.data() + text.size();
  auto [p, ec] = std::from_chars(text.data(), end, v);
  const bool ok = ec == std::errc() && p == end && std::isfinite(v) && v >= lo && v <= hi && (!whole || v == std::floor(v));
  if (!ok) {
    char range[96];
    std::snprintf(range, sizeof range, whole ? "a whole number from %.0f to %.0f" : "a number from %g to %g", lo, hi);
    throw UsageError(option + " takes " + range + ", got '" + text + "'");
  }
  return v;
}
}  // namespace

std::string usage_text() {
  return R"(usage: bench_net COMMAND [options]
Network figures of messd, each against bench_echo (the loopback floor) in the same run.
commands:
  push     ForcePt -> MeasPt at all of N clients (N 1 10 100 1000; quick 1 10 100),
           probe trigger (Hit t) -> Hit/MeasPt at all of 100 clients
  stream   200 clients at ReportHz 100 while the owner jogs: per-client CurrCor rate, messd CPU
  jog      StartMv from rest -> first changed CurrCor at the jogging client, ReportHz 10 and 100
  rtt      Status round trip vs the echo round trip
  memory   messd RSS with 0, 100, 1000 clients, then clients churning for --soak-seconds
  load     a load generator: --clients idle clients, one sending --lines-per-s lines for --seconds
  scan     a scan's points (1000/s, a measuring probe) -> Scan lines at all of 100 clients
  all      push stream jog rtt memory scan
options (all commands):
  --json FILE        write the results as JSON
  --quick            fewer samples, shorter windows, push without 1000 clients; the same
                     figure ids (all: about 30 s)
  --messd PATH       the messd to start (default: messd beside this program)
  --echo PATH        the bench_echo to start (default: bench_echo beside this program)
  --port P --pid PID use a messd already running on 127.0.0.1:P (PID for CPU and memory)
  --seed N           seed of the random phases (default 1)
  --rt               let the started messd take SCHED_FIFO and mlockall (default: --no-rt)
options of some commands:
  --samples N        samples per latency figure (push, jog, rtt, scan)
  --seconds S        stream: the measuring window (default 30, quick 2); load: duration (default 10)
  --clients N        stream: clients (default 200); load: idle clients (default 100)
  --lines-per-s R    load: command lines a second from the sending client (default 10000)
  --soak-seconds T   memory: the churn run (default 600, quick 4)
)";
}

Options parse_options(const std::vector<std::string>& args) {
  Options o;
  if (args.empty()) throw UsageError("no command given; accepted: push stream jog rtt memory load scan all (--help shows the options)");
  std::size_t i = 0;
  if (args[0] == "--help" || args[0] == "-h") {
    o.help = true;
    return o;
  }
  o.command = args[i++];
  if (!kCommands.count(o.command))
    throw UsageError("unknown command '" + o.command + "'; accepted: push stream jog rtt memory load scan all");
  const auto& own = kOwn.at(o.command);
  bool seen_port = false;
  while (i < args.size()) {
    const std::string a = args[i++];
    if (!kCommon.count(a) && !own.count(a)) {
      std::string accepted;
      for (const auto& s : kCommon) accepted += " " + s;
      for (const auto& s : own) accepted += " " + s;
      throw UsageError("'" + o.command + "' does not take '" + a + "'; it takes" + accepted);
    }
    auto value = [&](const std::string& what) -> std::string {
      if (i >= args.size()) throw UsageError(a + " needs " + what);
      return args[i++];
    };
    if (a == "--help" || a == "-h") o.help = true;
    else if (a == "--quick") o.quick = true;
    else if (a == "--rt") o.realtime = true;
    else if (a == "--json") o.json = value("a file name");
    else if (a == "--messd") o.messd = value("the path of a messd executable");
    else if (a == "--echo") o.echo = value("the path of a bench_echo executable");
    else if (a == "--port") {
      o.port = static_cast<int>(number(a, value("a port"), 1, 65535, true));
      seen_port = true;
    } else if (a == "--pid") o.pid = static_cast<int>(number(a, value("a process id"), 1, 4194304, true));
    else if (a == "--seed") o.seed = static_cast<unsigned>(number(a, value("a number"), 0, 4294967295.0, true));
    else if (a == "--samples") o.samples = static_cast<int>(number(a, value("a count"), 1, 1000000, true));
    else if (a == "--seconds") o.seconds = number(a, value("a duration in seconds"), 0.5, 86400, false);
    else if (a == "--soak-seconds") o.soak_seconds = number(a, value("a duration in seconds"), 2, 604800, false);
    else if (a == "--clients") o.clients = static_cast<int>(number(a, value("a count"), 1, 10000, true));
    else if (a == "--lines-per-s") o.lines_per_s = number(a, value("a rate"), 1, 1000000, false);
  }
  if (o.pid && !seen_port) throw UsageError("--pid names a running messd and needs its --port");
  if (seen_port && !o.messd.empty()) throw UsageError("--port uses a running messd; --messd starts one: give one of them");
  return o;
}

}  // namespace imess::bench
