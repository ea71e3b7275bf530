// The planner: validation, axis limits, the feed rule, junction deviation, look-ahead,
// final segments and the invariant that the queued tail ends at rest.
#include <catch2/catch.hpp>

#include "planner_rig.hpp"

using namespace imess::test;

namespace {
Machine xyz(double v = 100, double a = 1000) { return make_machine("XYZ", -1000, 1000, v, a); }

std::vector<PlannedSegment> take_all(Planner& p) {
  std::vector<PlannedSegment> out;
  PlannedSegment s;
  while (p.take(s)) out.push_back(s);
  return out;
}
}  // namespace

TEST_CASE("planner: 100 mm at 100 mm/s with 1000 mm/s² is one trapezoid of 1.1 s") {
  Planner p(xyz(200));
  REQUIRE(p.append(Line{1, pose_of({100, 0, 0}), 100}).ok());
  CHECK(p.ready() == 0);  // the newest segment is never final before a flush or a successor
  p.flush();
  const auto segs = take_all(p);
  REQUIRE(segs.size() == 1);
  CHECK(segs[0].id == 1);
  CHECK(segs[0].length == 100);
  CHECK(segs[0].duration() == Approx(1.1));
  CHECK(segs[0].v0 == 0);
  CHECK(segs[0].v1 == 0);
  // Sampled at 1 ms: 1100 ticks, the last exactly on the target.
  Planner q(xyz(200));
  const auto r = run(q, {Line{1, pose_of({100, 0, 0}), 100}});
  CHECK(static_cast<double>(r.ticks.size()) == Approx(1100).margin(1));  // summing 1 ms ticks rounds
  CHECK(r.ticks.back().pose == pose_of({100, 0, 0}));
  CHECK(r.done == std::vector<std::uint32_t>{1});
}

TEST_CASE("planner: a 90° corner with δ = 0.01 mm and 1000 mm/s² is taken at 4.9 mm/s") {
  Planner p(xyz(1000, 1000));
  p.append(Line{1, pose_of({100, 0, 0}), 100});
  p.append(Line{2, pose_of({100, 100, 0}), 100});
  p.flush();
  const auto segs = take_all(p);
  REQUIRE(segs.size() == 2);
  // v² = a·δ·sin(θ/2)/(1 − sin(θ/2)), θ = 90°: 1000·0.01·2.414 = 24.14.
  CHECK(segs[0].v1 == Approx(4.913).epsilon(1e-3));
  CHECK(segs[1].v0 == segs[0].v1);
  // Klipper's form: square corner velocity 5 mm/s gives exactly 5 mm/s at 90°.
  PlannerOptions o;
  o.square_corner_velocity = 5;
  Planner k(xyz(1000, 1000), o);
  k.append(Line{1, pose_of({100, 0, 0}), 100});
  k.append(Line{2, pose_of({100, 100, 0}), 100});
  k.flush();
  CHECK(take_all(k)[0].v1 == Approx(5));
}

TEST_CASE("planner: Klipper's cap keeps the virtual arc within half of a short move") {
  // 10° turn between 0.2 mm moves: JD alone allows v² = a·δ·R_jd; the cap ½·a·L·tan(θ/2) is lower.
  Planner p(xyz(1000, 1000));
  const double ang = 10 * 3.14159265358979 / 180;
  p.append(Line{1, pose_of({0.2, 0, 0}), 100});
  p.append(Line{2, pose_of({0.2 + 0.2 * std::cos(ang), 0.2 * std::sin(ang), 0}), 100});
  p.flush();
  const auto segs = take_all(p);
  const double theta = 3.14159265358979 - ang;
  const double jd = 1000 * 0.01 * std::sin(theta / 2) / (1 - std::sin(theta / 2));
  const double cap = 0.5 * 1000 * 0.2 * std::tan(theta / 2);
  REQUIRE(cap < jd);
  CHECK(segs[0].v1 * segs[0].v1 <= cap * (1 + 1e-12));
}

