// The unchanged MotionCore on the stepper machine: probing with the hit captured at the
// base rate, retract, limits, homing with the synthesised index, and STOP.
#include <catch2/catch.hpp>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;

namespace {
core::CoreConfig stepper_core() {
  core::CoreConfig c;
  c.params.max_speed = 80;
  c.params.max_accel = 2000;
  c.max_velocity = 80;
  c.params.idle_open_time = 60;
  return c;
}
}  // namespace

TEST_CASE("stepper: a jog onto the cube top measures it to one step and retracts") {
  StepperRig rig;
  rig.start_core(stepper_core());
  REQUIRE(rig.start_mv({0, 0, -25}) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  auto pts = rig.take(EventKind::MeasPt);
  REQUIRE(pts.size() == 1);
  CHECK(pts[0].p.z() <= 80.0);
  CHECK(pts[0].p.z() >= 80.0 - 0.001);  // captured at the base rate: within one step (1 um)
  CHECK(pts[0].p.x() == Approx(430));
  CHECK(rig.position().z() == Approx(pts[0].p.z() + 2.5).margin(1e-9));  // 0.5 mm behind the ball centre
  CHECK(!rig.core().machine().tip_touched);
  CHECK(rig.stepper().violations().total() == 0);
}

TEST_CASE("stepper: jogging into the end/ref switch stops with a Limit event, no step lost") {
  auto o = stepper_options();
  o.sim.mechanics.start = axes3(hal::Vec3(8, 330, 100));
  o.driver.initial_position = xyz(o.sim.mechanics.start);
  StepperRig rig(o);
  rig.start_core(stepper_core());
  REQUIRE(rig.start_mv({-30, 0, 0}) == core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
  auto lim = rig.take(EventKind::Limit);
  REQUIRE(lim.size() == 1);
  CHECK(lim[0].axis == 0);
  CHECK(lim[0].side == -1);
  CHECK(rig.mechanics().carriage().x() < -2.0);   // the cam closes 2 mm beyond travel
  CHECK(rig.mechanics().carriage().x() > -20.0);  // stopped before the hard stop
  CHECK(rig.stepper().lost_steps(0) == 0);
  CHECK(rig.position().x() == Approx(rig.mechanics().carriage().x()).margin(1e-6));
  // Moving further in is refused; moving out is allowed.
  CHECK(rig.start_mv({-30, 0, 0}) == core::Refusal::IntoLimit);
  CHECK(rig.start_mv({30, 0, 0}) == core::Refusal::None);
}

TEST_CASE("stepper: homing finds the end/ref switch and the synthesised index, repeatably") {
  auto home_from = [](hal::Vec3 start) {
    auto o = stepper_options();
    o.sim.scene = sim::Scene();
    o.sim.mechanics.start = axes3(start);
    o.driver.initial_position = hal::Vec3(0, 0, 0);  // unknown: counts from wherever it stands
    StepperRig rig(o);
    auto c = stepper_core();
    c.homing.order = {0, 1, 2};
    rig.start_core(c);
    REQUIRE(rig.simple(CommandKind::Home) == core::Refusal::None);
    REQUIRE(rig.run_until([&] { return !rig.take(EventKind::Homed).empty(); }, 60));
    CHECK(rig.core().snapshot().referenced);
    CHECK(rig.stepper().violations().total() == 0);
    return hal::Vec3(xyz(rig.mechanics().carriage()) - rig.position());  // machine frame vs reported
  };
  hal::Vec3 a = home_from({150, 120, 300});
  hal::Vec3 b = home_from({60, 400, 450});
  for (int i = 0; i < 3; ++i) CHECK(a[i] == Approx(b[i]).margin(0.0011));  // the same reference, to a step
  // The index lies half a pitch inside the switch: X's zero is 2 + 2.5 mm from the cam edge.
  CHECK(a.x() == Approx(-2 + 2.5 + 0.02).margin(0.002));
}

TEST_CASE("stepper: STOP stops at once, faults, and asks for a reference run") {
  StepperRig rig;
  auto c = stepper_core();
  c.referenced_at_start = true;
  rig.start_core(c);
  REQUIRE(rig.start_mv({60, 0, 0}) == core::Refusal::None);
  rig.run(0.3);
  REQUIRE(rig.mode() == Mode::Jog);
  rig.stepper().set_stop(true);
  rig.pump().advance_to(rig.clock().now() + hal::Nanos(10'000));  // two base periods
  auto at_stop = rig.stepper().steps(0);
  rig.run(0.2);
  CHECK(rig.stepper().steps(0) - at_stop <= 1);  // a pulse already started may finish
  auto f = rig.take(EventKind::Fault);
  REQUIRE(f.size() == 1);
  CHECK(f[0].fault == core::FaultKind::StopInput);
  CHECK(rig.mode() == Mode::Fault);
  CHECK(!rig.core().snapshot().referenced);
  // Reset while STOP is held: the fault comes straight back.
  rig.simple(CommandKind::Reset);
  rig.run(0.01);
  CHECK(rig.mode() == Mode::Fault);
  rig.stepper().set_stop(false);
  rig.run(0.01);
  rig.simple(CommandKind::Reset);
  rig.run(0.01);
  CHECK(rig.mode() == Mode::Free);
  CHECK(rig.start_mv({-60, 0, 0}) == core::Refusal::None);
  rig.run(0.1);
  CHECK(rig.stepper().steps(0) < at_stop);
}
