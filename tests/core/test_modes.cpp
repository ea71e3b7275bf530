// Mode rules: tip touched refuses jogs, loops open after 7 s idle, Free, faults and Reset.
#include <catch2/catch.hpp>

#include "core_rig.hpp"

using namespace imess::test;
using imess::core::Refusal;

TEST_CASE("a deflected tip refuses moves toward or along the surface, allows moves away from the approach") {
  CoreRig rig;
  REQUIRE(rig.mode() == Mode::Free);
  rig.hand({0, 0, -18.5}, 20);  // push the probe 0.5 mm into the top face by hand: a hand hit along -Z
  rig.run(2.0);
  REQUIRE(rig.mechanics().tip_contact());
  REQUIRE(rig.take(EventKind::MeasPt).size() == 1);
  CHECK(rig.start_mv({0, 0, -20}) == Refusal::TipTouched);  // further in
  CHECK(rig.start_mv({20, 0, 0}) == Refusal::TipTouched);   // dragged along the face
  CHECK(rig.start_mv({20, 0, 5}) == Refusal::TipTouched);   // mostly along: more than 60 degrees off
  CHECK(rig.go_to({500, 330, 81}) == Refusal::TipTouched);
  CHECK(rig.mode() == Mode::Free);
  CHECK(rig.start_mv({5, 0, 20}) == Refusal::None);  // back out, within 60 degrees of straight up
  REQUIRE(rig.run_until([&] { return !rig.mechanics().tip_contact(); }, 1.0));
  rig.stop();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 1.0));
  rig.clear_events();
  CHECK(rig.go_to({430, 330, 150}) == Refusal::None);
}

TEST_CASE("the position loops open 7 s after the last stop") {
  CoreRig rig;
  rig.start_mv({20, 0, 0});
  rig.run(0.5);
  rig.stop();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 0.5));
  rig.run(6.9);
  CHECK(rig.mode() == Mode::Idle);
  CHECK(rig.core().machine().loops_closed());
  rig.run(0.2);
  CHECK(rig.mode() == Mode::Free);
  CHECK_FALSE(rig.core().machine().loops_closed());
}

TEST_CASE("the idle time is a parameter") {
  CoreRig rig;
  rig.set(imess::core::ParamId::IdleOpenTime, 1.0);
  rig.start_mv({20, 0, 0});
  rig.run(0.2);
  rig.stop();
  rig.run(1.1);
  CHECK(rig.mode() == Mode::Free);
}

TEST_CASE("Free opens the loops at once, but not while moving") {
  CoreRig rig;
  rig.start_mv({20, 0, 0});
  CHECK(rig.simple(CommandKind::Free) == Refusal::Busy);
  rig.stop();
  CHECK(rig.simple(CommandKind::Free) == Refusal::Busy);  // still braking
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 0.5));
  CHECK(rig.simple(CommandKind::Free) == Refusal::None);
  CHECK(rig.mode() == Mode::Free);
}

TEST_CASE("HandMv is refused while the loops hold the machine") {
  CoreRig rig;
  rig.start_mv({20, 0, 0});
  CHECK(rig.hand({1, 0, 0}) == Refusal::LoopsClosed);
}

TEST_CASE("probe overtravel is an emergency: loops open, commands refused until Reset") {
  CoreRig rig;
  rig.hand({0, 0, -28}, 50);  // 10 mm into the part: beyond the stylus' 8 mm
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Fault; }, 2.0));
  auto f = rig.take(EventKind::Fault);
  REQUIRE(f.size() == 1);
  CHECK(f[0].fault == imess::core::FaultKind::Emergency);
  CHECK(rig.start_mv({0, 0, 20}) == Refusal::Faulted);
  rig.hand({0, 0, 15}, 50);  // free it by hand
  rig.run(1.0);
  REQUIRE(rig.simple(CommandKind::Reset) == Refusal::None);
  rig.run(0.1);
  CHECK(rig.mode() == Mode::Free);
  CHECK(rig.start_mv({0, 0, 20}) == Refusal::None);
}

TEST_CASE("a state event announces every mode change") {
  CoreRig rig;
  rig.clear_events();
  rig.start_mv({0, 0, 20});
  rig.stop();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 0.5));
  auto states = rig.take(EventKind::State);
  REQUIRE(states.size() == 3);
  CHECK(states[0].mode == Mode::Jog);
  CHECK(states[1].mode == Mode::Stopping);
  CHECK(states[2].mode == Mode::Idle);
}
