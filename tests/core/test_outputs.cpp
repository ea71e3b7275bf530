// Outputs in the motion core: a SetOutput segment switches when the path before it is at
// rest and holds the output's settle time; a backend that refuses the switch fails the queue;
// the probe's power output: edges within its arming time and while it is off are not hits
// (Warn HitIgnored), a Probe cycle that begins with the probe off fails ProbeOff. A seeded
// property: whatever the sequence, no point is ever taken from an unarmed probe and every
// queued id ends exactly once.
#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <random>
#include <string>

#include "ideal_follower.hpp"
#include "imess/planner/probe.hpp"

using namespace imess::test;
using imess::core::FailReason;
using imess::core::Warning;
namespace core = imess::core;
namespace planner = imess::planner;

namespace {
constexpr int kProbeOut = 1, kGripperOut = 2;
constexpr double kArming = 0.1, kGripperSettle = 0.3;

core::OutputSettings output(const std::string& name, int number, double settle, bool probe, bool at_start) {
  core::OutputSettings o;
  std::copy(name.begin(), name.end(), o.name.begin());
  o.number = number;
  o.settle_s = settle;
  o.probe_power = probe;
  o.at_start = at_start;
  return o;
}

core::CoreConfig with_outputs(double arming = kArming) {
  auto c = FollowerRig::default_config();
  c.outputs[0] = output("probe", kProbeOut, arming, true, true);
  c.outputs[1] = output("gripper", kGripperOut, kGripperSettle, false, false);
  c.output_count = 2;
  return c;
}

double seconds(const Event& e) { return std::chrono::duration<double>(e.time).count(); }
double seconds(imess::hal::Nanos t) { return std::chrono::duration<double>(t).count(); }

planner::SetOutput set_out(std::uint32_t id, int number, bool on, double hold) {
  return planner::SetOutput{id, static_cast<std::uint16_t>(number), on ? 1.0 : 0.0, hold};
}

// After the loop dropped its queue, as the io side does: later segments carry the loop's new
// drop count, and the plan starts where the machine stands.
void replan(FollowerRig& rig) {
  for (const auto& e : rig.events())
    if (e.kind == EventKind::QueueDropped) rig.drops = e.id;
  planner::Pose here{};
  for (int a = 0; a < 3; ++a) here[a] = rig.core().machine().position[a];
  rig.planner().set_position(here);
}

}  // namespace

TEST_CASE("outputs: every configured output is set to its start state when the core starts") {
  FollowerRig rig(with_outputs());
  REQUIRE(rig.hw.switches.size() == 2);
  CHECK(rig.hw.outputs[kProbeOut - 1]);
  CHECK_FALSE(rig.hw.outputs[kGripperOut - 1]);
  rig.step();
  CHECK(rig.core().snapshot().outputs == 0b01u);
}

TEST_CASE("outputs: a start state the backend lacks stops start-up naming the output") {
  auto c = with_outputs();
  c.outputs[1].number = 7;  // the follower has 4
  try {
    FollowerRig rig(c);
    FAIL("started");
  } catch (const std::runtime_error& e) {
    CHECK(std::string(e.what()) == "output 'gripper' is number 7; the backend has outputs 1 to 4");
  }
}

TEST_CASE("outputs: SetOutput switches when the path before it is at rest, holds the settle time, then goes on") {
  FollowerRig rig(with_outputs());
  rig.hw.switches.clear();
  rig.append(rig.line(1, 150, 100, 100, 50));
  rig.append(set_out(2, kGripperOut, true, kGripperSettle));
  rig.append(rig.line(3, 160, 100, 100, 50));
  rig.feed(true);
  REQUIRE(rig.run_until([&] { return rig.ids(EventKind::Done).size() == 3 && rig.mode() == Mode::Idle; }, 10));
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{1, 2, 3});
  REQUIRE(rig.hw.switches.size() == 1);
  const auto sw = rig.hw.switches[0];
  CHECK(sw.number == kGripperOut);
  CHECK(sw.on);
  CHECK(rig.hw.outputs[kGripperOut - 1]);
  // The setpoint of the switching cycle is the first move's end, at rest.
  REQUIRE(sw.setpoints_before < rig.hw.setpoints.size());
  const auto& at = rig.hw.setpoints[sw.setpoints_before];
  CHECK(at.position[0] == 150.0);
  CHECK(at.velocity.isZero());
  // The path holds there for the settle time (300 setpoints of 1 ms, within one), then moves.
  std::size_t k = sw.setpoints_before;
  while (k < rig.hw.setpoints.size() && rig.hw.setpoints[k].position[0] == 150.0) ++k;
  CHECK(static_cast<double>(k - sw.setpoints_before) * 1e-3 == Approx(kGripperSettle).margin(1.5e-3));
  CHECK(rig.core().snapshot().outputs == 0b11u);
  CHECK(rig.fail_reasons().empty());
}

