// Path mode: planned segments through the ring, sampled every cycle and followed by the
// backend (the IdealFollower double); Done / Failed ids, stops, feed hold, the full ring,
// probe edges, limits, a backend that cannot follow.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>

#include "ideal_follower.hpp"

using namespace imess::test;
using imess::core::FailReason;
using imess::core::Refusal;
namespace planner = imess::planner;

namespace {
// Lines, dwells and an arc. A corner is a velocity step by design of junction deviation
// (docs/architecture.md, "Planner"), so a dwell (an exact stop) separates every change of
// direction here and the acceleration check below holds at every tick.
void queue_mixed(FollowerRig& rig) {
  rig.append(rig.line(1, 150, 100, 100, 50));
  rig.append(planner::Dwell{6, 0.01});
  rig.append(rig.line(2, 150, 160, 120, 50));
  rig.append(planner::Dwell{3, 0.05});
  planner::Arc arc;
  arc.id = 4;
  arc.target = {190, 200, 120};  // centre (150, 200): radius 40, a quarter turn
  arc.centre = {150, 200, 120};
  arc.ccw = true;
  arc.feed = 40;
  rig.append(arc);
  rig.append(planner::Dwell{7, 0});
  rig.append(rig.line(5, 190, 200, 80, 30));
}

}  // namespace

TEST_CASE("a queue of lines, a dwell and an arc runs to its end: Done ids in order, at the target, idle") {
  FollowerRig rig;
  queue_mixed(rig);
  CHECK(rig.feed(true) == 7);
  rig.step();
  CHECK(rig.mode() == Mode::Path);
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 20));
  rig.step();  // the machine state of the cycle after the last setpoint
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{1, 6, 2, 3, 4, 7, 5});
  CHECK(rig.ids(EventKind::Failed).empty());
  CHECK(rig.position().isApprox(Vec3(190, 200, 80), 1e-12));
  CHECK(rig.hw.follow_calls > 1000);
  // the State words: move (Path) at the start, idle at the end
  auto states = rig.take(EventKind::State);
  REQUIRE(states.size() == 2);
  CHECK(states[0].mode == Mode::Path);
  CHECK(states[1].mode == Mode::Idle);
}

// Cycles from the last follow() of a path to the first Done of its last segment.
static int cycles_to_arrival(FollowerRig& rig) {
  rig.append(rig.line(41, 120, 100, 100, 50));
  rig.append(rig.line(42, 140, 110, 100, 50));
  rig.feed(true);
  long calls = -1;
  int after = 0;
  for (int i = 0; i < 5000 && rig.ids(EventKind::Done).size() < 2; ++i) {
    if (rig.hw.follow_calls != calls) calls = rig.hw.follow_calls, after = 0;
    else ++after;
    rig.step();
  }
  return after;
}

TEST_CASE("the last Done of a queue comes when the machine reports in position, with the idle state") {
  for (int lag : {0, 1, 7, 40, 300}) {
    FollowerRig rig;
    rig.hw.lag_cycles = lag;
    const int cycles = cycles_to_arrival(rig);
    INFO("axes in position " << lag << " cycles after the path's end");
    CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{41, 42});
    CHECK(cycles >= lag);
    CHECK(cycles <= lag + 2);
    CHECK(rig.mode() == Mode::Idle);
    // Done 41 went out on the way (the path went on); Done 42 and idle in the same cycle
    const auto& ev = rig.events();
    const auto done = std::find_if(ev.begin(), ev.end(), [](const Event& e) { return e.kind == EventKind::Done && e.id == 42; });
    const auto idle = std::find_if(ev.begin(), ev.end(), [](const Event& e) { return e.kind == EventKind::State && e.mode == Mode::Idle; });
    REQUIRE(done != ev.end());
    REQUIRE(idle != ev.end());
    CHECK(done < idle);
    CHECK(done->time == idle->time);
  }
}

TEST_CASE("a backend that never reports in position ends the queue all the same, half a second later") {
  FollowerRig rig;
  rig.hw.lag_cycles = -1;
  const int cycles = cycles_to_arrival(rig);
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{41, 42});
  CHECK(cycles >= 499);
  CHECK(cycles <= 502);
  CHECK(rig.mode() == Mode::Idle);
}

