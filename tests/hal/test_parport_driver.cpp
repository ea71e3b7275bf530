// The step/dir driver on the simulated machine, without the core: BRIEF §4's absolute step
// arithmetic (no rounding accumulates), moves end exactly on the commanded step count, the
// configuration refuses speeds the pulse timing cannot make.
#include <catch2/catch.hpp>

#include <atomic>
#include <random>
#include <thread>

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

// The SHD adapter with four user outputs: out 1 on data pin 5, out 2 on data pin 9 (active
// low), out 3 on control pin 1 (STROBE, inverted by the port), out 4 on control pin 16.
StepperRigOptions outputs_options() {
  auto o = stepper_options();
  auto& p = o.driver.pins;
  p.pins[5] = hal::parse_pin_signal("out 1");
  p.pins[9] = hal::parse_pin_signal("out 2");
  p.pins[9].invert = true;
  p.pins[1] = hal::parse_pin_signal("out 3");
  p.pins[16] = hal::parse_pin_signal("out 4");
  o.sim.stepper.pins = p;
  return o;
}
constexpr int kOutputPins[4] = {5, 9, 1, 16};

// The level at the connector pin, from the register the driver wrote.
bool pin_high(hal::PortIo& port, int pin) {
  const auto loc = hal::pin_location(pin);
  const bool bit = (port.in8(static_cast<std::uint16_t>(0x378 + loc.offset)) & loc.mask) != 0;
  return bit != loc.hw_inverted;
}
// Whether output n (1..4 of outputs_options) is on, by its pin's level.
bool output_on(hal::PortIo& port, int n) { return pin_high(port, kOutputPins[n - 1]) != (n == 2); }
std::array<bool, 4> outputs_on(hal::PortIo& port) {
  return {output_on(port, 1), output_on(port, 2), output_on(port, 3), output_on(port, 4)};
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

TEST_CASE("parallel-port outputs: each \"out N\" drives its pin, inverted as mapped, at the next base tick") {
  StepperRig rig(outputs_options());
  auto& b = rig.backend();
  REQUIRE(b.output_count() == 4);
  rig.servo_cycles(1);
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{false, false, false, false});
  CHECK_FALSE(pin_high(rig.port(), 5));
  CHECK(pin_high(rig.port(), 9));  // active low: off is high
  CHECK_FALSE(pin_high(rig.port(), 1));
  CHECK_FALSE(pin_high(rig.port(), 16));

  REQUIRE(b.set_output(2, true));
  rig.servo_cycles(1);
  CHECK_FALSE(pin_high(rig.port(), 9));
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{false, true, false, false});
  REQUIRE(b.set_output(3, true));
  REQUIRE(b.set_output(4, true));
  rig.servo_cycles(1);
  CHECK(pin_high(rig.port(), 1));
  CHECK(pin_high(rig.port(), 16));
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{false, true, true, true});
  REQUIRE(b.set_output(1, true));
  REQUIRE(b.set_output(3, false));
  rig.servo_cycles(1);
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{true, true, false, true});

  CHECK_FALSE(b.set_output(0, true));
  CHECK_FALSE(b.set_output(5, true));
  rig.servo_cycles(1);
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{true, true, false, true});

  StepperRig plain;  // the shipped map has no outputs
  CHECK(plain.backend().output_count() == 0);
  CHECK_FALSE(plain.backend().set_output(1, true));
}

TEST_CASE("parallel-port outputs: steps go on beside them, and they hold through moves, loops open, STOP and Reset") {
  StepperRig rig(outputs_options());
  auto& b = rig.backend();
  REQUIRE(b.set_output(1, true));
  REQUIRE(b.set_output(4, true));
  const std::array<bool, 4> on{true, false, false, true};
  REQUIRE(b.set_loops(true));
  rig.servo_cycles(2);
  const hal::Vec3 target(433.5, 328.25, 101);
  hal::AxisArray<hal::AxisMove> m;
  for (int a = 0; a < 3; ++a) m[a] = {target[a], 50, 2000};
  REQUIRE(b.move(m, 7));
  hal::MachineState ms;
  bool held = true;
  for (int i = 0; i < 2000; ++i) {
    rig.servo_cycles(1);
    b.read_state(ms);
    held = held && outputs_on(rig.port()) == on;
    if (ms.motion_done() && i > 10) break;
  }
  CHECK(held);
  REQUIRE(ms.motion_done());
  for (int a = 0; a < 3; ++a) CHECK(rig.stepper().steps(a) == rig.driver().steps_for(a, target[a]));
  CHECK(rig.stepper().violations().total() == 0);

  REQUIRE(b.set_loops(false));
  rig.servo_cycles(5);
  CHECK(outputs_on(rig.port()) == on);
  rig.stepper().set_stop(true);
  rig.servo_cycles(5);
  b.read_state(ms);
  CHECK(ms.any(hal::status::kStopInput));
  CHECK(outputs_on(rig.port()) == on);  // STOP stops the motors, not the outputs
  rig.stepper().set_stop(false);
  rig.servo_cycles(2);
  REQUIRE(b.reset_faults());
  rig.servo_cycles(5);
  CHECK(outputs_on(rig.port()) == on);
  REQUIRE(b.set_output(4, false));
  rig.servo_cycles(1);
  CHECK(outputs_on(rig.port()) == std::array<bool, 4>{true, false, false, false});
}

TEST_CASE("parallel-port outputs: set_output from another thread than the base routine's reaches the registers") {
  StepperRig rig(outputs_options());
  auto& drv = rig.driver();
  REQUIRE(drv.set_loops(true));
  std::atomic<bool> run{true};
  std::atomic<long> ticks{0};
  // The base routine in its own thread, as messd's base thread runs it on real ports.
  std::thread base([&] {
    while (run.load(std::memory_order_relaxed)) {
      drv.base_tick();
      ticks.fetch_add(1, std::memory_order_relaxed);
    }
  });
  auto wait_ticks = [&](long n) {
    const long until = ticks.load() + n;
    while (ticks.load() < until) std::this_thread::yield();
  };
  std::mt19937 rng(11);
  std::array<bool, 4> want{};
  bool agreed = true;
  for (int i = 0; i < 2000; ++i) {
    const int n = static_cast<int>(rng() % 4) + 1;
    want[n - 1] = !want[n - 1];
    REQUIRE(drv.set_output(n, want[n - 1]));
    if (i % 100 == 0) {  // and steps commanded meanwhile: the generator's data-register bits
      hal::AxisArray<hal::AxisMove> m;
      for (int a = 0; a < 3; ++a) m[a] = {rig.options().driver.initial_position[a] + (i % 200 == 0 ? 0.5 : 0.0), 50, 2000};
      drv.move(m, 7);
      hal::MachineState ms;
      drv.read_state(ms);
    }
    if (i % 10 == 0) {
      wait_ticks(2);  // a whole base tick after the call
      agreed = agreed && outputs_on(rig.port()) == want;
    }
  }
  wait_ticks(2);
  run = false;
  base.join();
  CHECK(agreed);
  CHECK(outputs_on(rig.port()) == want);
}