TEST_CASE("outputs: a switch the backend refuses fails the queue from there (Faulted) and the machine stops") {
  FollowerRig rig(with_outputs());
  rig.hw.refuse_outputs = true;
  rig.append(rig.line(1, 150, 100, 100, 50));
  rig.append(set_out(2, kGripperOut, true, 0));
  rig.append(rig.line(3, 160, 100, 100, 50));
  rig.feed(true);
  const bool ended = rig.run_until([&] { return rig.ids(EventKind::Failed).size() == 2 && rig.mode() == Mode::Idle; }, 10);
  REQUIRE(ended);
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{1});
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{2, 3});
  CHECK(rig.fail_reasons() == std::vector<FailReason>{FailReason::Faulted, FailReason::Faulted});
  CHECK(rig.position().x() == Approx(150).margin(1e-9));
}

TEST_CASE("probe power: the power-on edge at start and edges within the arming time are not hits") {
  FollowerRig rig(with_outputs());
  rig.hw.probe_power_output = kProbeOut;
  // An edge 50 ms after start: within the start-up arming, dropped without a word.
  rig.run(0.05);
  CHECK_FALSE(rig.core().snapshot().probe_armed);
  rig.hw.touch();
  rig.hw.tip = false;
  rig.step();
  CHECK(rig.take(EventKind::Warn).empty());
  CHECK(rig.take(EventKind::MeasPt).empty());
  rig.run(0.1);
  CHECK(rig.core().snapshot().probe_armed);
  // Switched on by a client (off, then on): the edges within the arming time are warned.
  rig.append(set_out(1, kProbeOut, false, 0));
  rig.append(set_out(2, kProbeOut, true, 0));  // no hold: the queue does not wait for the arming
  rig.feed(true);
  REQUIRE(rig.run_until([&] { return rig.ids(EventKind::Done).size() == 2; }, 2));
  rig.run(0.02);
  rig.hw.touch();
  rig.hw.tip = false;
  rig.step();
  auto warns = rig.take(EventKind::Warn);
  REQUIRE(warns.size() >= 1);
  for (const auto& w : warns) CHECK(w.warning == Warning::HitIgnored);
  CHECK(std::string(warns.back().reason) == "edge within the probe's arming time; no point taken");
  CHECK(rig.take(EventKind::MeasPt).empty());
  CHECK_FALSE(rig.core().snapshot().probe_armed);
  rig.run(0.1);
  CHECK(rig.core().snapshot().probe_armed);
}

TEST_CASE("probe power: switched off, its edge is ignored and a Probe fails ProbeOff before it moves on — on again, it hits") {
  FollowerRig rig(with_outputs());
  rig.hw.probe_power_output = kProbeOut;
  rig.run(0.2);
  rig.clear_events();
  rig.append(set_out(1, kProbeOut, false, kArming));
  queue_probe(rig, 2, {150, 100, 100});
  rig.append(rig.line(3, 100, 120, 100, 50));
  rig.feed(true);
  REQUIRE(rig.run_until([&] { return rig.ids(EventKind::Failed).size() == 2 && rig.mode() == Mode::Idle; }, 10));
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{1});
  CHECK(rig.ids(EventKind::Failed) == std::vector<std::uint32_t>{2, 3});
  CHECK(rig.fail_reasons().front() == FailReason::ProbeOff);
  CHECK(rig.position().x() < 100.01);  // it did not travel toward the part
  auto warns = rig.take(EventKind::Warn);
  REQUIRE(warns.size() == 1);  // the power-off edge
  CHECK(warns[0].warning == Warning::HitIgnored);
  CHECK(rig.take(EventKind::MeasPt).empty());
  CHECK_FALSE(rig.hw.outputs[kProbeOut - 1]);
  // An edge while off (a hand touch): ignored, with the other text.
  rig.hw.touch();
  rig.hw.tip = false;
  rig.step();
  warns = rig.take(EventKind::Warn);
  REQUIRE(warns.size() == 1);
  CHECK(std::string(warns[0].reason) == "probe edge while the probe is switched off; no point taken");
  // On again: the queue holds the arming time, then the Probe's edge is a hit.
  replan(rig);
  rig.clear_events();
  rig.append(set_out(4, kProbeOut, true, kArming));
  queue_probe(rig, 5, {150, 100, 100});
  rig.feed(true);
  bool touched = false;
  REQUIRE(rig.run_until([&] {
    if (!touched && rig.position().x() >= 151) {
      rig.hw.touch();
      touched = true;
    }
    if (touched && rig.hw.tip && rig.position().x() < 151) rig.hw.tip = false;
    return rig.ids(EventKind::Done).size() == 2 && rig.mode() == Mode::Idle;
  }, 20));
  CHECK(rig.ids(EventKind::Done) == std::vector<std::uint32_t>{4, 5});
  auto hits = rig.take(EventKind::MeasPt);
  REQUIRE(hits.size() == 1);
  CHECK(hits[0].id == 5);
  REQUIRE(rig.take(EventKind::Warn).size() == 1);  // the power-on edge only
}

