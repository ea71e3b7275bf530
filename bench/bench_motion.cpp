// bench_motion: the wall-clock cost of one MotionCore::cycle while it runs a queue of 1 000
// short segments (lines, and arcs in the XY, ZX, YZ and a tilted plane, some helical), on
// every shipped simulated configuration — each machine built as messd builds it
// (app::make_machine: emulated servo card, parport steppers, drive kits behind the
// simulated port space). The loop runs in virtual time: the clock is advanced 1 ms per
// cycle and nothing sleeps, so the motion itself (its seconds) is virtual; the cost of each
// cycle() call is measured with the wall clock. The planner holds the 1 000 segments and
// tops the core's 128-deep ring up between cycles (outside the measured call), as the io
// thread does. Each figure is printed raw and as a ratio to references measured in the
// same run: an idle cycle of the same machine (standing, loops closed) and a fixed
// arithmetic kernel. Prints figures; not a test.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "config_rig.hpp"
#include "imess/core/path_machine.hpp"

using namespace imess;
using Clock = std::chrono::steady_clock;

namespace {

constexpr double kPi = 3.14159265358979323846;
volatile double g_sink = 0;

double ns_since(Clock::time_point t0) { return std::chrono::duration<double, std::nano>(Clock::now() - t0).count(); }

struct Stats {
  double p50 = 0, p99 = 0, max = 0;
};
Stats stats(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return {v[v.size() / 2], v[v.size() * 99 / 100], v.back()};
}

// 1 000 short segments around `at`: 1 mm lines with 30° turns, and every fifth an arc of
// 2 mm radius (a quarter turn) cycling through XY, ZX, YZ and the plane normal to (1, 1, 1),
// every other arc rising 0.5 mm (a helix in the principal planes). The path returns toward
// its start every 40 segments, so it stays within a few millimetres.
std::vector<planner::Request> workload(const planner::Pose& at, double feed) {
  std::vector<planner::Request> r;
  planner::Pose p = at;
  for (int i = 1; i <= 1000; ++i) {
    const auto id = static_cast<std::uint32_t>(i);
    if (i % 5 == 0) {
      planner::Arc a;
      a.id = id;
      a.feed = feed;
      a.ccw = i % 10 == 0;
      const int plane = (i / 5) % 4;
      // start on +e1 of the circle, end on ±e2 (a quarter turn either way)
      std::array<double, 3> n{0, 0, 1}, e1{1, 0, 0};
      if (plane == 1) n = {0, 1, 0}, e1 = {0, 0, 1};
      if (plane == 2) n = {1, 0, 0}, e1 = {0, 1, 0};
      if (plane == 3) {
        const double s3 = 1 / std::sqrt(3.0), s2 = 1 / std::sqrt(2.0);
        n = {s3, s3, s3}, e1 = {s2, -s2, 0};
        a.planar = true;
      }
      const std::array<double, 3> e2{n[1] * e1[2] - n[2] * e1[1], n[2] * e1[0] - n[0] * e1[2],
                                     n[0] * e1[1] - n[1] * e1[0]};
      const double side = a.ccw ? 1 : -1, rise = (plane < 3 && i % 10 == 5) ? 0.5 : 0;
      planner::Pose t = p;
      for (int k = 0; k < 3; ++k) {
        a.centre[k] = p[k] - 2 * e1[k];
        t[k] = a.centre[k] + 2 * side * e2[k] + rise * n[k];
      }
      a.normal = n;
      a.target = t;
      r.push_back(a);
      p = t;
    } else {
      const double ang = (i % 2 ? 1 : -1) * kPi / 6 + (i % 40 < 20 ? 0 : kPi);
      planner::Pose t = p;
      t[0] += std::cos(ang);
      t[1] += std::sin(ang) * 0.3;
      t[2] += (i % 3 - 1) * 0.2;
      r.push_back(planner::Line{id, t, feed});
      p = t;
    }
  }
  return r;
}

// A fixed arithmetic kernel: 32 sine and cosine evaluations (about what sampling an arc
// segment and a few trajectory updates take), timed like a cycle.
double kernel_once() {
  double acc = 0;
  for (int i = 0; i < 32; ++i) acc += std::sin(acc + i * 0.1) * std::cos(acc - i * 0.2);
  return acc;
}

void run(const std::string& name, const std::string& path, const Stats& kernel) {
  test::ConfigRig rig(path);
  auto& core = rig.core();
  int done = 0, failed = 0;
  auto on_event = [&](const core::Event& e) {
    done += e.kind == core::EventKind::Done;
    failed += e.kind == core::EventKind::Failed;
  };
  for (int i = 0; i < 50; ++i) rig.step(on_event);  // settle: loops closed, standing
  // Reference: idle cycles of the same machine.
  std::vector<double> idle;
  for (int i = 0; i < 2000; ++i) {
    const auto t0 = Clock::now();
    rig.step(on_event);
    idle.push_back(ns_since(t0));
  }
  const Stats ref = stats(idle);

  planner::Planner planner(core::path_machine(core.config()), core::path_options(core.config()));
  planner::Pose here{};
  for (int a = 0; a < core.config().layout.count; ++a) here[a] = core.machine().position[a];
  planner.set_position(here);
  const double feed = 0.5 * core.config().axes[0].max_velocity;
  for (const auto& r : workload(here, feed)) {
    if (const auto res = planner.append(r); !res.ok()) {
      std::printf("  %-34s planner refused: %s\n", name.c_str(), planner::describe(res, planner.machine()).c_str());
      return;
    }
  }
  planner.flush();
  auto feed_ring = [&] {
    planner::PlannedSegment s;
    while (core.segment_room() > 0 && planner.take(s)) core.submit_segment({s, core.stop_ticket(), 0});
  };
  std::vector<double> cost;
  feed_ring();
  long cycles = 0;
  for (; cycles < 600000 && done + failed < 1000; ++cycles) {
    feed_ring();
    // rig.step() is clock + cycle + events; the events are drained after the timed call
    const auto t0 = Clock::now();
    rig.cycle();
    const double ns = ns_since(t0);
    core::Event e;
    while (core.events().pop(e)) on_event(e);
    if (cycles >= 10) cost.push_back(ns);  // the first cycles touch cold pages
  }
  const Stats c = stats(cost);
  std::printf("  %-34s %4d Done %d Failed in %6.2f s virtual  cycle p50 %6.1f us  p99 %6.1f us  max %7.1f us\n",
              name.c_str(), done, failed, cycles / 1000.0, c.p50 / 1e3, c.p99 / 1e3, c.max / 1e3);
  std::printf("  %-34s idle cycle p50 %6.1f us; path cycle p50 %5.2f x, p99 %5.2f x idle p50; "
              "p50 %6.1f x, p99 %6.1f x kernel p50\n",
              "", ref.p50 / 1e3, c.p50 / ref.p50, c.p99 / ref.p50, c.p50 / kernel.p50, c.p99 / kernel.p50);
}

}  // namespace

