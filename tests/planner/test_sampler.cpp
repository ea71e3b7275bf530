// The sampler: time carried across junctions, completions, rest at the end of the queue,
// and a chain of short tangent segments that runs without stopping.
#include <catch2/catch.hpp>

#include <numbers>

#include "planner_rig.hpp"

using namespace imess::test;

namespace {

double path_speed(const Tick& t) {
  return std::sqrt(t.velocity[0] * t.velocity[0] + t.velocity[1] * t.velocity[1] + t.velocity[2] * t.velocity[2]);
}
}  // namespace

TEST_CASE("sampler: with nothing queued it rests where it was put") {
  Sampler s(pose_of({1, 2, 3}));
  SegmentBuffer<4> empty;
  auto pop = [&](PlannedSegment& seg) { return empty.pop(seg); };
  const Sample& a = s.advance(kT, pop);
  CHECK(a.pose == pose_of({1, 2, 3}));
  CHECK(a.velocity == Pose{});
  CHECK_FALSE(a.busy);
  CHECK(a.done_count == 0);
  CHECK(s.idle());
}

TEST_CASE("sampler: leftover time is carried into the next segment, so junctions are continuous") {
  // Two collinear moves at cruise: the position advances v·T every tick across the junction.
  Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
  const auto r = run(p, {Line{1, pose_of({50.05, 0, 0}), 100}, Line{2, pose_of({100, 0, 0}), 100}});
  check_continuity(r);
  std::size_t junction = 0;
  for (std::size_t k = 0; k < r.ticks.size(); ++k)
    if (!r.ticks[k].done.empty()) {
      junction = k;
      break;
    }
  REQUIRE(junction > 0);
  CHECK(r.ticks[junction].done == std::vector<std::uint32_t>{1});
  for (std::size_t k = junction - 3; k <= junction + 3; ++k)
    CHECK(r.ticks[k].pose[0] - r.ticks[k - 1].pose[0] == Approx(0.1).epsilon(1e-9));
  CHECK(r.done == std::vector<std::uint32_t>{1, 2});
  CHECK(r.ticks.back().pose == pose_of({100, 0, 0}));
  CHECK(r.ticks.back().velocity == Pose{});
}

TEST_CASE("sampler: a circle of 1 mm chords at 100 mm/s runs without stopping between them") {
  Planner p(make_machine("XYZ", -1000, 1000, 200, 1000));
  const double R = 10;
  const int n = static_cast<int>(std::ceil(2 * std::numbers::pi * R / 1.0));  // 63 chords of ~1 mm
  p.set_position(pose_of({R, 0, 0}));
  std::vector<Request> reqs;
  for (int i = 1; i <= 2 * n; ++i)  // two laps
    reqs.push_back(Line{static_cast<std::uint32_t>(i), pose_of({R * std::cos(2 * std::numbers::pi * i / n), R * std::sin(2 * std::numbers::pi * i / n), 0}), 100});
  const auto r = run(p, reqs);
  check_continuity(r);
  check_limits(p.machine(), r);
  REQUIRE(r.done.size() == reqs.size());
  // Junction speed by junction deviation at a 5.7° turn: √(a·δ·R_jd) ≈ 89 mm/s; no chord
  // between the first and the last few slows below that.
  double slowest = 1e9;
  for (std::size_t i = 5; i + 5 < r.segments.size(); ++i) slowest = std::min(slowest, r.segments[i].v0);
  CHECK(slowest > 85);
  // In the sampled stream: from 0.1 s on until 0.1 s before the end the path never stops.
  for (std::size_t k = 100; k + 100 < r.ticks.size(); ++k) CHECK(path_speed(r.ticks[k]) > 80);
}

TEST_CASE("sampler: several zero-time segments in one tick all complete, in order") {
  Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
  std::vector<Request> reqs;
  for (std::uint32_t i = 1; i <= 40; ++i) reqs.push_back(SetOutput{i, static_cast<std::uint16_t>(i % 4), 1.0 * i});
  reqs.push_back(Line{41, pose_of({1, 0, 0}), 10});
  RunOptions o;
  o.requests_per_tick = 100;
  const auto r = run(p, reqs, o);
  std::vector<std::uint32_t> want;
  for (std::uint32_t i = 1; i <= 41; ++i) want.push_back(i);
  CHECK(r.done == want);
  CHECK(r.ticks.front().done.size() == static_cast<std::size_t>(kMaxCompletionsPerTick));
  CHECK(r.ticks.back().pose == pose_of({1, 0, 0}));
  // Every output switch is reported once, in order, with its output and value.
  std::vector<std::uint32_t> switched;
  for (const auto& t : r.ticks)
    for (const auto& sw : t.switches) {
      CHECK(sw.output == sw.id % 4);
      CHECK(sw.value == 1.0 * sw.id);
      switched.push_back(sw.id);
    }
  want.pop_back();
  CHECK(switched == want);
}

