// bench_rt base: messd's step/dir base thread (app::BaseThread, SCHED_FIFO 85) running the
// parallel-port driver's base_tick() in wall clock at 25 and 50 us on the simulated port,
// three axes stepping at the pulse-timing limit, with a TickRecorder attached; cyclictest at
// the same period and priority at the same time. Figures: wake-up latency against
// cyclictest, the write jitter and the step rate it allows (step_rule.hpp), the tick's cost
// measured in the thread plus ~1 us per port access as a real port would take.
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <thread>

#include "base_thread.hpp"
#include "counting_port.hpp"
#include "cyclictest.hpp"
#include "imess/core/loop_runner.hpp"
#include "imess/core/memory_lock.hpp"
#include "imess/hal/parport_stepper_driver.hpp"
#include "latency_figures.hpp"
#include "measurements.hpp"
#include "step_rule.hpp"
#include "thread_sched.hpp"
#include "tick_recorder.hpp"

namespace imess::bench {

namespace {
using Clock = std::chrono::steady_clock;
constexpr double kPortAccessUs = 1.0;  // an in/out on an ISA-compatible parallel port
constexpr double kWarmupS = 0.2;       // after start: SCHED_FIFO is set once the thread runs

std::string fixed(double v, int decimals) {
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

// The q-quantile of raw samples (sorted ascending), by rank floor(q × (n − 1)).
double quantile(const std::vector<double>& sorted, double q) {
  if (sorted.empty()) return 0;
  return sorted[static_cast<std::size_t>(q * static_cast<double>(sorted.size() - 1))];
}

std::vector<double> sorted_us(const std::vector<std::int32_t>& ns) {
  std::vector<double> v(ns.begin(), ns.end());
  for (auto& x : v) x /= 1000;
  std::sort(v.begin(), v.end());
  return v;
}

// The driver on a private simulated port: step and space one base period each, three axes
// at the fastest rate that allows (1 / 2T), inputs all inactive.
struct SteppingDriver {
  hal::SharedPortSpace space{"", 0x378};
  CountingPort port{space};
  core::MonotonicClock clock;
  std::unique_ptr<hal::ParportStepperDriver> driver;
  double rate = 0;  // steps/s per axis

  SteppingDriver(double period_us, double seconds) {
    hal::ParportStepperConfig c;
    c.pins = *hal::named_pin_map("shd-adapter");
    c.base = 0x378;
    c.base_period_ns = period_us * 1000;
    c.step_len_ns = c.step_space_ns = c.dir_setup_ns = c.dir_hold_ns = period_us * 1000;
    rate = 1e6 / (2 * period_us);
    for (auto& a : c.axes) {
      a.steps_per_mm = 1000;
      a.max_speed = rate / 1000;
      a.max_accel = 1e6;
    }
    // No input active: the status register at the pins' inactive levels (STOP released).
    space.out8(c.base + 1, hal::compile_pins(c.pins).status_xor);
    driver = std::make_unique<hal::ParportStepperDriver>(port, clock, c);
    driver->initialise(false);
    driver->set_loops(true);
    hal::AxisArray<hal::AxisMove> m{};
    const double far = rate / 1000 * (seconds + 10);  // never arrives within the run
    for (int a = 0; a < 3; ++a) m[a] = {a == 1 ? -far : far, rate / 1000, 1e6};
    driver->move(m, 7);
  }
};

void measure(double period_us, const Options& o, const std::string& cyclictest, const std::string& floor_missing,
             const std::string& work, Report& report) {
  const double seconds = o.base_seconds();
  const int priority = app::BaseThread::kPriority;
  const std::string tag = fixed(period_us, 0);
  SteppingDriver rig(period_us, seconds + kWarmupS);
  TickRecorder recorder(static_cast<std::size_t>((seconds + 1) * 1e6 / period_us), rig.port);
  app::BaseThread thread(*rig.driver);
  thread.observe(&recorder);
  thread.start(true);
  hal::MachineState state;
  std::array<std::int64_t, 3> steps0{};
  // The servo side, as the motion loop would call it (here time-shared, from this thread).
  auto servo_for = [&](double s) {
    const auto end = Clock::now() + std::chrono::duration<double>(s);
    for (auto next = Clock::now() + std::chrono::milliseconds(1); next < end; next += std::chrono::milliseconds(1)) {
      std::this_thread::sleep_until(next);
      rig.driver->read_state(state);
    }
  };
  servo_for(kWarmupS);
  const bool fifo = has_fifo_thread(getpid(), priority, "messd-base");
  Cyclictest ct;
  bool ct_running = false;
  std::string floor_unavailable = floor_missing;
  if (!cyclictest.empty()) {
    ct_running = ct.start(cyclictest, period_us, priority, seconds, work);
    if (!ct_running) floor_unavailable = ct.error();
  }
  for (int a = 0; a < 3; ++a) steps0[a] = rig.driver->step_count(a);
  recorder.record(true);
  servo_for(std::min(0.5, seconds / 2));
  if (ct_running) ct.check_priority();
  servo_for(seconds - std::min(0.5, seconds / 2));
  recorder.record(false);
  std::array<std::int64_t, 3> steps{};
  for (int a = 0; a < 3; ++a) steps[a] = std::llabs(rig.driver->step_count(a) - steps0[a]);
  thread.stop();

  LatencySide measured{"rt.base." + tag, "base thread " + tag + " us", nullptr, recorder.overruns(), "", {}};
  LatencySide floor{"floor.base." + tag, "cyclictest -i " + tag + " -p " + std::to_string(priority), nullptr, 0,
                    floor_unavailable, {}};
  Histogram woke_hist;
  const auto woke = sorted_us(recorder.woke());
  for (double us : woke) woke_hist.add(us);
  measured.histogram = &woke_hist;
  measured.raw_samples_us = woke;
  if (ct_running) {
    if (ct.finish(seconds + 30)) {
      floor.histogram = &ct.histogram();
      floor.overruns = ct.histogram().at_least(period_us);
    } else {
      floor.unavailable = ct.error();
    }
  }
  report.note("base " + tag + " us: " + std::to_string(recorder.ticks()) + " ticks in " + fixed(seconds, 1) +
              " s, SCHED_FIFO " + std::to_string(priority) + (fifo ? " granted" : " NOT granted") + "; steps per axis " +
              std::to_string(steps[0]) + " " + std::to_string(steps[1]) + " " + std::to_string(steps[2]) + " (at most " +
              fixed(rig.rate * seconds, 0) + "); " +
              (floor.histogram ? "cyclictest " + std::to_string(ct.histogram().count()) + " wake-ups, priority " +
                                     (ct.priority_seen() ? "seen" : "NOT seen")
                               : "cyclictest: " + floor.unavailable));
  add_latency_figures(report, measured, floor, "idle", false);

  // The write jitter: base_tick() returned d after the deadline; J = d_q − d_min.
  const auto done = sorted_us(recorder.done());
  const double d_min = done.empty() ? 0 : done.front();
  const std::string id = "rt.base." + tag;
  struct Spread {
    const char* key;
    const char* name;
    double q;
  };
  for (const Spread& s : {Spread{"", "max", 1.0}, Spread{".p999", "p99.9", 0.999}}) {
    const double jitter = quantile(done, s.q) - d_min;
    report.add(plain_figure(id + ".jitter" + s.key,
                            std::string("tick end jitter, ") + s.name + " - min, " + tag + " us base", "us", jitter));
    const StepRate r = step_rate(period_us, jitter, o.step_len_us, o.step_space_us);
    report.add(plain_figure(id + ".step_rate" + s.key,
                            "step rate per axis at " + std::string(s.name) + " jitter: " + std::to_string(r.len_periods) +
                                "+" + std::to_string(r.space_periods) + " periods",
                            "steps/s", r.steps_per_s, 0));
  }
  // The tick's cost: measured in the thread (wake-up to return, one clock read included)
  // plus the port accesses priced as a real port's.
  std::vector<double> cpu(done.size());
  {
    const auto w = recorder.woke(), d = recorder.done();
    for (std::size_t i = 0; i < w.size(); ++i) cpu[i] = (d[i] - w[i]) / 1000.0;
    std::sort(cpu.begin(), cpu.end());
  }
  const double ticks = std::max<double>(1, static_cast<double>(recorder.ticks()));
  const double accesses_max = static_cast<double>(recorder.max_reads() + recorder.max_writes());
  report.add(plain_figure(id + ".tick.p50", "base_tick() in the thread, p50 (sim port)", "ns",
                          quantile(cpu, 0.5) * 1000, 0));
  report.add(plain_figure(id + ".tick.p99", "base_tick() in the thread, p99 (sim port)", "ns",
                          quantile(cpu, 0.99) * 1000, 0));
  report.add(plain_figure(id + ".tick.ports",
                          "port accesses per tick, most (mean " +
                              fixed(static_cast<double>(recorder.reads() + recorder.writes()) / ticks, 2) + ")",
                          "n", accesses_max, 0));
  const double cost = quantile(cpu, 0.99) + accesses_max * kPortAccessUs;
  report.add(plain_figure(id + ".tick.cost", "tick cost, p99 + " + fixed(accesses_max, 0) + " x 1 us port access (modelled)",
                          "us", cost, 2));
  report.add(plain_figure(id + ".tick.share", "modelled tick cost, share of the " + tag + " us period", "%",
                          cost / period_us * 100));

  auto& setup = report.setup()["base"][tag];
  setup["seconds"] = seconds;
  setup["priority"] = priority;
  setup["fifo_granted"] = fifo;
  setup["ticks"] = recorder.ticks();
  setup["steps_per_axis"] = steps;
  setup["cyclictest_priority_seen"] = floor.histogram ? nlohmann::ordered_json(ct.priority_seen()) : nullptr;
}
}  // namespace

bool run_base(const Options& o, Report& report) {
  TempDir work("imess-bench-rt-base");
  const std::string cyclictest = o.cyclictest ? Cyclictest::find() : "";
  const std::string floor_missing = !o.cyclictest ? "--no-cyclictest" : "cyclictest not installed (Debian: rt-tests)";
  const core::MemoryLock memory = core::lock_memory();
  report.note(std::string("base: app::BaseThread with the parallel-port driver on the simulated port, wall clock; ") +
              "cyclictest at the same time, same period and priority: " + (cyclictest.empty() ? floor_missing : cyclictest) +
              "; " + memory.note + "; drive minimum step " +
              fixed(o.step_len_us, 1) + " us, space " + fixed(o.step_space_us, 1) + " us");
  report.setup()["base"]["drive_min_step_len_us"] = o.step_len_us;
  report.setup()["base"]["drive_min_step_space_us"] = o.step_space_us;
  report.setup()["base"]["port_access_us"] = kPortAccessUs;
  for (double period : {25.0, 50.0}) measure(period, o, cyclictest, floor_missing, work.path(), report);
  if (memory.locked) munlockall();
  return true;
}

}  // namespace imess::bench
