// Real-time discipline of the port backends: neither the servo-rate calls nor the base
// routine allocate — counted by replacing the global allocator while the core jogs, hits,
// retracts, moves, homes and stops on each backend.
#include <catch2/catch.hpp>

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
}  // namespace

TEST_CASE("stepper backend: no servo cycle or base tick allocates") {
  StepperRig rig;
  rig.start_core(brisk());
  push(rig, {CommandKind::StartMv, 1, 1, Vec3(0, 0, -30)});
  CHECK(allocations_over_cycles(rig, 2000) == 0);  // jog, hit at base rate, MeasPt, retract
  CHECK(rig.mode() == Mode::Idle);
  push(rig, {CommandKind::GoTo, 1, 2, Vec3(380, 300, 120), 80});
  CHECK(allocations_over_cycles(rig, 3000) == 0);
  CHECK(allocations_over_cycles(rig, 3000) == 0);  // loops open after 2 s
  CHECK(rig.mode() == Mode::Free);
  push(rig, {CommandKind::Home, 1, 3});
  CHECK(allocations_over_cycles(rig, 30000) == 0);
  push(rig, {CommandKind::StartMv, 1, 4, Vec3(50, 0, 0)});
  CHECK(allocations_over_cycles(rig, 100) == 0);
  rig.core().request_stop();
  CHECK(allocations_over_cycles(rig, 500) == 0);
}

TEST_CASE("drive-kit backend: no servo cycle allocates, in either kit mode") {
  for (int mode : {1, 2}) {
    DriveRig rig(drive_options(mode, mode == 1 ? "mrm-b" : "mrm-a"));
    rig.start_core(brisk(), &rig.mechanics());
    push(rig, {CommandKind::StartMv, 1, 1, Vec3(0, 0, -30)});
    CHECK(allocations_over_cycles(rig, 2000) == 0);  // jog, latch, MeasPt, retract
    push(rig, {CommandKind::GoTo, 1, 2, Vec3(380, 300, 120), 80});
    CHECK(allocations_over_cycles(rig, 3000) == 0);
    CHECK(allocations_over_cycles(rig, 3000) == 0);  // loops open
    push(rig, {CommandKind::HandMv, 1, 3, Vec3(0, 0, -3), 10});
    CHECK(allocations_over_cycles(rig, 500) == 0);
    push(rig, {CommandKind::Home, 1, 4});
    CHECK(allocations_over_cycles(rig, 20000) == 0);
    rig.kits().set_safety_open(2, true);
    CHECK(allocations_over_cycles(rig, 100) == 0);  // trip
    CHECK(rig.mode() == Mode::Fault);
  }
}