TEST_CASE("a stop while the machine settles answers Done, not Failed: the path was complete") {
  FollowerRig rig;
  rig.hw.lag_cycles = 100;
  rig.append(rig.line(43, 120, 100, 100, 50));
  rig.feed(true);
  const long before = rig.hw.follow_calls;
  REQUIRE(rig.run_until([&] { return rig.hw.follow_calls > before && rig.hw.velocity().isZero() && rig.hw.where() == Vec3(120, 100, 100); }, 5));
  rig.run(0.01);
  REQUIRE(rig.ids(EventKind::Done).empty());  // still settling
  rig.stop();
  rig.run(0.01);
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{43});
  CHECK(rig.ids(EventKind::Failed).empty());
}

TEST_CASE("followed setpoints stay within every axis' speed and acceleration (finite differences)") {
  FollowerRig rig;
  queue_mixed(rig);
  rig.feed(true);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle && rig.hw.follow_calls > 10; }, 20));
  const auto& sp = rig.hw.setpoints;
  REQUIRE(sp.size() > 1000);
  const auto& cfg = rig.core().config();
  const double dt = 0.001;
  double vmax_seen = 0;
  Vec3 prev_v = Vec3::Zero();  // starts at rest
  Vec3 prev_p = Vec3(100, 100, 100);
  for (const auto& s : sp) {
    Vec3 v = (xyz(s.position) - prev_p) / dt;
    for (int a = 0; a < 3; ++a) {
      CHECK(std::abs(v[a]) <= cfg.axes[a].max_velocity * (1 + 1e-6));
      CHECK(std::abs(v[a] - prev_v[a]) / dt <= cfg.axes[a].max_accel * (1 + 1e-6) + 1e-6);
      vmax_seen = std::max(vmax_seen, std::abs(v[a]));
    }
    prev_v = v;
    prev_p = xyz(s.position);
  }
  CHECK(vmax_seen > 20);  // it did move at speed: the checks above are not vacuous
  CHECK(sp.back().velocity.norm() == 0);  // ends at rest (the last tick covers a part of a period)
  CHECK(xyz(sp.back().position) == Vec3(190, 200, 80));
}

TEST_CASE("StopMv mid-queue brakes with the configured deceleration and fails every queued id") {
  FollowerRig rig;
  rig.append(rig.line(10, 400, 100, 100, 80));
  rig.append(rig.line(11, 400, 300, 100, 60));
  rig.append(rig.line(12, 100, 300, 100, 60));
  rig.feed(true);
  rig.run(1.0);  // cruising along X at 80 mm/s
  REQUIRE(rig.mode() == Mode::Path);
  REQUIRE(rig.hw.velocity().x() > 79);
  rig.stop();
  CHECK(rig.mode() == Mode::Stopping);
  CHECK(rig.hw.stops == 1);
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{10, 11, 12});
  for (auto r : rig.fail_reasons()) CHECK(r == FailReason::Stopped);
  CHECK(rig.ids(EventKind::Done).empty());
  // braking: 80 mm/s at X's 800 mm/s² takes 100 ms
  Vec3 prev = rig.position();
  double v_prev = rig.hw.velocity().x();
  int ticks = 0;
  while (rig.mode() == Mode::Stopping && ticks < 1000) {
    rig.step();
    ++ticks;
    const double v = (rig.position().x() - prev.x()) / 0.001;
    CHECK(v_prev - v <= 800 * 0.001 * (1 + 1e-6) + 1e-9);
    prev = rig.position();
    v_prev = v;
  }
  CHECK(rig.mode() == Mode::Idle);
  CHECK(ticks >= 99);
  CHECK(ticks <= 103);
  // nothing of the dropped queue runs later
  rig.run(0.5);
  CHECK(rig.ids(EventKind::Done).empty());
  CHECK(rig.mode() == Mode::Idle);
}

TEST_CASE("segments sent before a stop and taken after it are failed, never run") {
  FollowerRig rig;
  rig.append(rig.line(20, 200, 100, 100, 50));
  rig.planner().flush();
  planner::PlannedSegment s;
  REQUIRE(rig.planner().take(s));
  imess::core::QueuedSegment q{s, rig.core().stop_ticket(), 0};
  rig.core().request_stop();  // the stop is issued after the segment was stamped
  REQUIRE(rig.core().submit_segment(q));
  rig.step();
  rig.run(0.2);
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{20});
  CHECK(rig.hw.follow_calls == 0);
  CHECK(rig.position().isApprox(Vec3(100, 100, 100)));
}