TEST_CASE("sampler: an output switches when the path before it is at rest, and the path holds for its hold time") {
  Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
  const double hold = 0.05;
  const auto r = run(p, {Line{1, pose_of({10, 0, 0}), 100}, SetOutput{2, 3, 1, hold}, Line{3, pose_of({20, 0, 0}), 100}});
  int at = -1;
  for (std::size_t k = 0; k < r.ticks.size(); ++k)
    if (!r.ticks[k].switches.empty()) {
      REQUIRE(at < 0);  // once
      at = static_cast<int>(k);
      CHECK(r.ticks[k].switches[0].id == 2);
      CHECK(r.ticks[k].switches[0].output == 3);
      CHECK(r.ticks[k].switches[0].value == 1.0);
    }
  REQUIRE(at > 0);
  // The move before has arrived, at rest, by the switching tick (the 1 completes in it or earlier).
  CHECK(r.ticks[at].pose[0] == 10.0);
  CHECK(r.ticks[at].velocity[0] == 0.0);
  CHECK(std::find(r.done.begin(), r.done.end(), 1u) < std::find(r.done.begin(), r.done.end(), 2u));
  // The path stays there for the hold, then the SetOutput completes and the next move starts.
  int done2 = -1;
  for (std::size_t k = at; k < r.ticks.size() && done2 < 0; ++k)
    for (auto id : r.ticks[k].done)
      if (id == 2) done2 = static_cast<int>(k);
  REQUIRE(done2 > at);
  CHECK((done2 - at) * kT == Approx(hold).margin(1.5 * kT));
  for (int k = at; k < done2; ++k) CHECK(r.ticks[k].pose[0] == 10.0);
  CHECK(r.ticks.back().pose[0] == 20.0);
}

TEST_CASE("planner: an output's hold must be seconds >= 0") {
  Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
  CHECK(p.append(SetOutput{7, 1, 1, -0.1}).error == PlanError::BadDwell);
  CHECK(p.append(SetOutput{7, 1, 1, std::nan("")}).error == PlanError::BadDwell);
  CHECK(p.append(SetOutput{7, 1, 1, 0.2}).ok());
}

TEST_CASE("sampler: a feeder that falls behind makes it brake on the path, then go on") {
  // Segments handed over one by one with a gap: the last one it holds ends at speed.
  Planner p(make_machine("XYZ", -1000, 1000, 100, 1000));
  for (std::uint32_t i = 1; i <= 20; ++i) REQUIRE(p.append(Line{i, pose_of({10.0 * i, 0, 0}), 100}).ok());
  std::vector<PlannedSegment> segs;
  PlannedSegment s;
  while (p.take(s)) segs.push_back(s);  // final ones only: the tail stays pending
  REQUIRE(segs.size() >= 5);
  REQUIRE(segs[4].v1 > 0);
  Sampler smp;
  SegmentBuffer<64> ring;
  for (int i = 0; i < 5; ++i) ring.push(segs[i]);
  auto pop = [&](PlannedSegment& out) { return ring.pop(out); };
  RunResult r;
  bool starved = false;
  int starved_at = -1;
  for (int t = 0; t < 5000; ++t) {
    if (t == 1500) {  // the feeder wakes up
      for (std::size_t i = 5; i < segs.size(); ++i) ring.push(segs[i]);
      p.flush();
      while (p.take(s)) ring.push(s);
    }
    const Sample& a = smp.advance(kT, pop);
    if (a.starved && !starved) starved_at = t;
    starved = starved || a.starved;
    Tick k;
    k.pose = a.pose;
    k.velocity = a.velocity;
    for (int i = 0; i < a.done_count; ++i) k.done.push_back(a.done[i].id);
    r.ticks.push_back(k);
    if (t > 1500 && smp.idle()) break;
  }
  CHECK(starved);
  CHECK(starved_at < 1500);
  // At rest before the end of segment 5 (x = 50), never past it, until more arrived.
  CHECK(r.ticks[1499].velocity == Pose{});
  CHECK(r.ticks[1499].pose[0] <= 50);
  CHECK(r.ticks[1499].pose[0] > 45);
  CHECK(r.ticks.back().pose == pose_of({200, 0, 0}));
  Machine m = make_machine("XYZ", -1000, 1000, 100, 1000);
  for (std::size_t k = 1; k + 1 < r.ticks.size(); ++k) {
    const double acc = std::fabs(r.ticks[k + 1].pose[0] - 2 * r.ticks[k].pose[0] + r.ticks[k - 1].pose[0]) / (kT * kT);
    CHECK(acc <= m.axes[0].max_accel * (1 + 1e-6) + 1e-6);
  }
}
