// The servo card follows a planned path (Op::Follow): the real driver over the link to the
// emulated card, fed once per motion period with the Sampler's setpoints, in virtual time.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>

#include "card_follow_rig.hpp"
#include "imess/core/path_machine.hpp"

using namespace imess;
using namespace imess::test;
namespace st = hal::status;
using Fault = FaultyLink::Fault;

namespace {
constexpr double kCount = 0.0001;  // mm, one encoder count of the emulated card

hal::MachineState state(CardFollowRig& rig) {
  hal::MachineState ms;
  REQUIRE(rig.driver().read_state(ms));
  return ms;
}

// Runs the read-only cycles until the machine rests, up to max_s; returns the last state.
hal::MachineState settle(CardFollowRig& rig, double max_s = 1.0) {
  hal::MachineState ms = state(rig);
  for (int i = 0; i < max_s / CardFollowRig::kT && !ms.motion_done(); ++i) {
    rig.tick();
    ms = state(rig);
  }
  for (int i = 0; i < 300; ++i) rig.tick();  // the position loop settles
  return state(rig);
}
}  // namespace

TEST_CASE("card follow: the encoders follow a planned path with a corner and an arc, and end on the target") {
  CardFollowRig rig;
  const auto path = rig.sampled_path(corner_and_arc_path());
  REQUIRE(path.size() > 1000);
  auto& link = rig.link();

  // Link traffic of one cycle before following: the per-cycle ReadState alone.
  const long out0 = link.bytes_out, in0 = link.bytes_in, n0 = link.transactions;
  state(rig);
  const long before = link.bytes_out - out0 + link.bytes_in - in0;
  CHECK(link.transactions - n0 == 1);
  CHECK(before == 45);  // 5 out (op, table), 40 back (status, 3 × position, status word, inputs)

  double max_error = 0, max_speed = 0;
  Vec3 previous = rig.start();  // the path where it is now: the setpoint of the period ending now
  const long out1 = link.bytes_out, in1 = link.bytes_in, n1 = link.transactions;
  for (const auto& sp : path) {
    REQUIRE(rig.driver().follow(sp));
    const hal::MachineState ms = state(rig);  // the Follow reply: no second frame
    REQUIRE(!ms.faulted());
    max_error = std::max(max_error, (xyz(ms.position) - previous).norm());
    max_speed = std::max(max_speed, sp.velocity.norm());
    for (int a = 0; a < 3; ++a)
      if (sp.position[a] != previous[a]) {  // this axis' setpoint moves: the card must not claim done
        INFO("axis " << a << ", cycle " << (&sp - path.data()));
        CHECK((ms.status[a] & (st::kProfileEnd | st::kInPosition)) == 0);
      }
    previous = xyz(sp.position);
    rig.tick();
  }
  const long cycles = static_cast<long>(path.size());
  const long transactions = link.transactions - n1;
  const double per_cycle = static_cast<double>(link.bytes_out - out1 + link.bytes_in - in1) / cycles;
  CHECK(transactions == cycles);  // one round trip per cycle
  CHECK(per_cycle == 93);         // 53 out (op, table, 3 × position + velocity), 40 back
  std::printf("card follow: %ld cycles, peak path speed %.1f mm/s, max tracking error %.4f mm, link %.0f B/cycle "
              "(ReadState alone %ld B)\n",
              cycles, max_speed, max_error, per_cycle, before);
  CHECK(max_speed > 95);
  // Bound: the lag of the card's loop, (1 − 90 % feed-forward)·v / 60 /s (0.2 mm at the
  // path's 120 mm/s), plus 0.05 mm for the motor's 4 ms time constant and the corners.
  const sim::CardConfig card;
  CHECK(max_error < (1 - card.velocity_feedforward) * max_speed / card.position_gain + 0.05);

  // The path ends at rest: the card stops following by itself, no frames needed, no timeout.
  const hal::MachineState end = settle(rig);
  const Vec3 target = xyz(path.back().position);
  const double end_error = (xyz(end.position) - target).cwiseAbs().maxCoeff();
  std::printf("card follow: end error %.5f mm\n", end_error);
  CHECK(end_error <= kCount + 1e-9);
  CHECK(end.motion_done());
  CHECK(end.all(st::kInPosition));
  CHECK(!end.faulted());
  CHECK(!end.any(st::kFollowingError));
}