int main() {
  std::vector<double> k;
  for (int i = 0; i < 20000; ++i) {
    const auto t0 = Clock::now();
    g_sink = kernel_once();
    k.push_back(ns_since(t0));
  }
  const Stats kernel = stats(k);
  std::printf("MotionCore::cycle with 1 000 queued segments (lines; quarter arcs in XY, ZX, YZ and a tilted\n"
              "plane; helices), feed half the X axis' speed, per shipped simulated configuration.\n"
              "Virtual time: the motion's seconds; wall clock: each cycle() call, the simulated\n"
              "hardware behind the backend included. Reference kernel (32 sin*cos): p50 %.0f ns, p99 %.0f ns.\n",
              kernel.p50, kernel.p99);
  const std::string root = IMESS_SOURCE_DIR;
  const std::pair<const char*, const char*> configs[] = {
      {"servo card (emulated)", "config/sim-servo-card.json"},
      {"parport steppers, 3D-Step", "config/sim-parport-3dstep.json"},
      {"parport steppers, SHD", "config/sim-parport-shd.json"},
      {"drive kits, map B", "config/sim-portio-drive.json"},
      {"drive kits, map A", "config/sim-portio-drive-map-a.json"},
  };
  for (const auto& [name, file] : configs) run(name, root + "/" + file, kernel);
  return 0;
}
