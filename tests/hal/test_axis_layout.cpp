// The axis model: layouts from letters (and their refusals), the Cartesian part of a machine
// vector, and MachineState::all/any over the machine's own axes only.
#include <catch2/catch.hpp>

#include <stdexcept>

#include "imess/hal/drive_kit_driver.hpp"
#include "imess/hal/motion_backend.hpp"

using namespace imess::hal;

TEST_CASE("layouts from letters: kinds by letter, the Cartesian axes, the 1996 machine") {
  const AxisLayout xyz = make_layout("XYZ");
  CHECK(xyz.is_xyz());
  CHECK(AxisLayout{}.is_xyz());
  const AxisLayout arm = make_layout("XYCUV");
  CHECK_FALSE(arm.is_xyz());
  CHECK(arm.count == 5);
  CHECK(arm.kinds[2] == AxisKind::Rotary);  // C
  CHECK(arm.kinds[3] == AxisKind::Linear);  // U by its letter (the arm's config says rotary)
  CHECK(arm.index_of('C') == 2);
  CHECK(arm.index_of('Z') == -1);
  const AxisVec p = (AxisVec() << 200, 150, 90, -30, 45, 0, 0, 0, 0).finished();
  CHECK(arm.cartesian(p) == Vec3(200, 150, 0));  // no Z: 0
  CHECK(arm.machine(Vec3(1, 2, 3)) == (AxisVec() << 1, 2, 0, 0, 0, 0, 0, 0, 0).finished());
  AxisLayout rotary_x = make_layout("XYZ");
  rotary_x.kinds[0] = AxisKind::Rotary;  // not a Cartesian axis any more
  CHECK(rotary_x.cartesian(p).x() == 0);
  CHECK_FALSE(rotary_x.is_xyz());
  CHECK(make_layout("ZYX").cartesian(p) == Vec3(90, 150, 200));
}

TEST_CASE("layouts refuse what is not 1..9 distinct letters of XYZABCUVW, saying what is accepted") {
  for (const char* bad : {"", "XYZABCUVWX", "XYQ", "XYX", "xyz"}) {
    INFO(bad);
    CHECK_THROWS_WITH(make_layout(bad), Catch::Contains("X Y Z A B C U V W"));
  }
  CHECK_NOTHROW(make_layout("XYZABCUVW"));
  CHECK_NOTHROW(make_layout("C"));
}

TEST_CASE("MachineState::all/any look at the machine's axes only") {
  MachineState ms;
  ms.count = 5;
  for (int a = 0; a < 5; ++a) ms.status[a] = status::kClosedLoop;
  CHECK(ms.loops_closed());
  ms.status[4] = 0;  // the fifth axis open
  CHECK_FALSE(ms.loops_closed());
  ms.count = 4;
  CHECK(ms.loops_closed());
  ms.status[6] = status::kFollowingError;  // beyond the count: never counts
  CHECK_FALSE(ms.faulted());
  ms.status[3] |= status::kFollowingError;
  CHECK(ms.faulted());
}

TEST_CASE("the drive kits' port maps continue for more axes: map A for the arm is BRIEF's") {
  auto a = named_drive_kit_map("mrm-a", 5);
  REQUIRE(a);
  for (int i = 0; i < 5; ++i) {
    CHECK(a->axes[i].command_port == 0x301 + i);
    CHECK(a->axes[i].position_port == 0x306 + i);
    CHECK(a->axes[i].latch_port == 0x30D + i);
    CHECK(a->axes[i].enable_bit == (1u << i));
  }
  CHECK(a->latch_status_port == 0x312);
  CHECK(a->inputs2_port == 0x313);
  CHECK(a->axes[3].inputs_bank == 1);
  CHECK(a->axes[3].limit_neg_bit == 0x0001);
  CHECK(a->axes[4].home_bit == 0x0020);
  auto b = named_drive_kit_map("mrm-b", 5);  // BRIEF map B: DAC 0x306-0x30A, position 0x30B-0x30F
  REQUIRE(b);
  CHECK(b->axes[4].command_port == 0x30A);
  CHECK(b->axes[4].position_port == 0x30F);
  auto three = named_drive_kit_map("mrm-a");  // three axes: as before
  REQUIRE(three);
  CHECK(three->latch_status_port == 0x310);
  CHECK(three->inputs2_port == 0);
  CHECK_FALSE(named_drive_kit_map("mrm-a", 10));
}