TEST_CASE("card follow: stop() mid-path brakes to rest within v²/2a, and move() works afterwards") {
  CardFollowRig rig;
  const auto path = rig.sampled_path(corner_and_arc_path());
  // Cruising along the first line at 100 mm/s after 0.3 s.
  const std::size_t at = 300;
  hal::MachineState ms;
  for (std::size_t i = 0; i < at; ++i) {
    REQUIRE(rig.driver().follow(path[i]));
    ms = state(rig);
    rig.tick();
  }
  const Vec3 v = xyz(path[at - 1].velocity);
  REQUIRE(v.norm() > 99);
  const double decel = 1000;
  const Vec3 stopped_at = xyz(state(rig).position);
  REQUIRE(rig.driver().stop(hal::AxisVec::Constant(decel)));
  const hal::MachineState rest = settle(rig);
  const double travel = (xyz(rest.position) - stopped_at).norm(), braking = v.squaredNorm() / (2 * decel);
  std::printf("card follow: stop at %.1f mm/s: %.4f mm to rest, v²/2a = %.4f mm\n", v.norm(), travel, braking);
  CHECK(travel <= braking + 0.25);  // + the tracking lag at the stop
  CHECK(travel >= braking - 0.25);  // it braked at decel, not at once
  CHECK(rest.motion_done());
  CHECK(!rest.faulted());

  // A trapezoid move after following works as before.
  hal::AxisArray<hal::AxisMove> moves{};
  moves[0] = {450, 50, 500};
  REQUIRE(rig.driver().move(moves, 1u));
  rig.tick();
  CHECK(!state(rig).all(st::kProfileEnd));
  const hal::MachineState moved = settle(rig, 2);
  CHECK(std::abs(moved.position[0] - 450) <= kCount + 1e-9);
  CHECK(moved.motion_done());
  CHECK(!moved.faulted());
}

TEST_CASE("card follow: a lost or corrupted frame becomes a communication timeout (CommLost), never a hang") {
  for (Fault f : {Fault::LoseRequest, Fault::LoseReply, Fault::Truncate, Fault::Corrupt}) {
    INFO("fault " << static_cast<int>(f));
    CardFollowRig rig;
    const auto path = rig.sampled_path(corner_and_arc_path());
    const std::size_t at = 250;  // cruising on the first line
    for (std::size_t i = 0; i < at; ++i) {
      REQUIRE(rig.driver().follow(path[i]));
      state(rig);
      rig.tick();
    }
    rig.link().inject(f);
    CHECK_FALSE(rig.driver().follow(path[at]));
    // The driver reports the gap as a communication timeout on every axis: the motion core's
    // CommLost (it stops and opens the loops) ...
    hal::MachineState ms = state(rig);
    CHECK(ms.all(st::kCommTimeout));
    CHECK(ms.faulted());
    // ... and the card, whose setpoints stopped coming, brakes on its own and says so too.
    const Vec3 from = xyz(ms.position);
    for (int i = 0; i < 300; ++i) {
      rig.tick();
      ms = state(rig);
    }
    CHECK((rig.card_status()[0] & st::kCommTimeout) != 0);
    CHECK(ms.motion_done());
    // Braked at amax from ≤ 100 mm/s, after going on at that speed for the watchdog's 5 ms.
    CHECK((xyz(ms.position) - from).norm() < 100.0 * 100 / (2 * 1000) + 100.0 * 0.005 + 0.5);
    // Reset clears it; the loops close again and a new path can start from rest.
    REQUIRE(rig.driver().reset_faults());
    REQUIRE(rig.driver().set_loops(true));
    ms = state(rig);
    CHECK(!ms.faulted());
    CHECK(ms.loops_closed());
    hal::Setpoint hold;
    hold.position = ms.position;
    CHECK(rig.driver().follow(hold));
    CHECK(!state(rig).faulted());
  }
}

TEST_CASE("card follow: a host that stops sending setpoints mid-path gets a braked card and a timeout") {
  CardFollowRig rig;
  const auto path = rig.sampled_path(corner_and_arc_path());
  for (std::size_t i = 0; i < 250; ++i) {
    REQUIRE(rig.driver().follow(path[i]));
    state(rig);
    rig.tick();
  }
  hal::MachineState ms = state(rig);  // a plain ReadState now: no Follow frame this period
  CHECK(!ms.faulted());
  for (int late = 0; late < 3; ++late) {  // a host up to 4 ms late is bridged, not faulted
    rig.tick();
    ms = state(rig);
    CHECK(!ms.faulted());
  }
  rig.tick();
  rig.tick();
  ms = state(rig);  // six periods without a setpoint (over 5 ms): the card's watchdog has fired
  CHECK(ms.all(st::kCommTimeout));
  const hal::MachineState rest = settle(rig);
  CHECK(rest.motion_done());
  CHECK(rest.all(st::kCommTimeout));
}

