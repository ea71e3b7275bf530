// The drive kit's user outputs on the simulated port space: each output is its one bit of
// its port (map B: 0x302 bits 0..7; map A: the outputs port 0x30C bits 9..15 above the
// amplifier enables), set and cleared by read-modify-write without touching other bits; a
// safety trip or a following error switches them all off; bad numbers and bad tables are
// refused.
#include <catch2/catch.hpp>

#include "port_rigs.hpp"

using namespace imess;
using namespace imess::test;

namespace {
// Servo periods without the core, as the core would read.
void servo_cycles(DriveRig& rig, int n) {
  hal::MachineState ms;
  for (int i = 0; i < n; ++i) {
    rig.clock().advance(MotionRig::kPeriod);
    rig.pump().read_state(ms);
  }
}
}  // namespace

TEST_CASE("drive kit outputs, map B: outputs 1-8 are port 0x302 bits 0-7, each switched alone") {
  DriveRig rig;
  auto& b = rig.backend();
  REQUIRE(b.output_count() == 8);
  servo_cycles(rig, 2);
  CHECK(rig.port().in16(0x302) == 0);  // all off after initialise
  const std::uint16_t enables_before = rig.port().in16(0x303);
  REQUIRE(b.set_loops(true));
  const std::uint16_t enables = rig.port().in16(0x303);
  CHECK((enables & 0x7) == 0x7);
  CHECK(enables_before == 0);

  REQUIRE(b.set_output(1, true));  // the manual's gripper
  CHECK(rig.port().in16(0x302) == 0x0001);
  REQUIRE(b.set_output(8, true));
  CHECK(rig.port().in16(0x302) == 0x0081);
  REQUIRE(b.set_output(3, true));
  CHECK(rig.port().in16(0x302) == 0x0085);
  REQUIRE(b.set_output(1, false));
  CHECK(rig.port().in16(0x302) == 0x0084);
  REQUIRE(b.set_output(1, false));  // already off: stays so
  CHECK(rig.port().in16(0x302) == 0x0084);
  CHECK(rig.port().in16(0x303) == enables);  // the outputs port untouched

  // Loops open and closed, faults reset, the servo cycles run: the outputs stay.
  REQUIRE(b.set_loops(false));
  servo_cycles(rig, 20);
  REQUIRE(b.reset_faults());
  REQUIRE(b.set_loops(true));
  servo_cycles(rig, 20);
  CHECK(rig.port().in16(0x302) == 0x0084);

  CHECK_FALSE(b.set_output(0, true));
  CHECK_FALSE(b.set_output(9, true));
  CHECK_FALSE(b.set_output(-1, false));
  CHECK(rig.port().in16(0x302) == 0x0084);
}

TEST_CASE("drive kit outputs, map A: outputs 1-7 are bits 9-15 of the outputs port, beside the amplifier enables") {
  DriveRig rig(drive_options(2, "mrm-a"));
  auto& b = rig.backend();
  REQUIRE(b.output_count() == 7);
  servo_cycles(rig, 2);
  CHECK(rig.port().in16(0x30C) == 0);
  REQUIRE(b.set_output(1, true));
  CHECK(rig.port().in16(0x30C) == 0x0200);
  REQUIRE(b.set_loops(true));  // the enables join the outputs
  CHECK(rig.port().in16(0x30C) == 0x0207);
  REQUIRE(b.set_output(7, true));
  CHECK(rig.port().in16(0x30C) == 0x8207);
  REQUIRE(b.set_output(1, false));
  CHECK(rig.port().in16(0x30C) == 0x8007);  // the enables untouched
  REQUIRE(b.set_loops(false));
  CHECK(rig.port().in16(0x30C) == 0x8000);  // and the outputs untouched by the enables
  CHECK(rig.port().in16(0x302) == 0);       // map A's command port Y: never an output
  CHECK_FALSE(b.set_output(8, true));
}

TEST_CASE("drive kit outputs: a safety input trip switches every output off — on is refused until Reset") {
  for (const char* map : {"mrm-b", "mrm-a"}) {
    DYNAMIC_SECTION(map) {
      const bool a = std::string(map) == "mrm-a";
      const std::uint16_t port = a ? 0x30C : 0x302;
      const std::uint16_t out1 = a ? 0x0200 : 0x0001, out2 = a ? 0x0400 : 0x0002;
      DriveRig rig(drive_options(1, map));
      auto& b = rig.backend();
      servo_cycles(rig, 2);
      REQUIRE(b.set_loops(true));
      REQUIRE(b.set_output(1, true));
      REQUIRE(b.set_output(2, true));
      REQUIRE((rig.port().in16(port) & (out1 | out2)) == (out1 | out2));
      rig.kits().set_safety_open(1, true);
      servo_cycles(rig, 1);  // one servo period
      CHECK((rig.port().in16(port) & (out1 | out2)) == 0);
      CHECK((rig.port().in16(a ? 0x30C : 0x303) & 0x7) == 0);  // amplifiers off too
      CHECK_FALSE(b.set_output(1, true));                      // held off while the fault is latched
      CHECK((rig.port().in16(port) & out1) == 0);
      CHECK(b.set_output(2, false));                           // off is always taken
      rig.kits().set_safety_open(1, false);
      servo_cycles(rig, 2);
      CHECK_FALSE(b.set_output(1, true));  // closed again, but not yet reset
      REQUIRE(b.reset_faults());
      servo_cycles(rig, 1);
      REQUIRE(b.set_output(1, true));
      CHECK((rig.port().in16(port) & (out1 | out2)) == out1);
    }
  }
}

