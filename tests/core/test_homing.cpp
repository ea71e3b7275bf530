// Reference search: after Home the machine coordinates equal the true (world) positions.
#include <catch2/catch.hpp>

#include "core_rig.hpp"

using namespace imess::test;

namespace {
RigOptions relative_scales(Vec3 start) {
  auto o = default_options();
  o.sim.card.absolute_scales = false;
  o.core.referenced_at_start = false;
  o.sim.mechanics.start = axes3(start);
  return o;
}
}  // namespace

TEST_CASE("without homing the zero is where the machine stands at start") {
  CoreRig rig(relative_scales({430, 330, 100}));
  CHECK(rig.position().norm() < 1e-6);
}

TEST_CASE("Home finds switch and index on every axis and zeroes the machine there") {
  CoreRig rig(relative_scales({430, 330, 100}));
  REQUIRE(rig.simple(CommandKind::Home) == imess::core::Refusal::None);
  REQUIRE(rig.mode() == Mode::Home);
  REQUIRE(rig.run_until([&] { return rig.mode() != Mode::Home; }, 240.0));
  CHECK(rig.take(EventKind::Warn).empty());
  REQUIRE(rig.take(EventKind::Homed).size() == 1);
  CHECK(rig.mode() == Mode::Idle);
  Vec3 error = rig.position() - xyz(rig.mechanics().carriage());
  CHECK(error.cwiseAbs().maxCoeff() < 0.001);
  CHECK(rig.core().snapshot().homed);
}

TEST_CASE("Home from close to the switch backs off and searches again") {
  CoreRig rig(relative_scales({10, 15, 590}));
  REQUIRE(rig.simple(CommandKind::Home) == imess::core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() != Mode::Home; }, 240.0));
  REQUIRE(rig.take(EventKind::Homed).size() == 1);
  CHECK((rig.position() - xyz(rig.mechanics().carriage())).cwiseAbs().maxCoeff() < 0.001);
}

TEST_CASE("StopMv aborts homing") {
  CoreRig rig(relative_scales({430, 330, 100}));
  rig.simple(CommandKind::Home);
  rig.run(1.0);
  rig.stop();
  CHECK(rig.mode() == Mode::Stopping);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 1.0));
  CHECK_FALSE(rig.core().snapshot().homed);
}

TEST_CASE("a failed homing says why: Warn HomingFailed carries the phase's reason") {
  auto o = relative_scales({430, 330, 100});
  o.core.homing.phase_timeout = 0.5;  // the Z search needs seconds: this phase must time out
  CoreRig rig(o);
  REQUIRE(rig.simple(CommandKind::Home) == imess::core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() != Mode::Home; }, 5.0));
  auto warns = rig.take(EventKind::Warn);
  REQUIRE(warns.size() == 1);
  CHECK(warns[0].warning == imess::core::Warning::HomingFailed);
  REQUIRE(warns[0].reason != nullptr);
  CHECK(std::string(warns[0].reason).find("timed out") != std::string::npos);
  CHECK(rig.mode() == Mode::Stopping);  // brakes with the configured deceleration, then stands
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 2.0));
  CHECK_FALSE(rig.core().snapshot().homed);
}
