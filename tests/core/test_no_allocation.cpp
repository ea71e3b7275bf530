// Real-time discipline: a motion cycle allocates nothing — counted by replacing the global
// allocator while the core jogs, hits, retracts, measures by hand, homes and faults.
#include <catch2/catch.hpp>

#include "core_rig.hpp"
#include "ideal_follower.hpp"
#include "imess/core/event_fd.hpp"
#include "imess/core/interval_stats.hpp"
#include "imess/planner/probe.hpp"
#include "scan_rig.hpp"

#include "allocation_counter.hpp"

using namespace imess::test;

namespace planner = imess::planner;

namespace {
void push(MotionRig& rig, Command c) { rig.core().submit(c); }
}  // namespace

TEST_CASE("no motion cycle allocates: jog, hit, retract, idle, hand hits, GoTo, homing, fault") {
  CoreRig rig;
  push(rig, {CommandKind::StartMv, 1, 1, axes3(Vec3(0, 0, -20))});
  CHECK(allocations_over_cycles(rig, 3000) == 0);  // jog, hit, MeasPt, retract
  CHECK(rig.mode() == Mode::Idle);
  CHECK(allocations_over_cycles(rig, 7500) == 0);  // loops open after 7 s
  CHECK(rig.mode() == Mode::Free);
  push(rig, {CommandKind::HandMv, 1, 2, axes3(Vec3(0, 0, -3)), 10});
  CHECK(allocations_over_cycles(rig, 1000) == 0);  // hand hit
  push(rig, {CommandKind::HandMv, 1, 3, axes3(Vec3(0, 0, 5)), 10});
  CHECK(allocations_over_cycles(rig, 1000) == 0);
  push(rig, {CommandKind::GoTo, 1, 4, axes3(Vec3(300, 300, 200)), 100});
  push(rig, {CommandKind::ForcePt, 1, 5});
  rig.core().set_param(imess::core::ParamId::SpeedLevel, 0.5);
  CHECK(allocations_over_cycles(rig, 4000) == 0);
  push(rig, {CommandKind::Home, 1, 7});
  CHECK(allocations_over_cycles(rig, 60000) == 0);
  rig.core().request_stop();
  push(rig, {CommandKind::Free, 1, 9});
  push(rig, {CommandKind::HandMv, 1, 10, axes3(Vec3(0, 0, -700)), 100});
  CHECK(allocations_over_cycles(rig, 8000) == 0);  // into the table: overtravel fault
  CHECK(rig.mode() == Mode::Fault);
}

TEST_CASE("the eventfd wake-up allocates nothing and fires only for cycles that pushed events") {
  CoreRig rig;
  imess::core::EventFd wake;
  rig.core().set_event_signal(&wake);
  CHECK(allocations_over_cycles(rig, 100) == 0);  // idle: nothing pushed
  CHECK(wake.drain() == 0);
  push(rig, {CommandKind::StartMv, 1, 1, axes3(Vec3(0, 0, -20))});
  CHECK(allocations_over_cycles(rig, 3000) == 0);  // reply, hit, MeasPt, retract, State events
  const auto woken = wake.drain();
  CHECK(woken > 0);
  CHECK(woken < 3000);  // not every cycle: only those with events
  rig.core().set_event_signal(nullptr);
}

TEST_CASE("no motion cycle allocates while running queued segments: follow, Done, hold, resume, stop") {
  FollowerRig rig;
  rig.hw.record = false;  // the double's own log would allocate
  rig.append(rig.line(1, 150, 100, 100, 50));
  rig.append(rig.line(2, 150, 150, 100, 50));
  planner::Arc arc;
  arc.id = 3;
  arc.target = {190, 190, 100};
  arc.centre = {190, 150, 100};
  arc.ccw = false;
  arc.feed = 30;
  rig.append(arc);
  rig.append(planner::Dwell{4, 0.1});
  rig.append(rig.line(5, 300, 190, 120, 60));
  rig.feed(true);
  CHECK(allocations_over_cycles(rig, 1500) == 0);
  CHECK(rig.mode() == Mode::Path);
  push(rig, {CommandKind::Pause, 1, 1});
  CHECK(allocations_over_cycles(rig, 300) == 0);
  push(rig, {CommandKind::Resume, 1, 2});
  CHECK(allocations_over_cycles(rig, 300) == 0);
  rig.core().request_stop();  // fails the rest: Failed events, braking
  CHECK(allocations_over_cycles(rig, 500) == 0);
  CHECK(rig.mode() == Mode::Idle);
  CHECK(rig.hw.follow_calls > 1500);
}

