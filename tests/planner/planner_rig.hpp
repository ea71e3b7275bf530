// Test rig for the planner: feeds requests to a Planner while a Sampler runs in virtual
// time at 1 ms (a few requests per tick, final segments taken as they become final, a
// flush when input ends), records every sample and every segment, and checks the limits.
#pragma once
#include <catch2/catch.hpp>

#include <cmath>
#include <functional>
#include <map>
#include <random>
#include <vector>

#include "imess/planner/planner.hpp"
#include "imess/planner/sampler.hpp"

namespace imess::test {
using namespace imess::planner;

inline constexpr double kT = 0.001;  // the loop period, s

struct Tick {
  Pose pose{}, velocity{};
  std::vector<std::uint32_t> done;
  std::vector<OutputSwitch> switches;  // SetOutput segments that began this tick
  bool held = false;
};

struct RunResult {
  std::vector<Tick> ticks;
  std::vector<PlannedSegment> segments;  // in the order the sampler received them
  std::vector<std::uint32_t> done;       // completion order
  bool starved = false;
};

struct RunOptions {
  int requests_per_tick = 4;  // how fast input arrives
  int max_ticks = 2'000'000;
  // Called before each tick with the tick index and the sampler (hold/resume schedules).
  std::function<void(int, Sampler&)> on_tick;
};

inline Pose pose_of(std::initializer_list<double> v) {
  Pose p{};
  int i = 0;
  for (double x : v) p[i++] = x;
  return p;
}

// Runs the requests through planner and sampler until the sampler is idle after the last.
inline RunResult run(Planner& planner, const std::vector<Request>& requests, const RunOptions& o = {}) {
  RunResult r;
  Sampler sampler(planner.position());
  SegmentBuffer<256> ring;
  std::size_t next = 0;
  bool flushed = false;
  auto pop = [&](PlannedSegment& s) {
    if (!ring.pop(s)) return false;
    r.segments.push_back(s);
    return true;
  };
  for (int t = 0; t < o.max_ticks; ++t) {
    for (int i = 0; i < o.requests_per_tick && next < requests.size(); ++i) {
      const auto res = planner.append(requests[next++]);
      INFO(describe(res, planner.machine()));
      REQUIRE(res.ok());
    }
    if (next == requests.size() && !flushed) planner.flush(), flushed = true;
    PlannedSegment s;
    while (!ring.full() && planner.take(s)) ring.push(s);
    if (o.on_tick) o.on_tick(t, sampler);
    const Sample& smp = sampler.advance(kT, pop);
    Tick k;
    k.pose = smp.pose;
    k.velocity = smp.velocity;
    k.held = smp.held;
    r.starved = r.starved || smp.starved;
    for (int i = 0; i < smp.done_count; ++i) k.done.push_back(smp.done[i].id), r.done.push_back(smp.done[i].id);
    for (int i = 0; i < smp.switch_count; ++i) k.switches.push_back(smp.switches[i]);
    r.ticks.push_back(std::move(k));
    if (flushed && planner.ready() == 0 && planner.pending() == 0 && ring.size() == 0 && sampler.idle() &&
        !smp.busy)
      break;
  }
  return r;
}

// Largest per-axis speed seen by first differences, and the checks of MOTION.md (e):
// |v_i| ≤ v_i,max and |a_i| ≤ a_i,max by finite differences, with a relative slack for the
// rounding of positions (of order 1000 mm) divided by T². Windows that contain a junction
// between segments allow the junction's planned velocity step (junction deviation: the
// direction turns at v_j, which is what that corner law permits) on top.
struct LimitReport {
  double worst_v_ratio = 0, worst_a_ratio = 0;
};

inline Pose tangent(const PlannedSegment& s, double at_s) {
  Pose p, d;
  pose_at(s, at_s, p, d);
  return d;
}

inline LimitReport check_limits(const Machine& m, const RunResult& r, double a_slack = 1e-6) {
  LimitReport rep;
  const auto& t = r.ticks;
  // Junction allowance per tick: the velocity step at a junction completed in that tick.
  std::map<std::uint32_t, std::size_t> index;
  for (std::size_t i = 0; i < r.segments.size(); ++i) index[r.segments[i].id] = i;
  std::vector<Pose> step(t.size(), Pose{});
  for (std::size_t k = 0; k < t.size(); ++k)
    for (auto id : t[k].done) {
      const std::size_t i = index.at(id);
      if (i + 1 >= r.segments.size()) continue;
      const auto& a = r.segments[i];
      const auto& b = r.segments[i + 1];
      const Pose da = tangent(a, a.length), db = tangent(b, 0);
      for (int j = 0; j < m.count; ++j) step[k][j] += std::fabs(a.v1 * da[j] - b.v0 * db[j]);
    }
  for (std::size_t k = 1; k < t.size(); ++k) {
    for (int j = 0; j < m.count; ++j) {
      const double v = std::fabs(t[k].pose[j] - t[k - 1].pose[j]) / kT;
      const double vmax = m.axes[j].max_velocity;
      rep.worst_v_ratio = std::max(rep.worst_v_ratio, v / vmax);
      INFO("tick " << k << " axis " << m.axes[j].letter);
      CHECK(v <= vmax * (1 + 1e-9) + 1e-9);
      CHECK(std::fabs(t[k].velocity[j]) <= vmax * (1 + 1e-9));
      if (k + 1 < t.size()) {
        const double acc = std::fabs(t[k + 1].pose[j] - 2 * t[k].pose[j] + t[k - 1].pose[j]) / (kT * kT);
        const double amax = m.axes[j].max_accel;
        const double allowed = amax * (1 + a_slack) + 1e-6 + (step[k][j] + step[k + 1][j]) / kT;
        if (step[k][j] == 0 && step[k + 1][j] == 0) rep.worst_a_ratio = std::max(rep.worst_a_ratio, acc / amax);
        INFO("tick " << k << " axis " << m.axes[j].letter);
        CHECK(acc <= allowed);
      }
    }
  }
  return rep;
}

// Segment end == next start bit for bit; speeds continuous; first from rest, last to rest.
inline void check_continuity(const RunResult& r) {
  REQUIRE(!r.segments.empty());
  CHECK(r.segments.front().v0 == 0);
  CHECK(r.segments.back().v1 == 0);
  for (std::size_t i = 0; i + 1 < r.segments.size(); ++i) {
    const auto& a = r.segments[i];
    const auto& b = r.segments[i + 1];
    CHECK(a.end == b.start);
    CHECK(b.v0 == Approx(a.v1).margin(1e-9));
  }
}

}  // namespace imess::test
