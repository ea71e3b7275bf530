// bench_planner: what planning costs the planner thread (segments/s through append,
// look-ahead and release) and what sampling costs the 1 kHz loop per tick with 1 000
// segments queued. Each figure is printed raw and as a ratio to a reference measured in
// the same run on the same data (so a slower or busier machine shifts both alike):
// planning against planning a bare trapezoid per segment, a tick against evaluating one
// segment's profile and geometry. Prints figures; not a test.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <vector>

#include "imess/planner/planner.hpp"
#include "imess/planner/sampler.hpp"

using namespace imess::planner;
using Clock = std::chrono::steady_clock;

namespace {

double ns_since(Clock::time_point t0) { return std::chrono::duration<double, std::nano>(Clock::now() - t0).count(); }

volatile double g_sink = 0;  // keeps the reference loops from being optimised away

// A zig-zag of short moves (1 mm, 20° turns, every tenth a half circle in XY, ZX or YZ):
// junctions, look-ahead work.
std::vector<Request> workload(int n) {
  std::vector<Request> r;
  Pose p{};
  p[0] = p[1] = 500;
  for (int i = 1; i <= n; ++i) {
    Pose t = p;
    const double ang = (i % 2 ? 1 : -1) * 0.35;
    if (i % 10 == 0) {
      Arc a;
      a.id = static_cast<std::uint32_t>(i);
      const double up = i % 20000 < 10000 ? 1 : -1;  // stays within the travel
      const int plane = (i / 10) % 3;                // half circles in XY, ZX, YZ in turn
      if (plane == 0) {
        a.centre = {p[0], p[1] + 2 * up, p[2]};
        t[1] = p[1] + 4 * up;
      } else {
        a.centre = {p[0], p[1], p[2] + 2 * up};
        a.normal = plane == 1 ? std::array<double, 3>{0, 1, 0} : std::array<double, 3>{1, 0, 0};
        t[2] = p[2] + 4 * up;
      }
      a.target = t;
      a.ccw = i % 20 == 0;
      a.feed = 100;
      r.push_back(a);
    } else {
      t[0] += std::cos(ang) * (i % 40 < 20 ? 1 : -1);
      t[1] += std::sin(ang) * 0.2;
      r.push_back(Line{static_cast<std::uint32_t>(i), t, 100});
    }
    p = t;
  }
  return r;
}

Machine machine() { return make_machine("XYZ", -10000, 10000, 200, 2000); }

}  // namespace

int main() {
  const int n = 100'000;
  const auto reqs = workload(n);

  // Planning: append + look-ahead + release, taking final segments as they appear.
  double best_plan = 1e30, best_ref = 1e30;
  std::size_t produced = 0;
  for (int rep = 0; rep < 3; ++rep) {
    Planner p(machine());
    p.set_position(Pose{500, 500});
    PlannedSegment s;
    produced = 0;
    auto t0 = Clock::now();
    for (const auto& r : reqs) {
      if (const auto res = p.append(r); !res.ok()) {
        std::fprintf(stderr, "bench_planner: %s\n", describe(res, p.machine()).c_str());
        return 1;
      }
      while (p.take(s)) ++produced;
    }
    p.flush();
    while (p.take(s)) ++produced;
    best_plan = std::min(best_plan, ns_since(t0));
    // Reference: a bare trapezoid and its profile for each segment, no geometry, no look-ahead.
    auto t1 = Clock::now();
    double acc = 0;
    for (int i = 0; i < n; ++i) {
      const Trapezoid t = plan_trapezoid(1 + 1e-6 * i, 10, 100, 20, 2000);
      acc += trapezoid_profile(1 + 1e-6 * i, t).duration;
    }
    g_sink = acc;
    best_ref = std::min(best_ref, ns_since(t1));
  }
  std::printf("planner: %zu segments (1 mm zig-zag, every tenth a half circle in XY, ZX or YZ)\n", produced);
  std::printf("  plan + look-ahead + release  %8.0f ns/segment  %10.0f segments/s   %5.1f x a bare trapezoid (%5.0f ns)\n",
              best_plan / n, n / best_plan * 1e9, best_plan / best_ref, best_ref / n);

  // Sampling: 1 000 queued segments, one advance() per 1 ms tick.
  static SegmentBuffer<1024> ring;
  std::vector<PlannedSegment> segs;
  {
    Planner p(machine());
    p.set_position(Pose{500, 500});
    for (int i = 0; i < 1000; ++i) p.append(reqs[i]);
    p.flush();
    PlannedSegment s;
    while (p.take(s)) segs.push_back(s);
  }
  for (const auto& s : segs) ring.push(s);
  Sampler sampler(segs.front().start);
  auto pop = [](PlannedSegment& out) noexcept { return ring.pop(out); };
  std::vector<double> tick_ns;
  int hold_ticks = 0;
  for (int t = 0; !sampler.idle() || t == 0; ++t) {
    if (t == 3000) sampler.hold();
    if (t == 3400) sampler.resume();
    auto t0 = Clock::now();
    const Sample& smp = sampler.advance(0.001, pop);
    tick_ns.push_back(ns_since(t0));
    g_sink = smp.pose[0];
    hold_ticks += smp.held;
  }
  // Reference: evaluate one line segment's profile and pose, as often as there were ticks.
  std::vector<double> ref_ns;
  Pose pose, d;
  for (std::size_t t = 0; t < tick_ns.size(); ++t) {
    const PlannedSegment& s = segs[t % segs.size()];
    auto t0 = Clock::now();
    const PathState st = s.profile.at(0.4 * s.duration());
    pose_at(s, st.s, pose, d);
    ref_ns.push_back(ns_since(t0));
    g_sink = pose[0];
  }
  auto stats = [](std::vector<double> v, double& mean, double& p99, double& mx) {
    std::sort(v.begin(), v.end());
    double sum = 0;
    for (double x : v) sum += x;
    mean = sum / double(v.size());
    p99 = v[v.size() * 99 / 100];
    mx = v.back();
  };
  double m, p99, mx, rm, rp99, rmx;
  stats(tick_ns, m, p99, mx);
  stats(ref_ns, rm, rp99, rmx);
  std::printf("sampler: %zu ticks of 1 ms over %zu segments (%d ticks held)\n", tick_ns.size(), segs.size(), hold_ticks);
  std::printf("  advance()                    mean %6.0f ns  p99 %6.0f ns  max %7.0f ns   mean %4.1f x one profile+pose "
              "evaluation (%3.0f ns)   %.4f %% of the 1 ms period\n",
              m, p99, mx, m / rm, rm, m / 1e6 * 100);
  return 0;
}
