// The drive-kit backend on the simulated kits: the daemon's PID holds the step response
// within the following-error limit in both kit modes, 16-bit counters wrap without losing
// position, each safety input stops motion within one servo period and says which, and the
// core measures with the counters' latch.
#include <catch2/catch.hpp>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;

namespace {
core::CoreConfig drive_core() {
  core::CoreConfig c;
  c.params.max_speed = 80;
  c.params.max_accel = 2000;
  c.max_velocity = 150;
  c.params.idle_open_time = 60;
  c.referenced_at_start = false;
  return c;
}
}  // namespace

TEST_CASE("drive kit mode 1: a 60 mm step at full speed and acceleration stays within the following-error limit") {
  DriveRig rig;
  rig.start_core(drive_core());
  const hal::Vec3 start = rig.position();
  REQUIRE(rig.go_to(start + hal::Vec3(60, 0, 0), 150) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  CHECK(rig.driver().max_following_error_seen(0) < 1.0);
  CHECK(rig.driver().max_following_error_seen(0) > 0.0);
  CHECK(rig.position().x() == Approx(start.x() + 60).margin(0.005));
  CHECK(rig.mechanics().carriage().x() == Approx(start.x() + 60).margin(0.005));
  CHECK(rig.take(EventKind::Fault).empty());
  // 60 mm is 60 000 counts: the 16-bit position port wrapped and the wide count did not.
  CHECK(rig.driver().counts(0) == Approx((start.x() + 60) / 0.001).margin(6));
}

TEST_CASE("drive kit mode 2: increments with the write-back-zero handshake, fractions carried") {
  DriveRig rig(drive_options(2, "mrm-a"));
  rig.start_core(drive_core());
  const hal::Vec3 start = rig.position();
  REQUIRE(rig.go_to(start + hal::Vec3(-20.0004, 7.5, -12.25), 100) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  for (int a = 0; a < 3; ++a) CHECK(rig.driver().max_following_error_seen(a) < 1.0);
  hal::Vec3 error = rig.position() - (start + hal::Vec3(-20.0004, 7.5, -12.25));
  for (int a = 0; a < 3; ++a) CHECK(std::abs(error[a]) < 0.005);  // the in-position window
  CHECK(rig.kits().increments_taken() > 100);
  CHECK(rig.driver().handshake_misses() == 0);
}

TEST_CASE("a blocked axis trips the following-error limit: loops open, DAC zero") {
  DriveRig rig(drive_options_without_switches(hal::Vec3(10, 330, 100)));
  rig.start_core(drive_core());
  REQUIRE(rig.go_to(rig.position() + hal::Vec3(-60, 0, 0), 100) == core::Refusal::None);  // into the end stop
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Fault; }, 5));
  auto f = rig.take(EventKind::Fault);
  REQUIRE(!f.empty());
  CHECK(f[0].fault == core::FaultKind::FollowingError);
  CHECK(rig.mechanics().hard_stop_hits() > 0);
  for (int a = 0; a < 3; ++a) CHECK(rig.port().in16(0x306 + a) == 0);
}

TEST_CASE("each normally-closed safety input stops all motion within one servo period and is named") {
  const core::FaultKind kinds[4] = {core::FaultKind::SafetyInput1, core::FaultKind::SafetyInput2,
                                    core::FaultKind::SafetyInput3, core::FaultKind::SafetyInput4};
  for (int input = 0; input < 4; ++input) {
    DYNAMIC_SECTION("safety input " << input + 1) {
      DriveRig rig;
      rig.start_core(drive_core());
      REQUIRE(rig.start_mv({50, 30, 0}) == core::Refusal::None);
      rig.run(0.3);
      REQUIRE(rig.mode() == Mode::Jog);
      REQUIRE(rig.port().in16(0x306) != 0);
      rig.kits().set_safety_open(input, true);
      rig.step();  // one servo period
      for (int a = 0; a < 3; ++a) CHECK(rig.port().in16(0x306 + a) == 0);  // DACs zero
      CHECK((rig.port().in16(0x303) & 0x7) == 0);                          // amplifiers off
      auto f = rig.take(EventKind::Fault);
      REQUIRE(f.size() == 1);
      CHECK(f[0].fault == kinds[input]);
      CHECK(rig.mode() == Mode::Fault);
      rig.run(0.05);  // the motors coast to rest (4 ms time constant)
      CHECK(std::abs(rig.mechanics().velocity(0)) < 1e-3);
      // Reset while open keeps the fault; closed again, Reset clears it.
      rig.simple(CommandKind::Reset);
      rig.run(0.01);
      CHECK(rig.mode() == Mode::Fault);
      rig.kits().set_safety_open(input, false);
      rig.simple(CommandKind::Reset);
      rig.run(0.01);
      CHECK(rig.mode() == Mode::Free);
    }
  }
}

TEST_CASE("drive kit: the counters latch gives the exact touch point and hand measuring works with open loops") {
  DriveRig rig;
  rig.start_core(drive_core(), &rig.mechanics());
  REQUIRE(rig.start_mv({0, 0, -40}) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  auto pts = rig.take(EventKind::MeasPt);
  REQUIRE(pts.size() == 1);
  CHECK(pts[0].p.z() == Approx(80.0).margin(0.001));
  REQUIRE(rig.simple(CommandKind::Free) == core::Refusal::None);
  rig.run(0.01);
  REQUIRE(rig.send({CommandKind::HandMv, 0, 0, axes3(hal::Vec3(0, 0, 5)), 10}) == core::Refusal::None);
  rig.run(1.0);
  REQUIRE(rig.send({CommandKind::HandMv, 0, 0, axes3(hal::Vec3(0, 0, -8)), 10}) == core::Refusal::None);
  rig.run(1.5);
  auto hand = rig.take(EventKind::MeasPt);
  REQUIRE(hand.size() == 1);
  CHECK(hand[0].p.z() == Approx(80.0).margin(0.001));
}

TEST_CASE("drive kit: homing with home switches and the synthesised index") {
  auto o = drive_options();
  o.sim.scene = sim::Scene();
  o.sim.mechanics.start = axes3(hal::Vec3(150, 120, 300));
  o.driver.initial_position = hal::AxisVec::Zero();
  o.sim.kits.ports.initial_position = o.driver.initial_position;
  DriveRig rig(o);
  rig.start_core(drive_core());
  REQUIRE(rig.simple(CommandKind::Home) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return !rig.take(EventKind::Homed).empty(); }, 60));
  hal::Vec3 offset = xyz(rig.mechanics().carriage()) - rig.position();
  CHECK(offset.x() == Approx(-2 + 2.5 + 0.02).margin(0.01));
}
