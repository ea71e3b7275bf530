// bench_rt loop: messd's motion-loop wake-up latency over exactly S seconds (Stats Reset,
// then Stats Hist), against cyclictest at messd's period and the loop's SCHED_FIFO priority,
// idle and while a load command runs against messd. cyclictest runs at the same time as messd
// (not after it): both then meet the same background load second by second on a shared
// machine, the same power-management state and the same load command; on a machine with a
// single core the two threads would delay each other (bench_rt says so).
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <memory>
#include <thread>

#include "background_command.hpp"
#include "cyclictest.hpp"
#include "daemon_process.hpp"
#include "imess/core/loop_runner.hpp"
#include "latency_figures.hpp"
#include "measurements.hpp"

namespace imess::bench {

namespace {
using Clock = std::chrono::steady_clock;

// Reads and drops what messd sends for `seconds` (a client that stops reading is dropped).
void drain_for(test::LineClient& c, double seconds) {
  const auto end = Clock::now() + std::chrono::duration<double>(seconds);
  for (auto left = end - Clock::now(); left.count() > 0; left = end - Clock::now())
    c.next(std::min(0.2, std::chrono::duration<double>(left).count()));
}

// The value after `name` in a line of name-value pairs ("" when absent).
std::string field(const std::string& line, const std::string& name) {
  const std::string padded = line + " ";
  const auto at = padded.find(" " + name + " ");
  if (at == std::string::npos) return "";
  const auto start = at + name.size() + 2;
  return padded.substr(start, padded.find(' ', start) - start);
}

struct Interval {
  Histogram histogram;
  std::uint64_t cycles = 0, overruns = 0;
  std::string error;
};

// Stats Hist: "Stats Hist <us> <count>" lines, then "Ok Stats Hist Cycles n LatMax x Overruns n".
Interval read_interval(test::LineClient& c) {
  Interval r;
  c.send("Stats Hist");
  for (;;) {
    auto line = c.next(10.0);
    if (!line) {
      r.error = "no reply to Stats Hist";
      return r;
    }
    unsigned long us = 0, count = 0;
    if (std::sscanf(line->c_str(), "Stats Hist %lu %lu", &us, &count) == 2) {
      r.histogram.add(static_cast<double>(us), static_cast<std::uint32_t>(count));
    } else if (line->rfind("Ok Stats Hist ", 0) == 0) {
      r.cycles = std::stoull(field(*line, "Cycles"));
      r.overruns = std::stoull(field(*line, "Overruns"));
      r.histogram.set_max(std::stod(field(*line, "LatMax")));
      return r;
    } else if (line->rfind("Err ", 0) == 0) {
      r.error = "messd answered Stats Hist with '" + *line + "' (a messd without the measuring interval?)";
      return r;
    }
  }
}

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}
}  // namespace