TEST_CASE("no motion cycle allocates in a Probe cycle: approach, search, hit, retract, Done — a miss — an early touch") {
  FollowerRig rig;
  rig.hw.record = false;
  const auto& p = rig.core().params();
  const planner::ProbeGeometry g{p.prehit_distance, p.search_distance, 50, p.probe_speed};
  auto queue = [&](std::uint32_t id, double x) {
    auto c = planner::probe_cycle(id, rig.planner().position(), {x, 100, 100}, g);
    REQUIRE(c);
    if (c->approach) rig.append(*c->approach);
    rig.append(c->search);
    rig.feed(true);
  };
  // a hit in the search: the edge comes while the loop runs (latched where the axes are)
  queue(1, 130);
  CHECK(allocations_over_cycles(rig, 700) == 0);  // approach, into the search
  REQUIRE(rig.mode() == Mode::Path);
  rig.hw.touch();
  CHECK(allocations_over_cycles(rig, 1) == 0);  // the hit: MeasPt, the retract starts
  CHECK(rig.mode() == Mode::Retract);
  rig.hw.tip = false;
  CHECK(allocations_over_cycles(rig, 600) == 0);  // the retract, Done
  REQUIRE(rig.mode() == Mode::Idle);
  // a miss: the search runs out (PartNotFound)
  planner::Pose here{};
  for (int a = 0; a < 3; ++a) here[a] = rig.position()[a];
  rig.planner().set_position(here);
  queue(2, here[0] + 5);
  CHECK(allocations_over_cycles(rig, 4000) == 0);
  CHECK(rig.mode() == Mode::Idle);  // (the events are drained by the counter: test_probe_cycle.cpp checks them)
  // an early touch on the approach: UnexpectedHit, one Failed for the two segments
  for (int a = 0; a < 3; ++a) here[a] = rig.position()[a];
  rig.planner().set_position(here);
  queue(3, here[0] + 60);
  CHECK(allocations_over_cycles(rig, 100) == 0);
  rig.hw.touch();
  CHECK(allocations_over_cycles(rig, 1) == 0);
  rig.hw.tip = false;
  CHECK(allocations_over_cycles(rig, 600) == 0);
  CHECK(rig.mode() == Mode::Idle);
}

TEST_CASE("the loop's interval statistics record and restart without allocating") {
  auto stats = std::make_unique<imess::core::IntervalStats>();
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < 20000; ++i) {
    if (i % 1000 == 0) stats->request_restart();  // another thread's Stats Reset, seen by the next record
    stats->record(i % 50 * 0.7, i % 333 == 0);
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
}

TEST_CASE("no motion cycle allocates while scanning: approach, contact control, points, leave — and a lost contact",
          "[scan]") {
  CoreRig rig(analog_options(Vec3(470, 330, 90), GENERATE(false, true)));
  rig.run(0.2);
  planner::ScanSettings s;
  s.step = 0.05;
  s.speed = 20;
  // Along the top, then off its right edge: points, then Failed ScanLostContact and a stop.
  queue_scan(rig, 1, planner::ScanLineShape{{470, 330, 80}, {540, 330, 80}, {0, 0, 1}}, s);
  CHECK(allocations_over_cycles(rig, 6000) == 0);
  CHECK(rig.mode() == Mode::Idle);  // stopped, at rest (its events drained by the counter: test_scan.cpp checks them)
}

TEST_CASE("no motion cycle allocates on an unknown contour: steering round a corner, points, the stop plane, the back-off",
          "[scan]") {
  CoreRig rig(analog_options(Vec3(510, 290, 45), GENERATE(false, true)));
  rig.run(0.2);
  planner::ScanSettings s;
  s.step = 0.05;
  s.speed = 5;
  s.travel_min = {0, 0, 0};
  s.travel_max = {1000, 1000, 600};
  // Along the cube's front face (y ≈ 300) at z 40, round its right edge (x ≈ 520), along the
  // right face to the plane y 315: Done, backed off along +x.
  planner::ScanContourShape c;
  c.start = {510, 300.05, 40};
  c.start_normal = {0, -1, 0};
  c.plane_normal = {0, 0, 1};
  c.direction = {515, 300.05, 40};
  c.stop = planner::StopBody::Plane;
  c.stop_point = {520, 315, 40};
  c.stop_normal = {0, 1, 0};
  c.end_normal = {1, 0, 0};
  queue_scan(rig, 1, c, s);
  CHECK(allocations_over_cycles(rig, 9000) == 0);
  CHECK(rig.mode() == Mode::Idle);  // ended and backed off (test_scan_contour.cpp checks its events)
  CHECK(rig.core().machine().deflection.norm() < 1e-9);
  CHECK(rig.position().x() > 521);
  CHECK(rig.position().y() > 314);
}
