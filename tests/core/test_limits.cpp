// Limits under random jogging: switches stop the machine, only moves away are allowed, and
// neither the mechanical end stops nor (once referenced) the soft limits are ever passed.
#include <catch2/catch.hpp>

#include <random>

#include "core_rig.hpp"

using namespace imess::test;
using imess::core::Refusal;

namespace {
RigOptions empty_machine(bool referenced) {
  auto o = default_options();
  o.sim.scene = imess::sim::Scene();  // nothing to hit: this test is about travel
  o.sim.mechanics.start = axes3(Vec3(500, 500, 300));
  o.sim.card.absolute_scales = referenced;
  o.core.referenced_at_start = referenced;
  o.core.params.idle_open_time = 1e9;
  return o;
}

// Random StartMv commands, each held 5..150 ms; check() runs after every cycle.
void random_jogs(CoreRig& rig, int count, unsigned seed, const std::function<void()>& check) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pick(0, 6);
  std::uniform_int_distribution<int> hold_ms(5, 150);
  const double speeds[] = {-100, -20, -2, 0, 2, 20, 100};
  for (int i = 0; i < count; ++i) {
    Vec3 v(speeds[pick(rng)], speeds[pick(rng)], speeds[pick(rng)]);
    auto r = rig.start_mv(v);
    if (r != Refusal::None && r != Refusal::IntoLimit) FAIL("StartMv " << v.transpose() << " refused: " << int(r));
    for (int t = hold_ms(rng); t > 0; --t) {
      rig.step();
      check();
    }
  }
}
}  // namespace

TEST_CASE("10000 random jogs without soft limits: switches stop the machine before the end stops") {
  CoreRig rig(empty_machine(false));
  const auto& axes = rig.options().sim.mechanics.axes;
  long limit_events = 0, fault_cycles = 0;
  Vec3 lo = xyz(rig.mechanics().carriage()), hi = lo;
  random_jogs(rig, 10000, 1996, [&] {
    limit_events += static_cast<long>(rig.take(EventKind::Limit).size());
    rig.clear_events();
    lo = lo.cwiseMin(xyz(rig.mechanics().carriage()));
    hi = hi.cwiseMax(xyz(rig.mechanics().carriage()));
    fault_cycles += rig.mode() == Mode::Fault;
  });
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << a << " went from " << lo[a] << " to " << hi[a]);
    CHECK(lo[a] > axes[a].travel_min - axes[a].hard_margin);
    CHECK(hi[a] < axes[a].travel_max + axes[a].hard_margin);
  }
  CHECK(fault_cycles == 0);
  CHECK(rig.mechanics().hard_stop_hits() == 0);
  CHECK(limit_events > 0);
}

TEST_CASE("10000 random jogs when referenced: the soft limits are never crossed") {
  CoreRig rig(empty_machine(true));
  const auto& axes = rig.options().core.axes;
  Vec3 lo = rig.position(), hi = lo;
  random_jogs(rig, 10000, 2026, [&] {
    lo = lo.cwiseMin(rig.position());
    hi = hi.cwiseMax(rig.position());
    rig.clear_events();
  });
  int ends_reached = 0;
  for (int a = 0; a < 3; ++a) {
    INFO("axis " << a << " went from " << lo[a] << " to " << hi[a]);
    CHECK(lo[a] >= axes[a].travel_min - 0.05);  // servo overshoot (following error) only
    CHECK(hi[a] <= axes[a].travel_max + 0.05);
    ends_reached += (lo[a] < axes[a].travel_min + 1) + (hi[a] > axes[a].travel_max - 1);
  }
  CHECK(ends_reached >= 2);  // the walk did press against the soft limits
  CHECK(rig.mechanics().hard_stop_hits() == 0);
}

TEST_CASE("an axis in a limit switch may only move away from it") {
  CoreRig rig(empty_machine(false));
  rig.start_mv({100, 0, 0});
  REQUIRE(rig.run_until([&] { return !rig.take(EventKind::Limit).empty(); }, 10.0));
  CHECK(rig.mode() == Mode::Stopping);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 1.0));
  CHECK(rig.core().machine().motion_done());
  REQUIRE(rig.core().machine().input(0, imess::hal::input::kLimitPos));
  CHECK(rig.start_mv({20, 0, 0}) == Refusal::IntoLimit);
  CHECK(rig.start_mv({20, 20, 0}) == Refusal::None);  // the X part is dropped, Y moves
  rig.run(0.3);
  CHECK(rig.core().machine().input(0, imess::hal::input::kLimitPos));
  rig.stop();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 1.0));
  CHECK(rig.start_mv({-20, 0, 0}) == Refusal::None);
  rig.run(1.0);
  CHECK_FALSE(rig.core().machine().input(0, imess::hal::input::kLimitPos));
}
