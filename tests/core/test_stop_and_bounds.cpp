// Stop means stop, and every motion is bounded: the problems an attacker found, each as a
// test — a client-set MaxAccel cannot weaken a stop or homing, tiny components cannot
// drive an axis at full speed, a stop never waits behind queued commands.
#include <catch2/catch.hpp>

#include <cmath>

#include "core_rig.hpp"

using namespace imess::test;
using imess::core::ParamId;
using imess::core::Refusal;

namespace {
RigOptions open_floor(Vec3 start) {  // no workpiece in the way
  auto o = default_options();
  o.sim.scene = {};
  o.sim.mechanics.start = axes3(start);
  o.core.params.idle_open_time = 1e9;
  return o;
}
double braking_distance(double v, double a) { return v * v / (2 * a); }
}  // namespace

TEST_CASE("StopMv brakes with the configured deceleration even after a client set MaxAccel 1") {
  CoreRig rig(open_floor({475, 500, 300}));
  REQUIRE(rig.start_mv({100, 0, 0}) == Refusal::None);  // 100 mm/s toward X+
  rig.run(0.3);
  rig.set(ParamId::MaxAccel, 1);  // another client's hostile setting
  const double x0 = rig.position().x();
  rig.stop();
  const double allowed = braking_distance(100, rig.core().config().axes[0].max_accel) + 0.5;  // + one cycle, servo lag
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 2.0));
  CHECK(rig.position().x() - x0 < allowed);
  rig.run(0.5);
  CHECK(rig.position().x() - x0 < allowed);
  CHECK(rig.take(EventKind::Limit).empty());
}

TEST_CASE("State idle comes only when every axis is at rest") {
  CoreRig rig(open_floor({475, 500, 300}));
  rig.start_mv({100, 50, 0});
  rig.run(0.3);
  rig.clear_events();
  rig.stop();
  CHECK(rig.mode() == Mode::Stopping);
  Vec3 last = rig.position();
  REQUIRE(rig.run_until([&] {
    if (rig.mode() == Mode::Idle) return true;
    last = rig.position();
    return false;
  }, 2.0));
  // At the first idle cycle the machine stands: the previous cycle's position equals this one.
  CHECK((rig.position() - last).norm() < 1e-3);
  auto states = rig.take(EventKind::State);
  REQUIRE(states.size() == 2);
  CHECK(states[0].mode == Mode::Stopping);
  CHECK(states[1].mode == Mode::Idle);
}

TEST_CASE("a runtime MaxAccel or MaxSpeed only lowers motion below the configured limits") {
  CoreRig rig(open_floor({200, 500, 300}));
  rig.set(ParamId::MaxAccel, 20000);
  rig.set(ParamId::MaxSpeed, 1000);
  rig.start_mv({100, 0, 0});
  Vec3 prev = rig.position();
  double top = 0;
  for (int i = 0; i < 2000; ++i) {
    rig.step();
    top = std::max(top, (rig.position() - prev).norm() / 1e-3);
    prev = rig.position();
  }
  CHECK(top <= rig.core().config().max_velocity * 1.02);
  CHECK(top > rig.core().config().max_velocity * 0.9);
}

TEST_CASE("homing with a client-set MaxAccel 20 stays within the switches") {
  auto o = default_options();
  o.sim.card.absolute_scales = false;
  o.core.referenced_at_start = false;
  o.sim.mechanics.start = axes3({430, 330, 590});
  CoreRig rig(o);
  rig.set(ParamId::MaxAccel, 20);
  REQUIRE(rig.simple(CommandKind::Home) == Refusal::None);
  double z_max = 0;
  REQUIRE(rig.run_until([&] {
    z_max = std::max(z_max, rig.mechanics().carriage().z());
    return rig.mode() != Mode::Home;
  }, 240.0));
  CHECK(rig.take(EventKind::Homed).size() == 1);
  CHECK(rig.take(EventKind::Limit).empty());
  const auto& ax = rig.options().sim.mechanics.axes[2];
  CHECK(z_max < ax.travel_max + ax.limit_margin);  // the home cam is found and braked for before the limit
}

TEST_CASE("an axis with a negligible share of a jog does not move") {
  CoreRig rig(open_floor({500, 500, 300}));
  REQUIRE(rig.start_mv({0, 1e-8, 20}) == Refusal::None);
  rig.run(1.0);
  CHECK(std::abs(rig.position().y() - 500) < 1e-6);
  CHECK(rig.position().z() > 310);
  rig.stop();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 1.0));
  rig.run(0.5);  // settled

  const Vec3 start = rig.position();
  REQUIRE(rig.start_mv({100, 5e-8, 5e-8}) == Refusal::None);
  Vec3 prev = rig.position();
  double top = 0;
  for (int i = 0; i < 1000; ++i) {
    rig.step();
    top = std::max(top, (rig.position() - prev).norm() / 1e-3);
    prev = rig.position();
  }
  CHECK(std::abs(rig.position().y() - start.y()) < 1e-6);
  CHECK(std::abs(rig.position().z() - start.z()) < 1e-6);
  CHECK(top <= 100 * 1.02);
}

