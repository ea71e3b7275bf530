// RestWatch and the snapshot's rest_departures: the motion loop wakes the io side once when the
// position leaves a rest, never while it stands or keeps moving, so the io thread need not poll
// every millisecond for the first change after rest.
#include <catch2/catch.hpp>

#include <random>

#include "core_rig.hpp"
#include "imess/core/rest_watch.hpp"

using namespace imess::test;
using imess::core::AxisVec;
using imess::core::RestWatch;

TEST_CASE("RestWatch: one departure per rest of at least kStillCycles, none while standing or moving", "[rest]") {
  for (unsigned seed = 1; seed <= 50; ++seed) {
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> len(1, 12), axis(0, 5);
    std::uniform_real_distribution<double> jitter(-0.4 * RestWatch::kEpsilon, 0.4 * RestWatch::kEpsilon);
    RestWatch w;
    AxisVec p = AxisVec::Zero();
    int expected = 0, got = 0, still = 0;
    for (int phase = 0; phase < 40; ++phase) {
      const bool moving = phase % 2 == 1;
      const int cycles = len(rng);
      const AxisVec rest = p;
      for (int c = 0; c < cycles; ++c) {
        if (moving) {
          if (c == 0 && still >= RestWatch::kStillCycles) ++expected;
          p[axis(rng)] += 3 * RestWatch::kEpsilon;  // every cycle beyond epsilon from the last
          still = 0;
        } else {
          p = rest;
          p[axis(rng)] += jitter(rng);  // noise under epsilon: still standing
          ++still;
        }
        got += w.left_rest(p, 6);
      }
    }
    INFO("seed " << seed);
    CHECK(got == expected);
  }
}

namespace {
struct CountingSignal : imess::core::EventSignal {
  int count = 0;
  void notify() noexcept override { ++count; }
};
}  // namespace

TEST_CASE("the snapshot counts one rest departure when a jog or a hand push starts, none at rest", "[rest]") {
  CoreRig rig;
  CountingSignal signal;
  rig.core().set_event_signal(&signal);
  rig.run(0.5);
  rig.clear_events();
  signal.count = 0;
  rig.run(1.0);
  CHECK(signal.count == 0);  // standing: the io side is never woken
  rig.hand({5, 0, 0}, 10);
  rig.run(0.2);
  CHECK(signal.count >= RestWatch::kDepartureWakes);  // the departure and the cycles after it
  rig.core().set_event_signal(nullptr);
  rig.run(2.0);  // the push ends
  const auto at_rest = rig.core().snapshot().rest_departures;
  rig.run(1.0);
  CHECK(rig.core().snapshot().rest_departures == at_rest);
  REQUIRE(rig.hand({5, 0, 0}, 10) == imess::core::Refusal::None);
  rig.run(0.2);
  CHECK(rig.core().snapshot().rest_departures == at_rest + 1);
  rig.run(2.0);
  CHECK(rig.core().snapshot().rest_departures == at_rest + 1);  // one push, one departure
}