TEST_CASE("probe power, property: over seeded random sequences no point is taken from an unarmed probe and every id ends once") {
  int points = 0, ignored = 0;
  for (unsigned seed = 1; seed <= 12; ++seed) {
    INFO("seed " << seed);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> uni(0, 1);
    const double arming = 0.5;  // long: Probe searches and edges fall within it
    FollowerRig rig(with_outputs(arming));
    rig.hw.probe_power_output = kProbeOut;
    rig.hw.record = false;
    // The probe as the backend saw it switched: powered, and armed from this time on.
    bool powered = true;
    double armed_at = seconds(rig.clock().now()) + arming;
    std::uint32_t id = 0;
    std::vector<std::uint32_t> queued;
    for (int round = 0; round < 8; ++round) {
      const int n = 1 + static_cast<int>(uni(rng) * 4);
      for (int i = 0; i < n; ++i) {
        const double r = uni(rng);
        const auto at = rig.planner().position();
        if (r < 0.3) {
          // A hold shorter than the arming time (the io side holds it all): the core must
          // still ignore the edges within it.
          rig.append(set_out(++id, kProbeOut, uni(rng) < 0.6, arming * uni(rng)));
        } else if (r < 0.4) {
          rig.append(set_out(++id, kGripperOut, uni(rng) < 0.5, 0.05));
        } else if (r < 0.7) {  // a Probe 5 to 15 mm away in X Y
          const double a = 2 * 3.141592653589793 * uni(rng), d = 5 + 10 * uni(rng);
          queue_probe(rig, ++id, {at[0] + d * std::cos(a), at[1] + d * std::sin(a), at[2]});
        } else {
          rig.append(rig.line(++id, 100 + 40 * uni(rng), 100 + 40 * uni(rng), 100, 20 + 60 * uni(rng)));
        }
        queued.push_back(id);
        if (r >= 0.4 && r < 0.7) break;  // what follows a Probe waits on the io side: the round ends with it
      }
      rig.feed(true);  // a round's few segments fit the ring at once
      for (int t = 0; t < 6000; ++t) {
        if (uni(rng) < 0.01) {  // an edge now and then; the tip re-seats at once
          rig.hw.touch();
          rig.hw.tip = false;
        }
        const bool was_powered = powered;
        const double was_armed_at = armed_at;
        rig.step();
        const double now = seconds(rig.clock().now());
        // The cycle reads the latch before it switches outputs: a point in it is judged by
        // the state before the switch.
        for (const auto& e : rig.take(EventKind::MeasPt)) {
          CHECK(was_powered);
          CHECK(seconds(e) >= was_armed_at - 1e-9);
          ++points;
        }
        if (rig.hw.outputs[kProbeOut - 1] != powered) {
          powered = rig.hw.outputs[kProbeOut - 1];
          armed_at = now + arming;
        }
        if (rig.mode() == Mode::Idle &&
            rig.ids(EventKind::Done).size() + rig.ids(EventKind::Failed).size() >= queued.size())
          break;
      }
      REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5));
      for (const auto& w : rig.take(EventKind::Warn)) ignored += w.warning == Warning::HitIgnored;
      replan(rig);
    }
    std::map<std::uint32_t, int> ends;
    for (auto& e : rig.events())
      if (e.kind == EventKind::Done || e.kind == EventKind::Failed) ++ends[e.id];
    for (auto q : queued) {
      INFO("id " << q);
      CHECK(ends[q] == 1);
    }
  }
  CHECK(points > 0);   // the property was put to the test: points were taken ...
  CHECK(ignored > 0);  // ... and edges ignored
}

TEST_CASE("outputs: a backend that switched its outputs off (a safety trip) is what Outputs and the probe follow") {
  FollowerRig rig(with_outputs());
  rig.hw.probe_power_output = kProbeOut;
  rig.append(set_out(1, kGripperOut, true, 0));
  rig.feed(true);
  REQUIRE(rig.run_until([&] { return rig.ids(EventKind::Done).size() == 1 && rig.mode() == Mode::Idle; }, 5));
  rig.run(0.2);
  CHECK(rig.core().snapshot().outputs == 0b11u);
  CHECK(rig.core().snapshot().probe_armed);
  rig.hw.outputs = {};  // the trip: every output off
  rig.step();
  CHECK(rig.core().snapshot().outputs == 0u);
  CHECK_FALSE(rig.core().snapshot().probe_armed);
  rig.hw.touch();  // an edge now is no hit
  rig.hw.tip = false;
  rig.step();
  CHECK(rig.take(EventKind::MeasPt).empty());
  REQUIRE(rig.take(EventKind::Warn).size() == 1);
}