TEST_CASE("segments sent after a stop, before the loop took it, run once the machine stands") {
  // A Run or MoveTo in the same write after a StopMv or Abort: planned from where the machine
  // stands, stamped with the stop's ticket. The stop fails what was sent before it only.
  FollowerRig rig;
  rig.append(rig.line(21, 200, 100, 100, 50));
  rig.planner().flush();
  planner::PlannedSegment s;
  REQUIRE(rig.planner().take(s));
  rig.core().request_stop();  // the stop is issued before the segment is stamped
  imess::core::QueuedSegment q{s, rig.core().stop_ticket(), 0};
  REQUIRE(rig.core().submit_segment(q));
  rig.step();
  rig.run(3.0);
  CHECK(rig.ids(EventKind::Failed).empty());
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{21});
  CHECK(rig.position().isApprox(Vec3(200, 100, 100)));
}

TEST_CASE("Pause brakes on the path and Resume finishes it at the target") {
  FollowerRig rig;
  rig.append(rig.line(30, 300, 250, 150, 60));
  rig.feed(true);
  rig.run(1.0);
  REQUIRE(rig.mode() == Mode::Path);
  CHECK(rig.send({CommandKind::Pause}) == Refusal::None);
  const Vec3 a(100, 100, 100), b(300, 250, 150), u = (b - a).normalized();
  for (int i = 0; i < 500; ++i) {
    rig.step();
    const Vec3 d = rig.position() - a;
    CHECK((d - d.dot(u) * u).norm() < 1e-9);  // on the line
  }
  CHECK(rig.hw.velocity().norm() == 0);  // held at rest
  CHECK(rig.mode() == Mode::Path);       // still running the queue
  CHECK(rig.core().snapshot().path_held);
  CHECK(rig.core().snapshot().path_id == 30);
  const Vec3 held = rig.position();
  rig.run(0.2);
  CHECK(rig.position() == held);
  CHECK(rig.send({CommandKind::Resume}) == Refusal::None);
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 10));
  rig.step();
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{30});
  CHECK(rig.position().isApprox(b, 1e-12));
}

TEST_CASE("a stop ends a feed hold: the next queue starts moving, not held at its start") {
  FollowerRig rig;
  rig.append(rig.line(40, 300, 100, 100, 60));
  rig.feed(true);
  rig.run(0.5);
  REQUIRE(rig.send({CommandKind::Pause}) == Refusal::None);
  rig.run(0.5);
  REQUIRE(rig.core().snapshot().path_held);
  rig.stop();
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{40});
  CHECK_FALSE(rig.core().snapshot().path_held);
  const Vec3 here = rig.position();
  rig.planner().set_position({here.x(), here.y(), here.z()});
  rig.append(rig.line(41, here.x(), 200, here.z(), 60));
  rig.feed(true);
  CHECK(rig.run_until([&] { return rig.ids(EventKind::Done) == std::vector<std::uint32_t>{41}; }, 10));
  CHECK(rig.position().isApprox(Vec3(here.x(), 200, here.z()), 1e-9));

  // A Pause sent just before a stop reaches the loop after it (the stop lane is read first):
  // it is superseded like a move sent before the stop, and holds nothing.
  rig.planner().set_position({here.x(), 200, here.z()});
  rig.append(rig.line(42, here.x(), 250, here.z(), 60));
  rig.feed(true);
  rig.run(0.3);
  REQUIRE(rig.mode() == Mode::Path);
  imess::core::Command pause{CommandKind::Pause};
  pause.client = 1;
  pause.seq = 4242;
  REQUIRE(rig.core().submit(pause));
  rig.stop();
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  CHECK_FALSE(rig.core().snapshot().path_held);
}

