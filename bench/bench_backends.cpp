// bench_backends: the step rate the parallel-port backend sustains (three axes at once) on
// the simulated port without timing violations, what limits it, and the CPU time of one
// servo cycle for every backend (the MotionCore plus the driver plus the simulated
// hardware behind it). Prints figures; not a test.
// Which clock: the steps/s are VIRTUAL time — the base routine and the simulated stepper run
// in lock-step virtual base periods, so they prove the pulse logic, not that a thread on this
// kernel wakes every 2–20 µs (bench_rt base measures that in wall clock). The base_tick ns,
// "sim CPU" and the cycle costs are wall-clock CPU time on this machine.
#include <algorithm>
#include <chrono>
#include <vector>
#include <cstdio>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;
using Clock = std::chrono::steady_clock;

namespace {

double us_since(Clock::time_point t0) { return std::chrono::duration<double, std::micro>(Clock::now() - t0).count(); }

// Three axes stepping at the pulse-timing limit of a base period for one simulated second.
void step_rate(double base_us) {
  auto o = stepper_options();
  o.sim.scene = sim::Scene();
  o.driver.base_period_ns = base_us * 1000;
  o.driver.step_len_ns = o.driver.step_space_ns = o.driver.dir_setup_ns = o.driver.dir_hold_ns = base_us * 1000;
  o.sim.stepper.min_step_len_ns = o.sim.stepper.min_step_space_ns = base_us * 1000;
  o.sim.stepper.min_dir_setup_ns = o.sim.stepper.min_dir_hold_ns = base_us * 1000;
  const double rate = 1e6 / (2 * base_us);  // one step per 2 base periods
  for (auto& a : o.driver.axes) {
    a.steps_per_mm = 1000;
    a.max_speed = rate / 1000;
    a.max_accel = 1e6;
  }
  StepperRig rig(o);
  rig.pump().set_loops(true);
  hal::AxisArray<hal::AxisMove> m;
  for (int a = 0; a < 3; ++a) m[a] = {o.sim.mechanics.start[a] + (a == 1 ? -1 : 1) * rate / 1000 * 2, rate / 1000, 1e6};
  rig.pump().move(m, 7);
  hal::AxisArray<std::int64_t> start{rig.stepper().steps(0), rig.stepper().steps(1), rig.stepper().steps(2)};
  auto t0 = Clock::now();
  rig.servo_cycles(1000);  // one simulated second
  double cpu = us_since(t0);
  // Base routine alone (driver side: read status, pulse making, write data), per tick.
  auto& d = rig.driver();
  auto t1 = Clock::now();
  const int n = 2'000'000;
  for (int i = 0; i < n; ++i) d.base_tick();
  double tick_ns = us_since(t1) * 1000 / n;
  std::printf("  base %5.1f us: %7.0f steps/s per axis x3 (virtual time)  moved %7ld %7ld %7ld  violations %lu  lost %lu  "
              "base_tick %4.0f ns  sim CPU %5.1f %% of real time\n",
              base_us, rate, static_cast<long>(rig.stepper().steps(0) - start[0]),
              static_cast<long>(start[1] - rig.stepper().steps(1)), static_cast<long>(rig.stepper().steps(2) - start[2]),
              rig.stepper().violations().total(), rig.stepper().lost_steps(0) + rig.stepper().lost_steps(1) + rig.stepper().lost_steps(2),
              tick_ns, cpu / 1e6 * 100);
}

// Average and worst CPU time of MotionCore::cycle (read_state, logic, hardware writes)
// while jogging, over `cycles` cycles.
void cycle_cost(const char* name, MotionRig& rig, core::CoreConfig c) {
  rig.start_core(c);
  rig.start_mv({20, 10, 0});
  double total = 0;
  const int cycles = 3000;
  std::vector<double> samples;
  for (int i = 0; i < cycles; ++i) {
    rig.clock().advance(MotionRig::kPeriod);
    auto t0 = Clock::now();
    rig.core().cycle(rig.clock().now());
    double us = us_since(t0);
    if (i < 10) continue;  // warm-up: first touches of pages and caches
    total += us;
    samples.push_back(us);
    core::Event e;
    while (rig.core().events().pop(e)) {}
  }
  std::sort(samples.begin(), samples.end());
  std::printf("  %-38s %7.2f us mean  %7.2f us p99  %7.2f us max (a shared machine preempts)\n", name,
              total / (cycles - 10), samples[samples.size() * 99 / 100], samples.back());
}

class ServoCardRig final : public MotionRig {
 public:
  ServoCardRig() : cmm_(sim::SimulatedCmmConfig{}, clock_), driver_(cmm_.link(), hal::ServoCardConfig{}) { driver_.initialise(false); }
  hal::MotionBackend& backend() override { return driver_; }

 private:
  sim::SimulatedCmm cmm_;
  hal::ServoCardDriver driver_;
};

}  // namespace

int main() {
  std::printf("Parallel-port step/dir: three axes at the pulse-timing limit (1 base period high, 1 low),\n"
              "one simulated second each, real driver + simulated stepper machine on the port space.\n"
              "steps/s are VIRTUAL time (lock-step virtual base periods: the pulse logic, not a thread's\n"
              "wake-ups; bench_rt base has the wall-clock jitter); base_tick ns and sim CPU are wall clock:\n");
  for (double base : {20.0, 10.0, 5.0, 2.0}) step_rate(base);
  std::printf("\nCPU per servo cycle (MotionCore + driver + simulated hardware behind it), jogging; wall-clock\n"
              "CPU time of cycles stepped in virtual time (no sleeping, no wake-up latency):\n");
  core::CoreConfig c;
  c.params.max_speed = 80;
  c.max_velocity = 80;
  {
    ServoCardRig r;
    cycle_cost("servo card (emulated, 10 kHz firmware)", r, c);
  }
  {
    StepperRig r;  // 5 us base period: 200 base ticks per cycle
    cycle_cost("parport stepper (5 us base, sim)", r, c);
  }
  {
    auto o = stepper_options();
    o.driver.base_period_ns = 20000;
    o.driver.step_len_ns = o.driver.step_space_ns = o.driver.dir_setup_ns = o.driver.dir_hold_ns = 5000;
    for (auto& a : o.driver.axes) {
      a.steps_per_mm = 200;
      a.max_speed = 50;
    }
    o.sim.stepper.steps_per_mm = {200, 200, 200};
    StepperRig r(o);
    cycle_cost("parport stepper (20 us base, sim)", r, c);
  }
  {
    DriveRig r;
    cycle_cost("drive kit mode 1 (100 us kit, sim)", r, c);
  }
  {
    DriveRig r(drive_options(2, "mrm-a"));
    cycle_cost("drive kit mode 2 (100 us kit, sim)", r, c);
  }
  std::printf("\nThe simulated hardware dominates these figures; on real ports the servo-side driver work\n"
              "is a few port accesses per axis (~1 us each on an ISA-style port) plus the planning.\n");
  return 0;
}
