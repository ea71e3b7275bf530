// Real-time discipline of the servo card's path following: follow(), the read_state() that
// returns its reply, a stop and switching the probe power (set_output) allocate nothing — on the request/reply link and on the
// stream over the byte-timed line, with a touch-trigger and a measuring probe — and the simulated
// analog probe's reading every step, counted by
// replacing the global allocator.
#include <catch2/catch.hpp>

#include "card_follow_rig.hpp"

#include "allocation_counter.hpp"
#include "imess/sim/mechanics.hpp"

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
      rig.driver().stop(hal::AxisVec::Constant(1000));  // ends following; the next frame starts it again
      rig.driver().read_state(ms);
    }
    if (i % 250 == 0 && !rig.driver().set_output(1, (i / 250) % 2 == 1)) ++failures;  // the probe's power
    rig.tick();
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
  CHECK(failures == 0);
}

TEST_CASE("card stream: the driver's real-time calls on the stream and the byte-timed line allocate nothing") {
  RigOptions o = default_options();
  o.sim.streamed = true;
  // With a touch-trigger probe, and with a measuring one (its deflection in every status frame).
  const bool analog = GENERATE(false, true);
  if (analog) o.sim.mechanics.probe.type = sim::ProbeType::Analog;
  CoreRig rig(o);
  auto& drv = rig.driver();
  hal::MachineState ms;
  hal::Setpoint sp;
  sp.position = axes3(rig.position());
  hal::AxisArray<hal::AxisMove> moves{};
  moves[0] = {sp.position.x() - 5, 50, 500};
  hal::AxisVec latched = hal::AxisVec::Zero();
  long failures = 0, latches = 0;
  double v = 0;
  g_allocations = 0;
  g_counting = true;
  if (!drv.set_loops(true)) ++failures;
  for (int i = 0; i < 3000; ++i) {
    rig.clock().advance(MotionRig::kPeriod);
    if (!drv.read_state(ms)) ++failures;
    // A latch is read as soon as it shows, as the core reads it: the probe power edges'.
    if (ms.latch_valid()) {
      if (!drv.read_latch(latched)) ++failures;
      ++latches;
    }
    if (i < 1000) {  // a path along X (setpoints out, status frames in), then a stop, a move, set_position, reset
      v = std::min(50.0, v + 1.0);
      sp.position.x() += v * 0.001;
      sp.velocity = axes3(Vec3(v, 0, 0));
      if (!drv.follow(sp)) ++failures;
    }
    if (i == 1000 && !drv.stop(hal::AxisVec::Constant(1000))) ++failures;
    if (i == 1500 && !drv.move(moves, 1u)) ++failures;
    if (i % 400 == 0 && !drv.set_output(1, (i / 400) % 2 == 1)) ++failures;  // the probe's power, on the stream
    if (i == 2500) {
      if (!drv.set_position(0, 100) || !drv.reset_faults()) ++failures;
    }
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
  CHECK(failures == 0);
  CHECK(!ms.faulted());
  CHECK(ms.deflection_valid == analog);
  CHECK(drv.stream()->frames_sent() > 250);
  CHECK(drv.stream()->status_frames() > (analog ? 450u : 500u));  // every 5 ms, 6 ms with the deflection
  CHECK(latches >= 7);  // one per probe power edge (initialise()'s and the first set_output's may be one)
}

TEST_CASE("analog probe: the mechanics' step with its deflection reading allocates nothing") {
  sim::MechanicsConfig mc;
  mc.probe.type = sim::ProbeType::Analog;
  mc.probe.analog.noise = 0.0005;
  mc.start.head<3>() = sim::Vec3(430, 330, 82.5);
  sim::Mechanics m(mc, sim::default_scene());
  for (int a = 0; a < 3; ++a) m.set_position_driven(a, true);
  int contacts = 0;
  g_allocations = 0;
  g_counting = true;
  for (int i = 1; i <= 5000; ++i) {  // 0.5 s at the card's sub-tick, down 1.25 mm onto the top
    m.command_position(2, 82.5 - 0.00025 * i);
    m.step(1e-4);
    contacts += m.analog_reading().contact;
  }
  g_counting = false;
  CHECK(g_allocations.load() == 0);
  CHECK(contacts > 1000);
}
