// Real-time discipline of the servo card's path following: follow(), the read_state() that
// returns its reply, and a stop allocate nothing — counted by replacing the global allocator.
#include <catch2/catch.hpp>

#include "card_follow_rig.hpp"

#include "allocation_counter.hpp"

using namespace imess;
using namespace imess::test;

TEST_CASE("card follow: follow() and the cycle's read_state() allocate nothing") {
  CardFollowRig rig;
  const auto path = rig.sampled_path(corner_and_arc_path());  // planned and sampled beforehand
  hal::MachineState ms;
  long failures = 0;
  g_allocations = 0;
  g_counting = true;
  for (std::size_t i = 0; i < path.size(); ++i) {
    if (!rig.driver().follow(path[i]) || !rig.driver().read_state(ms)) ++failures;
    if (i == path.size() / 2) {
      rig.driver().stop(Vec3::Constant(1000));  // ends following; the next frame starts it again
      rig.driver().read_state(ms);
    }
    rig.tick();
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
  CHECK(failures == 0);
}