bool run_loop(const Options& o, Report& report) {
  const double seconds = o.loop_seconds();
  TempDir work("imess-bench-rt");
  const std::string config = work.path() + "/messd.json";
  {
    std::ofstream out(config);
    out << R"({"server": {"max_clients": 250})";
    if (o.period_us) out << R"(, "motion": {"period_us": )" << *o.period_us << "}";
    out << "}\n";
  }
  std::unique_ptr<test::DaemonProcess> messd;
  try {
    messd = std::make_unique<test::DaemonProcess>(
        std::vector<std::string>{"--config", config, "--journal", work.path(), "--frames", work.path() + "/frames.json"},
        test::DaemonProcess::Scheduling::RealtimeIfPermitted, o.messd);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_rt: messd did not start (%s); set IMESS_TEST_DAEMON_LOG=1 to see its log\n", e.what());
    return false;
  }
  test::LineClient client(messd->port());
  // Stats Interval: the period and whether SCHED_FIFO was granted at once (plain Stats has
  // them only after its first once-a-second summary).
  const auto stats = client.request("Stats Interval");
  if (!stats || stats->rfind("Ok Stats Interval ", 0) != 0) {
    std::fprintf(stderr, "bench_rt: messd answered Stats Interval with '%s': this messd has no measuring interval\n",
                 stats ? stats->c_str() : "nothing");
    return false;
  }
  const double period_us = std::stod(field(*stats, "Period"));
  const bool realtime = field(*stats, "Realtime") == "yes";
  const int priority = core::LoopRunner::kPriority;
  const std::string cyclictest = o.cyclictest ? Cyclictest::find() : "";
  const std::string floor_missing = !o.cyclictest ? "--no-cyclictest" : "cyclictest not installed (Debian: rt-tests)";
  report.note("loop: messd on port " + std::to_string(messd->port()) + ", period " + fixed(period_us, 0) +
              " us, SCHED_FIFO " + std::to_string(priority) + " requested: Realtime " + (realtime ? "yes" : "no") +
              "; cyclictest at the same time, same period and priority: " + (cyclictest.empty() ? floor_missing : cyclictest) +
              "; " + fixed(seconds, 0) + " s per condition, wall clock");
  if (!realtime)
    report.note("loop: SCHED_FIFO was not granted to messd (not root, no CAP_SYS_NICE): its loop runs time-shared, "
                "and cyclictest, which needs SCHED_FIFO, will not run either");
  if (sysconf(_SC_NPROCESSORS_ONLN) < 2)
    report.note("loop: one CPU: messd's loop and cyclictest run at the same time and delay each other");
  auto& setup = report.setup()["loop"];
  setup["period_us"] = period_us;
  setup["priority"] = priority;
  setup["seconds"] = seconds;
  setup["messd_realtime"] = realtime;
  setup["concurrent"] = true;
  setup["cpus"] = sysconf(_SC_NPROCESSORS_ONLN);

  for (const std::string condition : {"idle", "loaded"}) {
    LatencySide measured{"rt.loop." + condition, "messd loop", nullptr, 0, "", {}};
    LatencySide floor{"floor.loop." + condition, "cyclictest -i " + fixed(period_us, 0) + " -p " + std::to_string(priority),
                      nullptr, 0, floor_missing, {}};
    std::unique_ptr<BackgroundCommand> load;
    if (condition == "loaded") {
      if (!o.load_cmd || o.load_cmd->empty()) {
        measured.unavailable = floor.unavailable = "no --load-cmd given";
        add_latency_figures(report, measured, floor, condition, true);
        continue;
      }
      const double warmup = o.quick ? 1 : 3;
      std::string cmd = substitute(*o.load_cmd, "port", std::to_string(messd->port()));
      cmd = substitute(cmd, "seconds", std::to_string(static_cast<int>(std::ceil(warmup + seconds + 10))));
      setup["load_cmd"] = cmd;
      report.note("loaded: " + cmd + " (started " + fixed(warmup, 0) + " s before the measurement)");
      load = std::make_unique<BackgroundCommand>(cmd, work.path() + "/load.log");
      drain_for(client, warmup);
      if (auto st = load->ended()) {
        measured.unavailable = floor.unavailable =
            "the load command ended before the measurement (status " + std::to_string(*st) + ")";
        report.note("loaded: the load command said: " + load->log_tail());
        add_latency_figures(report, measured, floor, condition, true);
        continue;
      }
    }
    Cyclictest ct;
    bool ct_running = false;
    if (!cyclictest.empty()) {
      ct_running = ct.start(cyclictest, period_us, priority, seconds, work.path());
      if (!ct_running) floor.unavailable = ct.error();
    }
    const auto reset = client.request("Stats Reset");
    if (reset != std::optional<std::string>("Ok Stats Reset")) {
      std::fprintf(stderr, "bench_rt: messd answered Stats Reset with '%s': this messd has no measuring interval\n",
                   reset ? reset->c_str() : "nothing");
      if (ct_running) ct.finish(seconds + 30);
      return false;
    }
    drain_for(client, std::min(0.5, seconds / 2));
    if (ct_running) ct.check_priority();
    drain_for(client, seconds - std::min(0.5, seconds / 2));
    Interval interval = read_interval(client);
    if (!interval.error.empty()) {
      std::fprintf(stderr, "bench_rt: %s\n", interval.error.c_str());
      if (ct_running) ct.finish(seconds + 30);
      return false;
    }
    measured.histogram = &interval.histogram;
    measured.overruns = interval.overruns;
    std::string load_said;
    if (load) {
      if (auto st = load->ended()) load_said = "; the load command had ended (status " + std::to_string(*st) + ") before the interval did";
      load->stop();
    }
    if (ct_running) {
      if (ct.finish(seconds + 30)) {
        floor.histogram = &ct.histogram();
        floor.overruns = ct.histogram().at_least(period_us);  // a thread without work overruns when a period late
      } else {
        floor.unavailable = ct.error();
      }
    }
    report.note(condition + ": messd " + std::to_string(interval.cycles) + " cycles; " +
                (floor.histogram ? "cyclictest " + std::to_string(ct.histogram().count()) + " wake-ups, SCHED_FIFO " +
                                       std::to_string(priority) + (ct.priority_seen() ? " seen" : " NOT seen") +
                                       " on its thread"
                                 : "cyclictest: " + floor.unavailable) +
                load_said);
    setup[condition]["messd_cycles"] = interval.cycles;
    setup[condition]["cyclictest_priority_seen"] = floor.histogram ? nlohmann::ordered_json(ct.priority_seen()) : nullptr;
    if (floor.histogram) setup["cyclictest"] = ct.command_line();
    add_latency_figures(report, measured, floor, condition, true);
  }
  return true;
}

}  // namespace imess::bench
