// Property: seeded random sequences of commands from several sessions — only the owner's
// controlling commands are ever accepted; there is never more than one owner; observer
// hosts never own; every loss of control is a release, a disconnect or a forced take-over.
#include <catch2/catch.hpp>

#include <random>
#include <set>

#include "imess/net/control.hpp"

using namespace imess::net;

TEST_CASE("Control property: random sessions, commands, takes, releases and disconnects") {
  for (std::uint32_t seed = 1; seed <= 50; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    Control c;
    constexpr std::uint32_t kSessions = 6;
    // Sessions 1-2 may force, 3-4 may control, 5-6 may only observe.
    auto may_control = [](std::uint32_t s) { return s <= 4; };
    auto may_force = [](std::uint32_t s) { return s <= 2; };
    std::set<std::uint32_t> connected{1, 2, 3, 4, 5, 6};
    std::optional<std::uint32_t> model;  // who should own
    for (int step = 0; step < 2000; ++step) {
      std::uint32_t s = 1 + rng() % kSessions;
      Controller me{s, "client" + std::to_string(s), "127.0.0." + std::to_string(s)};
      switch (rng() % 6) {
        case 0:
        case 1: {  // a controlling command
          auto r = c.claim(me, may_control(s));
          const bool accepted = r == ControlOutcome::Kept || r == ControlOutcome::Taken;
          REQUIRE(accepted == (may_control(s) && (!model || *model == s)));
          if (accepted) model = s;
          break;
        }
        case 2: {  // Take, sometimes forced
          const bool force = rng() % 2;
          auto r = c.take(me, may_control(s), force, may_force(s));
          const bool got = r == ControlOutcome::Kept || r == ControlOutcome::Taken || r == ControlOutcome::TakenOver;
          REQUIRE(got == (may_control(s) && (!model || *model == s || (force && may_force(s)))));
          if (r == ControlOutcome::TakenOver) REQUIRE(c.previous()->session == *model);
          if (got) model = s;
          break;
        }
        case 3:  // Release
          REQUIRE(c.release(s) == (model && *model == s));
          if (model && *model == s) model.reset();
          break;
        case 4:  // disconnect and reconnect (a new connection starts without control)
          c.release(s);
          if (model && *model == s) model.reset();
          break;
        default:  // StopMv or an open command: control is unchanged
          break;
      }
      REQUIRE(c.owner().has_value() == model.has_value());
      if (model) {
        REQUIRE(c.owner()->session == *model);
        REQUIRE(may_control(*model));
        for (std::uint32_t other = 1; other <= kSessions; ++other) REQUIRE(c.owns(other) == (other == *model));
      }
    }
  }
}