TEST_CASE("planner: a reversal stops, a straight continuation does not slow down") {
  Planner p(xyz(1000, 1000));
  p.append(Line{1, pose_of({50, 0, 0}), 100});
  p.append(Line{2, pose_of({100, 0, 0}), 100});
  p.append(Line{3, pose_of({0, 0, 0}), 100});
  p.flush();
  const auto segs = take_all(p);
  REQUIRE(segs.size() == 3);
  CHECK(segs[0].v1 == Approx(100));
  CHECK(segs[1].v1 == 0);
  CHECK(segs[2].v1 == 0);
}

TEST_CASE("planner: path speed and acceleration are limited by every moving axis") {
  Machine m = xyz(100, 1000);
  m.axes[1].max_velocity = 20;
  m.axes[1].max_accel = 200;
  Planner p(m);
  p.append(Line{1, pose_of({30, 40, 0}), 100});  // u = (0.6, 0.8)
  p.flush();
  const auto s = take_all(p)[0];
  CHECK(s.vc == Approx(20 / 0.8));
  CHECK(s.a == Approx(200 / 0.8));
}

TEST_CASE("planner: the feed rule for rotary axes") {
  Machine m = make_machine("XYZA", -1000, 1000, 100, 1000);
  m.axes[3].travel_min = -3600, m.axes[3].travel_max = 3600;
  m.axes[3].max_velocity = 180;
  SECTION("A alone: F is degrees per second") {
    Planner p(m);
    p.append(Line{1, pose_of({0, 0, 0, 90}), 45});
    p.flush();
    const auto s = take_all(p)[0];
    CHECK(s.length == 90);
    CHECK(s.vc == Approx(45));
    CHECK(s.duration() == Approx(90 / 45.0 + 45 / 1000.0));
  }
  SECTION("X with A: F is the XYZ path speed, stretched until A meets its limit") {
    Planner p(m);
    p.append(Line{1, pose_of({100, 0, 0, 360}), 100});  // A turns 3.6°/mm: 100 mm/s would be 360°/s
    p.flush();
    const auto s = take_all(p)[0];
    CHECK(s.length == 100);
    CHECK(s.vc == Approx(50));
  }
  SECTION("U alone (no XYZ): F is the UVW path speed") {
    Machine mu = make_machine("XYU", -1000, 1000, 100, 1000);
    Planner p(mu);
    p.append(Line{1, pose_of({0, 0, 30}), 10});
    p.flush();
    const auto s = take_all(p)[0];
    CHECK(s.length == 30);
    CHECK(s.vc == Approx(10));
  }
}

TEST_CASE("planner: a segment leaving the travel is refused, naming the segment and the axis") {
  Machine m = make_machine("XYZ", 0, 500, 100, 1000);
  m.axes[2].travel_min = -200, m.axes[2].travel_max = 0;
  Planner p(m);
  p.set_position(pose_of({10, 10, 0}));
  REQUIRE(p.append(Line{1, pose_of({100, 10, 0}), 50}).ok());
  const AppendResult r = p.append(Line{42, pose_of({100, 10, 5}), 50});
  CHECK(r.error == PlanError::OutOfTravel);
  CHECK(r.id == 42);
  CHECK(r.axis == 2);
  CHECK(r.value == 5);
  CHECK(describe(r, m) == "segment 42: axis Z leaves its travel at 5.000000");
  CHECK(p.position() == pose_of({100, 10, 0}));  // refused: nothing changed
  CHECK(p.pending() == 1);
  CHECK(p.append(Line{43, pose_of({100, -0.5, 0}), 50}).axis == 1);
}

TEST_CASE("planner: bad requests are refused with their own error") {
  Planner p(xyz());
  CHECK(p.append(Line{1, pose_of({10, 0, 0}), 0}).error == PlanError::BadFeed);
  CHECK(p.append(Line{2, pose_of({10, 0, NAN}), 10}).error == PlanError::BadPose);
  CHECK(p.append(Dwell{3, -1}).error == PlanError::BadDwell);
  CHECK(p.append(Line{4, pose_of({0, 0, 0}), 0}).ok());  // zero length: no feed needed
  CHECK_THROWS_AS(Planner(make_machine("XYZ", 0, 10, 1, 1), PlannerOptions{0.01, 0, 0}), std::invalid_argument);
  CHECK_THROWS_AS(make_machine("XQ", 0, 10, 1, 1), std::invalid_argument);
  CHECK_THROWS_AS(make_machine("XX", 0, 10, 1, 1), std::invalid_argument);
}