TEST_CASE("card follow: the motion core reading the Follow replies faults CommLost on a lost frame") {
  CardFollowRig rig;
  core::CoreConfig config = default_options().core;
  config.params.idle_open_time = 60;  // the loops stay closed while the test feeds the card
  core::MotionCore core(rig.driver(), config, &rig.mechanics());
  core.start(rig.clock().now());
  REQUIRE(core.mode() == Mode::Idle);
  std::vector<Event> events;
  auto cycle = [&] {
    core.cycle(rig.clock().now());  // its read_state() takes the Follow reply: no frame of its own
    Event e;
    while (core.events().pop(e)) events.push_back(e);
  };
  const auto path = rig.sampled_path(corner_and_arc_path());
  const long frames = rig.link().transactions;
  for (std::size_t i = 0; i < 250; ++i) {
    REQUIRE(rig.driver().follow(path[i]));
    cycle();
    REQUIRE(core.mode() == Mode::Idle);
    rig.tick();
  }
  CHECK(rig.link().transactions - frames == 250);
  rig.link().inject(Fault::LoseRequest);
  CHECK_FALSE(rig.driver().follow(path[250]));
  cycle();
  CHECK(core.mode() == Mode::Fault);
  bool comm_lost = false;
  for (const auto& e : events) comm_lost = comm_lost || (e.kind == EventKind::Fault && e.fault == core::FaultKind::CommLost);
  CHECK(comm_lost);
  const auto card = rig.card_status();
  for (int a = 0; a < 3; ++a) CHECK((card[a] & st::kClosedLoop) == 0);  // the core opened the loops
}

TEST_CASE("card follow: the motion core rides over a stalled host, the path going on with the clock") {
  // Every 40 cycles the host wakes 3 ms late (4 ms since the last Follow): the card went on
  // at the last setpoint's velocity meanwhile, so the core advances the path by the time
  // that passed; a path advanced one period per cycle would send a setpoint behind the card,
  // which it refuses as implausible (CommLost).
  CardFollowRig rig;
  core::CoreConfig config = default_options().core;
  config.params.idle_open_time = 60;
  core::MotionCore core(rig.driver(), config, &rig.mechanics());
  core.start(rig.clock().now());
  REQUIRE(core.mode() == Mode::Idle);
  planner::Planner planner(core::path_machine(core.config()), core::path_options(core.config()));
  planner.set_position(pose3(rig.start()));
  for (const auto& r : corner_and_arc_path()) REQUIRE(planner.append(r).ok());
  planner.flush();
  std::vector<planner::PlannedSegment> segments;
  double planned_s = 0;
  for (planner::PlannedSegment s; planner.take(s);) {
    segments.push_back(s);
    planned_s += s.duration();
  }

  std::vector<Event> events;
  int cycles = 0, stalls = 0;
  bool idle = false;
  std::size_t next = 0;
  for (; cycles < 20000 && !idle; ++cycles) {
    while (next < segments.size() && core.segment_room() > 0 && core.submit_segment({segments[next], core.stop_ticket(), 0}))
      ++next;
    rig.tick();
    if (cycles % 40 == 39) {
      for (int late = 0; late < 3; ++late) rig.tick();
      ++stalls;
    }
    core.cycle(rig.clock().now());
    Event e;
    while (core.events().pop(e)) {
      events.push_back(e);
      idle = idle || (e.kind == EventKind::State && e.mode == Mode::Idle);
    }
    REQUIRE(core.mode() != Mode::Fault);
  }
  CHECK(idle);
  std::vector<std::uint32_t> done;
  for (const auto& e : events)
    if (e.kind == EventKind::Done) done.push_back(e.id);
  CHECK(done == std::vector<std::uint32_t>{1, 2, 3, 4});
  const hal::MachineState ms = state(rig);
  CHECK((xyz(ms.position) - Vec3(430, 330, 100)).cwiseAbs().maxCoeff() <= 0.005);  // the in-position window
  // The path took its planned time in the clock, not in cycles: about 3 cycles fewer per stall.
  INFO("cycles " << cycles << ", planned " << planned_s << " s, stalls " << stalls);
  CHECK(stalls > 20);
  CHECK((cycles + 3 * stalls) * CardFollowRig::kT == Approx(planned_s).margin(0.05));  // + arrival
}