TEST_CASE("drive kit outputs: a following-error trip switches the outputs off") {
  DriveRig rig(drive_options_without_switches(hal::Vec3(10, 330, 100)));
  core::CoreConfig c;
  c.params.max_speed = 80;
  c.params.max_accel = 2000;
  c.max_velocity = 150;
  c.referenced_at_start = false;
  rig.start_core(c);
  REQUIRE(rig.backend().set_output(4, true));
  REQUIRE(rig.go_to(rig.position() + hal::Vec3(-60, 0, 0), 100) == core::Refusal::None);  // into the end stop
  CHECK(rig.port().in16(0x302) == 0x0008);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Fault; }, 5));
  auto f = rig.take(EventKind::Fault);
  REQUIRE(!f.empty());
  CHECK(f[0].fault == core::FaultKind::FollowingError);
  CHECK(rig.port().in16(0x302) == 0);
}

TEST_CASE("drive kit outputs: a table of outputs on other ports, and tables that cannot work") {
  auto o = drive_options();
  o.driver.output_count = 3;
  o.driver.outputs[0] = {0x301, 0x0004};  // a port of its own
  o.driver.outputs[1] = {0x303, 0x0100};  // the outputs port, above the enables
  o.driver.outputs[2] = {0x301, 0x8000};  // the first port again: one shadow for both
  o.sim.kits.ports = o.driver;
  DriveRig rig(o);
  auto& b = rig.backend();
  REQUIRE(b.output_count() == 3);
  REQUIRE(b.set_output(1, true));
  REQUIRE(b.set_output(3, true));
  CHECK(rig.port().in16(0x301) == 0x8004);
  REQUIRE(b.set_output(1, false));
  CHECK(rig.port().in16(0x301) == 0x8000);
  REQUIRE(b.set_loops(true));
  REQUIRE(b.set_output(2, true));
  CHECK(rig.port().in16(0x303) == 0x0107);
  CHECK(rig.port().in16(0x302) == 0);  // the map's outputs are replaced
  CHECK_FALSE(b.set_output(4, true));

  auto bad = [](auto change) {
    hal::DriveKitConfig c = *hal::named_drive_kit_map("mrm-b");
    change(c);
    return c;
  };
  using Catch::Contains;
  CHECK_NOTHROW(hal::validate_drive_kit_outputs(*hal::named_drive_kit_map("mrm-a", 5)));  // the MRM arm's five axes
  // Map A's positions reach its outputs port at the seventh axis (0x306 + 6).
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(*hal::named_drive_kit_map("mrm-a", 7)),
                    Contains("output 1 (port 0x30C bit 9)") && Contains("axis 7's position port"));
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(bad([](auto& c) { c.outputs[1] = {0x303, 0x0002}; })),
                    Contains("output 2 (port 0x303 bit 1)") && Contains("axis Y's amplifier enable"));
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(bad([](auto& c) { c.outputs[0] = {0x302, 0x0003}; })),
                    Contains("output 1 (port 0x302 mask 0x3)") && Contains("one bit"));
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(bad([](auto& c) { c.outputs[4] = {0x304, 0x0800}; })),
                    Contains("output 5 (port 0x304 bit 11)") && Contains("inputs port"));
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(bad([](auto& c) { c.outputs[2] = {0x307, 0x0001}; })),
                    Contains("axis Y's command port"));
  CHECK_THROWS_WITH(hal::validate_drive_kit_outputs(bad([](auto& c) { c.outputs[7] = {0x302, 0x0001}; })),
                    Contains("output 8 (port 0x302 bit 0)") && Contains("output 1 is that bit already"));
  // The driver refuses the same at construction.
  auto o2 = drive_options();
  o2.driver.outputs[0] = {0x303, 0x0001};
  o2.sim.kits.ports = o2.driver;
  CHECK_THROWS_WITH(DriveRig(o2), Contains("axis X's amplifier enable"));
}
