// Real-time discipline of the port backends: neither the servo-rate calls nor the base
// routine allocate — counted by replacing the global allocator while the core jogs, hits,
// retracts, moves, homes and stops on each backend, and while each follows a planned path
// and switches its user outputs (set_output).
#include <catch2/catch.hpp>

#include "follow_rig.hpp"
#include "port_rigs.hpp"

#include "allocation_counter.hpp"

using namespace imess;
using namespace imess::test;

namespace {
void push(MotionRig& rig, core::Command c) { rig.core().submit(c); }
core::CoreConfig brisk() {
  core::CoreConfig c;
  c.params.max_speed = 80;
  c.params.max_accel = 2000;
  c.max_velocity = 80;
  c.params.idle_open_time = 2;
  return c;
}
// Servo periods of follow() from a path planned beforehand, then stop() and a move(), the
// backend's outputs switched on and off meanwhile: the allocations counted inside the loop
// only (the sampler is allocation-free).
template <class Rig>
long allocations_following(Rig& rig, PathFeed& feed, int periods) {
  hal::MachineState ms;
  auto& backend = rig.backend();
  g_allocations = 0;
  g_counting = true;
  bool ok = true;
  REQUIRE(backend.output_count() >= 2);
  for (int i = 0; i < periods; ++i) {
    rig.clock().advance(Rig::kPeriod);
    ok = backend.read_state(ms) && ok;
    if (i % 100 == 0) ok = backend.set_output(1 + (i / 100) % 2, (i / 200) % 2 == 0) && ok;
    if (i < periods / 2) {
      const hal::Setpoint sp = feed.next();
      ok = backend.follow(sp) && ok;
    } else if (i == periods / 2) {
      ok = backend.stop(hal::AxisVec::Constant(2000)) && ok;  // mid-path
    }
  }
  hal::AxisArray<hal::AxisMove> moves;
  for (int a = 0; a < 3; ++a) moves[a] = {ms.position[a] + 1, 20, 1000};
  ok = backend.move(moves, 7) && ok;
  for (int i = 0; i < 200; ++i) {
    rig.clock().advance(Rig::kPeriod);
    ok = backend.read_state(ms) && ok;
  }
  g_counting = false;
  CHECK(ok);
  return g_allocations.load();
}
}  // namespace

TEST_CASE("port backends: follow(), stop() after it and move() after it do not allocate") {
  {
    auto o = stepper_options();
    o.driver.pins.pins[5] = hal::parse_pin_signal("out 1");   // a data pin: the base routine merges it
    o.driver.pins.pins[17] = hal::parse_pin_signal("out 2");  // a control pin
    o.sim.stepper.pins = o.driver.pins;
    StepperRig rig(o);
    hal::MachineState ms;
    rig.servo_cycles(1);
    REQUIRE(rig.backend().read_state(ms));
    REQUIRE(rig.backend().set_loops(true));
    PathFeed feed(follow_machine(rig.options().sim.mechanics, rig.options().driver.axes), xyz(ms.position));
    feed.plan(corner_arc_dwell_path(xyz(ms.position), 80));
    CHECK(allocations_following(rig, feed, 2500) == 0);
  }
  for (int mode : {1, 2}) {
    auto o = drive_options(mode, mode == 1 ? "mrm-b" : "mrm-a");
    DriveRig rig(o);
    hal::MachineState ms;
    rig.clock().advance(MotionRig::kPeriod);
    REQUIRE(rig.backend().read_state(ms));
    REQUIRE(rig.backend().set_loops(true));
    PathFeed feed(follow_machine(o.sim.mechanics, o.driver.axes), xyz(ms.position));
    feed.plan(corner_arc_dwell_path(xyz(ms.position), 120));
    CHECK(allocations_following(rig, feed, 2500) == 0);
  }
}

TEST_CASE("stepper backend: no servo cycle or base tick allocates") {
  StepperRig rig;
  rig.start_core(brisk());
  push(rig, {CommandKind::StartMv, 1, 1, axes3(Vec3(0, 0, -30))});
  CHECK(allocations_over_cycles(rig, 2000) == 0);  // jog, hit at base rate, MeasPt, retract
  CHECK(rig.mode() == Mode::Idle);
  push(rig, {CommandKind::GoTo, 1, 2, axes3(Vec3(380, 300, 120)), 80});
  CHECK(allocations_over_cycles(rig, 3000) == 0);
  CHECK(allocations_over_cycles(rig, 3000) == 0);  // loops open after 2 s
  CHECK(rig.mode() == Mode::Free);
  push(rig, {CommandKind::Home, 1, 3});
  CHECK(allocations_over_cycles(rig, 30000) == 0);
  push(rig, {CommandKind::StartMv, 1, 4, axes3(Vec3(50, 0, 0))});
  CHECK(allocations_over_cycles(rig, 100) == 0);
  rig.core().request_stop();
  CHECK(allocations_over_cycles(rig, 500) == 0);
}

TEST_CASE("drive-kit backend: no servo cycle allocates, in either kit mode") {
  for (int mode : {1, 2}) {
    DriveRig rig(drive_options(mode, mode == 1 ? "mrm-b" : "mrm-a"));
    rig.start_core(brisk(), &rig.mechanics());
    push(rig, {CommandKind::StartMv, 1, 1, axes3(Vec3(0, 0, -30))});
    CHECK(allocations_over_cycles(rig, 2000) == 0);  // jog, latch, MeasPt, retract
    push(rig, {CommandKind::GoTo, 1, 2, axes3(Vec3(380, 300, 120)), 80});
    CHECK(allocations_over_cycles(rig, 3000) == 0);
    CHECK(allocations_over_cycles(rig, 3000) == 0);  // loops open
    push(rig, {CommandKind::HandMv, 1, 3, axes3(Vec3(0, 0, -3)), 10});
    CHECK(allocations_over_cycles(rig, 500) == 0);
    push(rig, {CommandKind::Home, 1, 4});
    CHECK(allocations_over_cycles(rig, 20000) == 0);
    rig.kits().set_safety_open(2, true);
    CHECK(allocations_over_cycles(rig, 100) == 0);  // trip
    CHECK(rig.mode() == Mode::Fault);
  }
}
