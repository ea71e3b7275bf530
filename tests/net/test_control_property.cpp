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

// Property with the handover (control.handover_s): the same sessions plus the I++ DME session,
// a modelled machine (a jog, queued moves that finish as time passes, stops) and a clock. Control
// passes without force only when the owner was idle — the machine at rest, nothing queued, the
// owner silent for handover_s — and never from the I++ DME session; anyone's StopMv changes
// nothing about control; only the owner's commands move the machine.
TEST_CASE("Control property: a handover only from an idle owner, never while the machine moves or has a queue") {
  constexpr double kHandover = 2.0;
  std::size_t handovers = 0, refused_busy = 0;
  for (std::uint32_t seed = 1; seed <= 50; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    Control c(kHandover);
    // Sessions 1-2 may force, 3-4 may control, 5-6 may only observe, 7 is the I++ DME session.
    const std::vector<std::uint32_t> sessions{1, 2, 3, 4, 5, 6, kIppSession};
    auto may_control = [](std::uint32_t s) { return s <= 4 || s == kIppSession; };
    auto may_force = [](std::uint32_t s) { return s <= 2 || s == kIppSession; };
    std::optional<std::uint32_t> model;
    bool moving = false;  // a jog or GoTo runs
    int queued = 0;       // queued moves not yet done
    double now = 0, heard = 0;  // seconds; the owner's last command
    for (int step = 0; step < 3000; ++step) {
      now += std::uniform_real_distribution<double>(0, 1.2)(rng);
      if (queued > 0 && rng() % 3 == 0) --queued;      // a queued move is done
      if (moving && rng() % 4 == 0) moving = false;    // the jog ran into the part, the GoTo arrived
      const std::uint32_t s = sessions[rng() % sessions.size()];
      const Controller me{s, "client" + std::to_string(s), "127.0.0.1"};
      const Activity act{moving, queued > 0, now - heard};
      const bool idle_owner = model && *model != kIppSession && !moving && queued == 0 && now - heard >= kHandover;
      const auto before = model;
      bool forced = false;
      INFO("step " << step << " session " << s << " moving " << moving << " queued " << queued << " silent " << now - heard);
      switch (rng() % 8) {
        case 0:
        case 1:
        case 2: {  // a command that moves the machine (StartMv, GoTo) or queues (MoveTo)
          const auto r = c.claim(me, may_control(s), act);
          const bool accepted = r == ControlOutcome::Kept || r == ControlOutcome::Taken || r == ControlOutcome::HandedOver;
          REQUIRE(accepted == (may_control(s) && (!model || *model == s || idle_owner)));
          if (r == ControlOutcome::HandedOver) {
            REQUIRE(idle_owner);
            REQUIRE(c.previous()->session == *model);
            ++handovers;
          }
          if (!accepted && may_control(s) && model && *model != s && (moving || queued > 0)) ++refused_busy;
          if (accepted) {
            model = s;
            heard = now;
            if (rng() % 2) moving = true; else ++queued;
          }
          break;
        }
        case 3: {  // Take, sometimes forced
          const bool force = rng() % 2;
          const auto r = c.take(me, may_control(s), force, may_force(s), act);
          const bool got = r == ControlOutcome::Kept || r == ControlOutcome::Taken || r == ControlOutcome::TakenOver ||
                           r == ControlOutcome::HandedOver;
          REQUIRE(got == (may_control(s) && (!model || *model == s || idle_owner || (force && may_force(s)))));
          if (r == ControlOutcome::HandedOver) REQUIRE(idle_owner);
          if (r == ControlOutcome::TakenOver) {  // the operator's force stops the machine first
            REQUIRE(c.previous()->session == *model);
            forced = true;
            moving = false;
            queued = 0;
          }
          if (got && model != s) heard = now;
          if (got) model = s;
          break;
        }
        case 4:  // StopMv, from anyone: the machine stops, control stays where it is
          moving = false;
          queued = 0;
          break;
        case 5:  // Release (stops the machine when it was the owner's)
          REQUIRE(c.release(s) == (model && *model == s));
          if (model && *model == s) {
            model.reset();
            moving = false;
            queued = 0;
          }
          break;
        case 6:  // disconnect: the same
          c.release(s);
          if (model && *model == s) {
            model.reset();
            moving = false;
            queued = 0;
          }
          break;
        default:  // an open command (Status, Get): the owner is not silent
          if (model && *model == s) heard = now;
          break;
      }
      REQUIRE(c.owner().has_value() == model.has_value());
      if (model) {
        REQUIRE(c.owner()->session == *model);
        REQUIRE(may_control(*model));
        for (auto other : sessions) REQUIRE(c.owns(other) == (other == *model));
      }
      // Control never went from one session to another while the machine moved or had a queue,
      // or from an owner that spoke lately, or from the I++ DME session — except by the
      // operator's force (which stopped the machine).
      if (before && model && *before != *model) {
        const bool idle = !act.machine_moves && !act.queue && act.owner_silent_s >= kHandover && *before != kIppSession;
        REQUIRE((forced || idle));
      }
    }
  }
  CHECK(handovers > 100);    // the rule was exercised both ways
  CHECK(refused_busy > 100);
}