TEST_CASE("a full segment ring refuses the next segment at once and the loop keeps running") {
  FollowerRig rig;
  for (std::uint32_t i = 0; i < 200; ++i) rig.append(rig.line(100 + i, 100 + (i + 1) * 0.5, 100, 100, 50));
  rig.planner().flush();
  int pushed = 0;
  planner::PlannedSegment s;
  bool refused = false;
  while (rig.planner().take(s)) {
    if (!rig.core().submit_segment({s, rig.core().stop_ticket(), 0})) {
      refused = true;
      break;
    }
    ++pushed;
  }
  CHECK(pushed == static_cast<int>(imess::core::kSegmentCapacity));
  CHECK(refused);
  rig.step();  // the loop does not wait for room: it runs
  CHECK(rig.mode() == Mode::Path);
  CHECK(rig.core().segment_room() > 0);
}

TEST_CASE("a probe edge during a queued segment: Failed UnexpectedHit, stop, retract, no point") {
  FollowerRig rig;
  rig.append(rig.line(40, 100, 100, 50, 20));
  rig.append(rig.line(41, 150, 100, 50, 20));
  rig.feed(true);
  rig.run(0.5);
  REQUIRE(rig.mode() == Mode::Path);
  rig.hw.touch();
  rig.step();
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{40, 41});
  for (auto r : rig.fail_reasons()) CHECK(r == FailReason::UnexpectedHit);
  CHECK(rig.take(EventKind::MeasPt).empty());
  auto warns = rig.take(EventKind::Warn);
  REQUIRE(warns.size() == 1);
  CHECK(warns[0].warning == imess::core::Warning::UnexpectedHit);
  CHECK(rig.mode() == Mode::Retract);
  CHECK(rig.take(EventKind::QueueDropped).size() == 1);  // the io side is told to plan anew
}

TEST_CASE("a backend that cannot follow: Failed Faulted for every queued id, the machine stands") {
  FollowerRig rig;
  rig.hw.can_follow = false;
  rig.append(rig.line(50, 120, 100, 100, 20));
  rig.append(rig.line(51, 140, 100, 100, 20));
  rig.feed(true);
  rig.run(0.1);
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{50, 51});
  for (auto r : rig.fail_reasons()) CHECK(r == FailReason::Faulted);
  CHECK(rig.mode() == Mode::Idle);
  CHECK(rig.position() == Vec3(100, 100, 100));
}

TEST_CASE("follow() failing at call N mid-queue fails the running and the queued ids") {
  FollowerRig rig;
  rig.hw.fail_at_call = 300;
  rig.append(rig.line(60, 200, 100, 100, 50));
  rig.append(rig.line(61, 200, 200, 100, 50));
  rig.feed(true);
  rig.run(1.0);
  CHECK(rig.hw.follow_calls == 300);
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{60, 61});
  CHECK(rig.mode() == Mode::Idle);
}

TEST_CASE("GoTo, StartMv and Home while a queue runs are refused Busy — the queue goes on") {
  FollowerRig rig;
  rig.append(rig.line(70, 200, 100, 100, 50));
  rig.feed(true);
  rig.run(0.3);
  REQUIRE(rig.mode() == Mode::Path);
  CHECK(rig.go_to(Vec3(0, 0, 0), 10) == Refusal::Busy);
  CHECK(rig.start_mv(Vec3(10, 0, 0)) == Refusal::Busy);
  CHECK(rig.simple(CommandKind::Home) == Refusal::Busy);
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{70});
}

TEST_CASE("a limit switch entered along the path fails the queue IntoLimit and brakes") {
  FollowerRig rig;
  rig.append(rig.line(80, 300, 100, 100, 50));
  rig.feed(true);
  rig.run(0.5);
  REQUIRE(rig.mode() == Mode::Path);
  rig.hw.inputs[0] = imess::hal::input::kLimitPos;
  rig.step();
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{80});
  CHECK(rig.fail_reasons() == std::vector<FailReason>{FailReason::IntoLimit});
  CHECK(rig.mode() == Mode::Stopping);
}

TEST_CASE("a queue that does not start where the machine stands fails OffPath and does not move") {
  FollowerRig rig;
  planner::Pose elsewhere{50, 50, 50};
  rig.planner().set_position(elsewhere);
  rig.append(rig.line(90, 60, 50, 50, 20));
  rig.feed(true);
  rig.run(0.1);
  CHECK(rig.fail_reasons() == std::vector<FailReason>{FailReason::OffPath});
  CHECK(rig.hw.follow_calls <= 1);
  CHECK(rig.position() == Vec3(100, 100, 100));
}
