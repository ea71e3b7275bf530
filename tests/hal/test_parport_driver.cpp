// The step/dir driver on the simulated machine, without the core: BRIEF §4's absolute step
// arithmetic (no rounding accumulates), moves end exactly on the commanded step count, the
// configuration refuses speeds the pulse timing cannot make.
#include <catch2/catch.hpp>

#include <random>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;

namespace {
void move_to(StepperRig& rig, const hal::Vec3& mm, double v = 50) {
  hal::AxisArray<hal::AxisMove> m;
  for (int a = 0; a < 3; ++a) m[a] = {mm[a], v, 2000};
  REQUIRE(rig.pump().move(m, 7));
  hal::MachineState ms;
  for (int i = 0; i < 20000; ++i) {
    rig.servo_cycles(1);
    rig.pump().read_state(ms);
    if (ms.motion_done()) return;
  }
  FAIL("move did not end");
}
}  // namespace

TEST_CASE("steps = round(target x steps/mm) + zero offset: returning to a coordinate returns to its step count") {
  StepperRig rig;
  REQUIRE(rig.pump().set_loops(true));
  rig.servo_cycles(2);
  const hal::Vec3 home(430.0004, 330.0006, 99.9996);  // between steps
  move_to(rig, home);
  hal::AxisArray<std::int64_t> at_home{rig.driver().step_count(0), rig.driver().step_count(1), rig.driver().step_count(2)};
  for (int a = 0; a < 3; ++a) CHECK(at_home[a] == rig.driver().steps_for(a, home[a]));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> d(-3.0, 3.0);
  for (int i = 0; i < 25; ++i) {
    move_to(rig, home + hal::Vec3(d(rng), d(rng), d(rng)) * 1.0001);  // never on a step
    move_to(rig, home);
    for (int a = 0; a < 3; ++a) CHECK(rig.driver().step_count(a) == at_home[a]);
  }
  for (int a = 0; a < 3; ++a) CHECK(rig.stepper().steps(a) == at_home[a]);  // the motors agree
  CHECK(rig.stepper().violations().total() == 0);
}

TEST_CASE("set_position redefines the zero offset, not the step count") {
  StepperRig rig;
  auto before = rig.driver().step_count(0);
  REQUIRE(rig.pump().set_position(0, 12.3456));
  hal::MachineState ms;
  rig.servo_cycles(1);
  rig.pump().read_state(ms);
  CHECK(rig.driver().step_count(0) == before);
  CHECK(ms.position.x() == Approx(12.346).margin(1e-9));  // the nearest step
}

TEST_CASE("a speed the pulse timing cannot make is refused at set-up with the figures") {
  auto o = stepper_options();
  o.driver.axes[1].max_speed = 120;  // 120 000 steps/s > 100 000
  CHECK_THROWS_WITH(hal::ParportStepperDriver(*std::make_unique<hal::SharedPortSpace>("", 0x378, 100), VirtualClock(), o.driver),
                    Catch::Contains("axis Y") && Catch::Contains("120000 steps/s") && Catch::Contains("allow 100000"));
}