TEST_CASE("planner: a feed below the machine's minimum is refused and the message says the minimum") {
  PlannerOptions o;
  o.min_feed = 0.01;
  Planner p(xyz(), o);
  const auto r = p.append(Line{7, pose_of({10, 0, 0}), 1e-8});
  CHECK(r.error == PlanError::BadFeed);
  CHECK(describe(r, xyz()) == "segment 7: feed must be a number of at least 0.010000");
  CHECK(p.pending() == 0);
  CHECK(p.append(Line{8, pose_of({10, 0, 0}), 0.01}).ok());
}

TEST_CASE("planner: zero-length moves, dwells and outputs complete with their id and do not move") {
  Planner p(xyz());
  const auto r = run(p, {Line{1, pose_of({0, 0, 0}), 100}, Line{2, pose_of({10, 0, 0}), 100},
                         Line{3, pose_of({10, 0, 0}), 100}, Dwell{4, 0.05}, SetOutput{5, 2, 1},
                         Line{6, pose_of({10, 0, 0}), 0}});
  CHECK(r.done == std::vector<std::uint32_t>{1, 2, 3, 4, 5, 6});
  check_continuity(r);
  check_limits(p.machine(), r);
  CHECK(r.ticks.back().pose == pose_of({10, 0, 0}));
  // The dwell holds the machine still for its 50 ms.
  int still = 0;
  for (std::size_t k = 1; k < r.ticks.size(); ++k)
    if (r.ticks[k].pose == pose_of({10, 0, 0})) ++still;
  CHECK(still >= 50);
}

TEST_CASE("planner: final segments are released lazily and never change afterwards") {
  // A straight chain of 1 mm moves: cruising segments become final while the tail, which
  // must be able to stop, stays pending.
  Planner inc(xyz(1000, 1000)), batch(xyz(1000, 1000));
  std::vector<PlannedSegment> taken;
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  std::vector<Request> reqs;
  for (int i = 1; i <= 300; ++i) reqs.push_back(Line{static_cast<std::uint32_t>(i), pose_of({i * 1.0, jitter(rng), 0}), 100});
  std::size_t max_pending = 0;
  for (const auto& r : reqs) {
    REQUIRE(inc.append(r).ok());
    REQUIRE(batch.append(r).ok());
    max_pending = std::max(max_pending, inc.pending());
    PlannedSegment s;
    while (inc.take(s)) taken.push_back(s);
    // The invariant: what is queued ends at rest (flush a copy to see it).
    Planner copy = inc;
    copy.flush();
    PlannedSegment last;
    while (copy.take(last)) {}
    CHECK(last.v1 == 0);
  }
  CHECK(taken.size() > 250);
  CHECK(max_pending < 40);
  inc.flush();
  PlannedSegment s;
  while (inc.take(s)) taken.push_back(s);
  batch.flush();
  const auto all = take_all(batch);
  REQUIRE(all.size() == taken.size());
  for (std::size_t i = 0; i < all.size(); ++i) {
    CHECK(all[i].v0 == Approx(taken[i].v0).margin(1e-9));
    CHECK(all[i].v1 == Approx(taken[i].v1).margin(1e-9));
    CHECK(all[i].vc == Approx(taken[i].vc).margin(1e-9));
  }
}

TEST_CASE("planner: segments are at least 1.02 loop periods long") {
  Planner p(xyz(100000, 1e7));
  p.append(Line{1, pose_of({0.05, 0, 0}), 10000});
  p.flush();
  const auto s = take_all(p)[0];
  CHECK(s.vc <= 0.05 / (1.02 * 0.001) * (1 + 1e-12));
  CHECK(s.duration() >= 1.02 * 0.001);
}

TEST_CASE("planner: set_position starts planning from where the machine is") {
  Planner p(xyz());
  p.append(Line{1, pose_of({10, 0, 0}), 100});
  p.set_position(pose_of({5, 5, 5}));
  CHECK(p.pending() == 0);
  p.append(Line{2, pose_of({5, 5, 10}), 100});
  p.flush();
  const auto s = take_all(p);
  REQUIRE(s.size() == 1);
  CHECK(s[0].start == pose_of({5, 5, 5}));
  CHECK(s[0].length == 5);
}
