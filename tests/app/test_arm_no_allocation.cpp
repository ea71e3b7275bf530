// Real-time discipline on five axes: the motion core and the drive kits of the MRM arm
// (config/sim-mrm-arm.json) allocate nothing per cycle while rotary and linear axes jog,
// stop, follow a five-axis planned segment and home — counted by replacing the allocator.
#include <catch2/catch.hpp>

#include "config_rig.hpp"
#include "imess/core/path_machine.hpp"

#include "allocation_counter.hpp"

using namespace imess;
using namespace imess::test;

namespace {
long counted_cycles(ConfigRig& rig, int cycles) {
  g_allocations = 0;
  g_counting = true;
  for (int i = 0; i < cycles; ++i) rig.step([](const core::Event&) {});
  g_counting = false;
  return g_allocations.load();
}
}  // namespace

TEST_CASE("the MRM arm's cycles allocate nothing: jog C and U, stop, a five-axis segment, homing") {
  ConfigRig rig(std::string(IMESS_SOURCE_DIR) + "/config/sim-mrm-arm.json");
  CHECK(counted_cycles(rig, 50) == 0);
  core::Command jog{core::CommandKind::JogAx};
  jog.v[2] = 40;
  jog.v[3] = -30;
  rig.core().submit(jog);
  CHECK(counted_cycles(rig, 500) == 0);
  rig.core().request_stop();
  CHECK(counted_cycles(rig, 300) == 0);

  // The segment is planned and queued before counting (the io side may allocate).
  planner::Planner p(core::path_machine(rig.core().config()), core::path_options(rig.core().config()));
  planner::Pose here{};
  for (int a = 0; a < 5; ++a) here[a] = rig.core().snapshot().position[a];
  p.set_position(here);
  planner::Line l{1, here, 40};
  l.target[0] += 30;
  l.target[1] -= 20;
  l.target[2] -= 40;
  l.target[3] += 25;
  l.target[4] += 50;
  REQUIRE(p.append(l).ok());
  p.flush();
  planner::PlannedSegment seg;
  while (p.take(seg)) REQUIRE(rig.core().submit_segment({seg, rig.core().stop_ticket(), 0}));
  CHECK(counted_cycles(rig, 3000) == 0);
  CHECK(rig.core().mode() == core::Mode::Idle);

  core::Command home{core::CommandKind::Home};
  rig.core().submit(home);
  CHECK(counted_cycles(rig, 20000) == 0);
}
