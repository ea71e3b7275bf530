// Feed hold: brake on the path within every axis' limit, rest, resume to the same ends.
#include <catch2/catch.hpp>

#include "planner_rig.hpp"

using namespace imess::test;

namespace {
// Distance from p (XY) to the path made of the run's segments (lines and XY arcs).
double off_path(const RunResult& ref, const Pose& p) {
  double best = 1e9;
  for (const auto& s : ref.segments) {
    if (s.kind == SegmentKind::Arc) {
      const double r = std::hypot(p[0] - s.arc.centre[0], p[1] - s.arc.centre[1]);
      best = std::min(best, std::fabs(r - s.arc.r0));
    } else {
      const double dx = s.end[0] - s.start[0], dy = s.end[1] - s.start[1];
      const double len2 = dx * dx + dy * dy;
      double f = len2 > 0 ? ((p[0] - s.start[0]) * dx + (p[1] - s.start[1]) * dy) / len2 : 0;
      f = std::clamp(f, 0.0, 1.0);
      best = std::min(best, std::hypot(p[0] - s.start[0] - f * dx, p[1] - s.start[1] - f * dy));
    }
  }
  return best;
}

std::vector<Request> path() {
  Arc a;
  a.id = 2;
  a.target = pose_of({150, 50, 0});
  a.centre = {100, 50, 0};
  a.ccw = true;
  a.feed = 80;
  return {Line{1, pose_of({50, 50, 0}), 100}, a, Line{3, pose_of({150, 150, 0}), 100}, Line{4, pose_of({10, 10, 0}), 100}};
}
}  // namespace

TEST_CASE("hold: braking and resuming stay on the path, within the limits, and end at the same point") {
  Machine m = make_machine("XYZ", 0, 400, 100, 1000);
  m.axes[1].max_accel = 600;
  Planner ref_p(m);
  const auto ref = run(ref_p, path());
  for (int hold_at : {150, 700, 1200, 2500}) {  // in the first line, on the arc, at its end, in the diagonal
    INFO("hold at tick " << hold_at);
    Planner p(m);
    int held_ticks = 0;
    RunOptions o;
    o.on_tick = [&](int t, Sampler& s) {
      if (t == hold_at) s.hold();
      if (s.last().held) ++held_ticks;
      if (held_ticks == 300) s.resume();
    };
    const auto r = run(p, path(), o);
    CHECK(held_ticks >= 300);
    for (const auto& t : r.ticks) CHECK(off_path(ref, t.pose) < 1e-9);
    // Brakes at the path acceleration; each tick covers exactly ½(w + w_new)·dt, so the
    // finite differences meet the limits with the same rounding slack as the plan itself.
    check_limits(m, r);
    CHECK(r.ticks.back().pose == ref.ticks.back().pose);
    CHECK(r.done == ref.done);
    CHECK(r.ticks.size() > ref.ticks.size() + 300);
  }
}

TEST_CASE("hold: while held nothing moves and dwells wait, resume continues where it stood") {
  Planner p(make_machine("XYZ", 0, 400, 100, 1000));
  std::vector<Pose> held_poses;
  RunOptions o;
  o.on_tick = [&](int t, Sampler& s) {
    if (t == 300) s.hold();
    if (s.last().held) held_poses.push_back(s.last().pose);
    if (t == 900) s.resume();
  };
  const auto r = run(p, {Line{1, pose_of({100, 0, 0}), 100}, Dwell{2, 0.1}, Line{3, pose_of({0, 0, 0}), 100}}, o);
  REQUIRE(held_poses.size() > 400);
  for (const auto& h : held_poses) CHECK(h == held_poses.front());
  // Braking from 100 mm/s at 1000 mm/s² takes 5 mm: held near x = 25 + 5.
  CHECK(held_poses.front()[0] == Approx(30).margin(0.3));
  CHECK(r.ticks.back().pose == pose_of({0, 0, 0}));
  CHECK(r.done == std::vector<std::uint32_t>{1, 2, 3});
}

TEST_CASE("hold: a dwell's clock stops while held") {
  const std::vector<Request> reqs{Line{1, pose_of({1, 0, 0}), 100}, Dwell{2, 0.2}, Line{3, pose_of({2, 0, 0}), 100}};
  Planner ref_p(make_machine("XYZ", 0, 400, 100, 1000));
  const auto ref = run(ref_p, reqs);
  Planner p(make_machine("XYZ", 0, 400, 100, 1000));
  RunOptions o;
  o.on_tick = [&](int t, Sampler& s) {
    if (t == 150) s.hold();  // inside the dwell (the first line takes about 65 ms)
    if (t == 650) s.resume();
  };
  const auto r = run(p, reqs, o);
  CHECK(r.ticks.size() >= ref.ticks.size() + 499);
  CHECK(r.ticks.size() <= ref.ticks.size() + 501);
  CHECK(r.ticks.back().pose == pose_of({2, 0, 0}));
}

TEST_CASE("hold: a feed hold keeps a SetOutput from switching until resume, wherever it comes") {
  // A 1 mm line braking to its planned stop, then an output; held at every third tick before
  // the output would switch unheld.
  const std::vector<Request> reqs{Line{1, pose_of({1, 0, 0}), 50}, SetOutput{2, 1, 1, 0}, Line{3, pose_of({2, 0, 0}), 50}};
  int unheld = -1;
  {
    Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
    const auto r = run(p, reqs);
    for (std::size_t k = 0; k < r.ticks.size() && unheld < 0; ++k)
      if (!r.ticks[k].switches.empty()) unheld = static_cast<int>(k);
  }
  REQUIRE(unheld > 30);
  for (int hold_at = 0; hold_at < unheld; hold_at += 3) {
    INFO("hold at tick " << hold_at);
    Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
    RunOptions o;
    const int resume_at = 400;
    o.on_tick = [&](int t, Sampler& s) {
      if (t == hold_at) s.hold();
      if (t == resume_at) s.resume();
    };
    const auto r = run(p, reqs, o);
    int switched = -1, done2 = -1;
    for (std::size_t k = 0; k < r.ticks.size(); ++k) {
      if (!r.ticks[k].switches.empty() && switched < 0) switched = static_cast<int>(k);
      for (auto id : r.ticks[k].done)
        if (id == 2) done2 = static_cast<int>(k);
    }
    REQUIRE(switched >= 0);
    CHECK(switched >= resume_at);  // not while held
    CHECK(done2 >= switched);
    CHECK(r.done == std::vector<std::uint32_t>{1, 2, 3});
    CHECK(r.ticks.back().pose[0] == 2.0);
  }
}
