// The simulated stepper machine behind the port: it decodes what the real driver writes,
// so a million steps of random moves on three axes arrive without a lost step or a timing
// violation; and it does catch a driver that breaks the timing.
#include <catch2/catch.hpp>

#include <random>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;

TEST_CASE("a million steps of random moves on three axes: none lost, no timing violation, exact counts") {
  auto o = stepper_options();
  o.sim.scene = sim::Scene();  // nothing to touch: pure motion
  StepperRig rig(o);
  REQUIRE(rig.pump().set_loops(true));
  std::mt19937 rng(1996);
  std::uniform_real_distribution<double> where(-40, 40), speed(5, 90), accel(500, 4000);
  std::uniform_int_distribution<int> cycles_before_retarget(1, 400), mask_dist(1, 7);
  const hal::Vec3 centre = xyz(o.sim.mechanics.start);
  std::int64_t total = 0;
  hal::AxisArray<std::int64_t> last{rig.stepper().steps(0), rig.stepper().steps(1), rig.stepper().steps(2)};
  hal::AxisArray<double> target{centre.x(), centre.y(), centre.z()};
  int moves = 0;
  while (total < 1'000'000) {
    hal::AxisArray<hal::AxisMove> m;
    unsigned mask = static_cast<unsigned>(mask_dist(rng));
    for (int a = 0; a < 3; ++a) {
      if (mask & (1u << a)) target[a] = centre[a] + where(rng);
      m[a] = {target[a], speed(rng), accel(rng)};
    }
    REQUIRE(rig.pump().move(m, mask));  // often retargets an axis still moving, reversing it
    ++moves;
    rig.servo_cycles(cycles_before_retarget(rng));
    for (int a = 0; a < 3; ++a) {
      total += std::abs(rig.stepper().steps(a) - last[a]);
      last[a] = rig.stepper().steps(a);
    }
  }
  // Let everything arrive, then compare: commanded = driver count = motor count.
  hal::MachineState ms;
  for (int i = 0; i < 5000 && !ms.motion_done(); ++i) {
    rig.servo_cycles(1);
    rig.pump().read_state(ms);
  }
  REQUIRE(ms.motion_done());
  INFO(moves << " moves, " << total << " steps");
  CHECK(total >= 1'000'000);
  for (int a = 0; a < 3; ++a) {
    CHECK(rig.driver().step_count(a) == rig.driver().steps_for(a, target[a]));
    CHECK(rig.stepper().steps(a) == rig.driver().step_count(a));
    CHECK(rig.stepper().lost_steps(a) == 0);
    CHECK(rig.mechanics().carriage()[a] == Approx(target[a]).margin(0.0005));
  }
  CHECK(rig.stepper().violations().total() == 0);
  CHECK(rig.port().errors() == 0);
}

TEST_CASE("the machine counts every timing violation of a sloppy driver") {
  sim::Mechanics mech(sim::MechanicsConfig{}, sim::Scene());
  hal::SharedPortSpace port("", 0x378, 100);
  sim::StepperMachineConfig c;  // SHD pins; needs 2 us everywhere
  sim::StepperMachine m(c, mech, port);
  std::int64_t t = 0;
  auto at = [&](std::int64_t dt_ns, std::uint8_t data) {
    t += dt_ns;
    port.out8(0x378, data);
    m.sample(t);
  };
  at(0, 0x00);
  at(10000, 0x11);  // dir X and step X together: no setup time
  CHECK(m.violations().dir_setup == 1);
  at(1000, 0x10);   // 1 us pulse
  CHECK(m.violations().pulse_width == 1);
  at(1000, 0x11);   // 1 us space
  CHECK(m.violations().step_space == 1);
  at(5000, 0x10);
  at(1000, 0x00);   // dir change 1 us after the step ended
  CHECK(m.violations().dir_hold == 1);
  CHECK(m.steps(0) == 2);
  at(10000, 0x01);  // a clean negative step
  CHECK(m.steps(0) == 1);
  CHECK(m.violations().total() == 4);
}

TEST_CASE("switches and STOP reach the status register with the pin map's sense") {
  sim::MechanicsConfig mc;
  mc.start = axes3(hal::Vec3(-3, 330, 100));  // X in its home cam (closes 2 mm beyond travel_min)
  sim::Mechanics mech(mc, sim::Scene());
  hal::SharedPortSpace port("", 0x378, 100);
  sim::StepperMachine m(sim::StepperMachineConfig{}, mech, port);
  m.sample(0);
  std::uint8_t st = port.in8(0x379);
  CHECK((st & 0x40) != 0);  // ACK: end/ref X
  CHECK((st & 0x20) == 0);  // PAPER OUT: end/ref Y open
  CHECK((st & 0x80) != 0);  // BUSY bit set: pin low, STOP released
  m.set_stop(true);
  m.sample(1000);
  CHECK((port.in8(0x379) & 0x80) == 0);
}