TEST_CASE("speeds below the minimum are refused, and a GoTo never hangs in move") {
  CoreRig rig(open_floor({500, 500, 300}));
  CHECK(rig.start_mv({0, 1e-9, 0}) == Refusal::TooSlow);
  CHECK(rig.go_to({430, 330, 110}, 1e-300) == Refusal::TooSlow);
  CHECK(rig.go_to({430, 330, 110}, 0.5 * imess::core::kMinSpeed) == Refusal::TooSlow);
  CHECK(rig.mode() != Mode::Move);
  REQUIRE(rig.go_to({500, 500, 300 + 1e-6}, 10) == Refusal::None);  // nothing to do: no axis moves
  CHECK(rig.mode() != Mode::Move);
  REQUIRE(rig.go_to({430, 330, 110}, 100) == Refusal::None);
  CHECK(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 10.0));
}

TEST_CASE("a stop never waits behind queued commands, and supersedes the motion queued before it") {
  CoreRig rig(open_floor({500, 500, 300}));
  Command jog{CommandKind::StartMv, 1, 900, axes3(Vec3(100, 0, 0))};
  Command go{CommandKind::GoTo, 1, 901, axes3(Vec3(100, 100, 100)), 100};
  rig.core().submit(jog);
  rig.core().submit(go);
  rig.core().request_stop();  // arrives before the loop took either
  rig.run(1.0);
  CHECK((rig.position() - Vec3(500, 500, 300)).norm() < 1e-3);
  int ok = 0;
  for (const auto& e : rig.events())
    if (e.kind == EventKind::Reply && (e.seq == 900 || e.seq == 901) && e.refusal == Refusal::None) ++ok;
  CHECK(ok == 2);  // each answered, none started
  CHECK(rig.start_mv({20, 0, 0}) == Refusal::None);  // a command after the stop runs
  rig.run(0.5);
  CHECK(rig.position().x() > 505);
}

TEST_CASE("a Set sent before a motion command applies to it") {
  CoreRig rig(open_floor({500, 500, 300}));
  rig.core().set_param(ParamId::SpeedLevel, 0.5);
  rig.start_mv({0, 0, 100});  // same cycle as the Set
  rig.run(1.0);
  const double z0 = rig.position().z();
  rig.run(1.0);
  CHECK(rig.position().z() - z0 == Approx(50).margin(0.5));
}

// The 1996 jog panel's own sequence: press (StartMv 0 0 -20), the probe hits, the button is
// released (StopMv) 0-200 ms after the hit, pressed again. The retract must finish and leave
// the tip free, and the second press must move the machine.
TEST_CASE("the 1996 panel: a release during the retract lets it finish, then the next press moves") {
  for (int delay_ms = 0; delay_ms <= 200; delay_ms += 10) {
    INFO("StopMv " << delay_ms << " ms after the hit");
    CoreRig rig;
    REQUIRE(rig.start_mv({0, 0, -20}) == Refusal::None);
    REQUIRE(rig.run_until([&] { return !rig.take(EventKind::MeasPt).empty(); }, 3.0));
    rig.run(delay_ms / 1000.0);
    rig.stop();
    REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 3.0));
    CHECK_FALSE(rig.mechanics().tip_contact());
    CHECK(rig.position().z() == Approx(82.5).margin(0.005));
    CHECK(rig.take(EventKind::Warn).empty());
    CHECK(rig.start_mv({0, 0, -20}) == Refusal::None);  // pressed again: toward the part, a new hit
    REQUIRE(rig.run_until([&] { return !rig.take(EventKind::MeasPt).empty(); }, 3.0));
    CHECK(rig.take(EventKind::Warn).empty());
  }
}

TEST_CASE("a press during the retract starts once the retract is done") {
  CoreRig rig;
  rig.start_mv({0, 0, -20});
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Retract; }, 3.0));
  CHECK(rig.start_mv({0, 0, 20}) == Refusal::None);
  CHECK(rig.mode() == Mode::Retract);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Jog; }, 3.0));
  CHECK_FALSE(rig.mechanics().tip_contact());
  rig.run(0.5);
  CHECK(rig.position().z() > 85);
}
