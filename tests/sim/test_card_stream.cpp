// The servo card streamed over a 115 200 baud serial line in virtual time: the motion core
// runs queued arcs of 1 mm chords at 100 mm/s with timed setpoints sent ahead and status
// frames coming back; the line carries it without overruns, the card never starves; a lost
// or damaged host frame is sent again, a line that keeps damaging them ends in Fault
// LinkErrors, status frames that stop coming in Fault CommLost; jog, GoTo, probing,
// homing, stop and reset work over the stream.
#include <catch2/catch.hpp>

#include <cstdio>
#include <random>

#include "card_stream_rig.hpp"

using namespace imess;
using namespace imess::test;
namespace st = hal::status;
using ChannelFault = sim::SerialChannel::Fault;

namespace {
constexpr double kBudget = 115200.0 / 10 / 1000;  // bytes per ms each way: 11.52

struct PathRun {
  long cycles = 0;
  double out_per_ms = 0, in_per_ms = 0, peak_speed = 0, max_radial = 0, end_error = 0;
  int min_margin = 1 << 30;
};

// Two turns of a 20 mm circle in 1 mm chords at 100 mm/s, from the machine's start; the
// radial error is the distance of the reported position from the circle.
PathRun run_circle(StreamRig& s, bool streamed) {
  const Vec3 start = s.rig.position(), centre = start + Vec3(20, 0, 0);
  s.queue(chord_circle(start, 20, 1.0, 2, 100));
  s.step();
  REQUIRE(s.rig.mode() == Mode::Path);
  PathRun run;
  const long out0 = s.line().to_card().stats().bytes, in0 = s.line().to_host().stats().bytes;
  const auto& m = s.rig.mechanics();
  while (s.rig.mode() == Mode::Path && run.cycles < 10000) {
    s.step();
    ++run.cycles;
    const Vec3 p = s.rig.position();
    run.peak_speed = std::max(run.peak_speed, Vec3(m.velocity(0), m.velocity(1), m.velocity(2)).norm());
    if (run.cycles > 300)  // once up to speed on the circle (the first chords accelerate)
      run.max_radial = std::max(run.max_radial, std::abs(Vec3(p - centre).head<2>().norm() - 20));
    if (streamed && s.session().newest().knots > 0) run.min_margin = std::min<int>(run.min_margin, s.session().newest().margin);
  }
  REQUIRE(s.rig.mode() == Mode::Idle);
  run.out_per_ms = static_cast<double>(s.line().to_card().stats().bytes - out0) / run.cycles;
  run.in_per_ms = static_cast<double>(s.line().to_host().stats().bytes - in0) / run.cycles;
  s.run_until([&] { return s.rig.core().machine().motion_done(); }, 1);
  s.rig.run(0.3);  // the position loop settles
  run.end_error = (s.rig.position() - start).cwiseAbs().maxCoeff();
  return run;
}
}  // namespace

TEST_CASE("card stream: arcs of 1 mm chords at 100 mm/s over 115 200 baud: no overrun, no starvation, on the path") {
  StreamRig s;
  const PathRun run = run_circle(s, true);
  const auto& out = s.line().to_card().stats();
  const auto& in = s.line().to_host().stats();
  std::printf("card stream: %ld cycles, peak %.1f mm/s; host->card %.2f B/ms, card->host %.2f B/ms (budget %.2f); "
              "longest wait for the line %.2f ms / %.2f ms; overruns %ld / %ld; starvations %lu; least lead %.1f ms; "
              "radial error %.4f mm; end error %.5f mm; frames out %lu, status frames %lu\n",
              run.cycles, run.peak_speed, run.out_per_ms, run.in_per_ms, kBudget, out.max_backlog * 1e3,
              in.max_backlog * 1e3, out.overruns, in.overruns, s.card().starvations(), run.min_margin * 0.1,
              run.max_radial, run.end_error, s.session().frames_sent(), s.session().status_frames());
  CHECK(run.peak_speed > 95);
  CHECK(run.peak_speed < 105);
  CHECK(run.out_per_ms < kBudget);
  CHECK(run.in_per_ms < kBudget);
  CHECK(out.overruns == 0);  // no frame waited a motion period for the line
  CHECK(in.overruns == 0);
  CHECK(out.refused == 0);
  CHECK(s.card().starvations() == 0);
  CHECK(run.min_margin > 20);  // the card always held setpoints ≥ 2 ms ahead
  CHECK(s.session().errors() == 0);
  CHECK(s.line().damaged_at_card() == 0);
  CHECK(s.line().damaged_at_host() == 0);
  CHECK(s.rig.events().end() == std::find_if(s.rig.events().begin(), s.rig.events().end(),
                                             [](const Event& e) { return e.kind == EventKind::Fault; }));
  CHECK(run.max_radial < 0.05);
  CHECK(run.end_error <= 0.0002);

  // The same path on the instant request/reply link (one Follow round trip per cycle).
  StreamRig sync(default_options());
  const PathRun ref = run_circle(sync, false);
  std::printf("card follow (request/reply): radial error %.4f mm, end error %.5f mm\n", ref.max_radial, ref.end_error);
}

TEST_CASE("card stream: a lost or damaged host frame is sent again and the path runs on to its end") {
  struct Case {
    const char* what;
    ChannelFault fault;
  };
  for (const Case c : {Case{"setpoint frame lost", ChannelFault::Lose}, Case{"setpoint frame damaged", ChannelFault::Corrupt}}) {
    INFO(c.what);
    StreamRig s;
    const Vec3 centre = s.rig.position() + Vec3(20, 0, 0);
    s.queue(chord_circle(s.rig.position(), 20, 1.0, 2, 100));
    for (int i = 0; i < 400; ++i) s.step();
    REQUIRE(s.rig.mode() == Mode::Path);
    REQUIRE(s.session().frames_resent() == 0);
    s.line().to_card().inject(c.fault);
    int cycles = 0, resent_after = -1;
    double radial = 0;
    while (s.rig.mode() == Mode::Path && cycles < 10000) {
      s.step();
      ++cycles;
      if (resent_after < 0 && s.session().frames_resent() > 0) resent_after = cycles;
      radial = std::max(radial, std::abs(Vec3(s.rig.position() - centre).head<2>().norm() - 20));
    }
    std::printf("card stream: %s -> sent again after %d ms (%lu frames); path ended, radial error %.4f mm\n", c.what,
                resent_after, s.session().frames_resent(), radial);
    CHECK(s.rig.mode() == Mode::Idle);
    CHECK(resent_after > 0);
    CHECK(resent_after <= 20);  // well inside the 60 ms lead
    CHECK(s.card().starvations() == 0);
    CHECK(s.session().errors() >= 1);  // counted (Stats: LinkErrors)
    CHECK(radial < 0.05);
    for (const Event& e : s.rig.events()) {
      CHECK(e.kind != EventKind::Fault);
      CHECK(e.kind != EventKind::Warn);
      CHECK(e.kind != EventKind::Failed);
    }
  }
}

TEST_CASE("card stream: a damaged GoTo frame is sent again and the move ends on its target") {
  StreamRig s;
  const Vec3 target = s.rig.position() + Vec3(10, -5, 0);
  s.line().to_card().inject(ChannelFault::Corrupt);
  REQUIRE(s.rig.go_to(target, 50) == core::Refusal::None);
  CHECK(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 2));
  CHECK(s.session().frames_resent() >= 1);
  CHECK((s.rig.position() - target).cwiseAbs().maxCoeff() < 0.005);
  for (const Event& e : s.rig.events()) CHECK(e.kind != EventKind::Fault);
}

TEST_CASE("card stream: a line that damages every frame sent again ends in Fault LinkErrors, braked on the path") {
  StreamRig s;
  const Vec3 centre = s.rig.position() + Vec3(20, 0, 0);
  s.queue(chord_circle(s.rig.position(), 20, 1.0, 2, 100));
  for (int i = 0; i < 400; ++i) s.step();
  REQUIRE(s.rig.mode() == Mode::Path);
  int cycles = 0;
  while (!s.faulted(core::FaultKind::LinkErrors) && cycles < 300) {
    s.line().to_card().inject(ChannelFault::Corrupt);  // every host frame from now on
    s.step();
    ++cycles;
  }
  std::printf("card stream: every host frame damaged -> Fault LinkErrors after %d ms, %lu frames sent again\n", cycles,
              s.session().frames_resent());
  CHECK(s.faulted(core::FaultKind::LinkErrors));
  CHECK_FALSE(s.comm_lost());
  CHECK(cycles <= 120);  // the lead (60 ms) plus the tries under way
  CHECK(s.session().frames_resent() >= 1);
  CHECK(s.rig.mode() == Mode::Fault);
  for (const Event& e : s.rig.events()) CHECK(!(e.kind == EventKind::Warn && e.warning == core::Warning::HostStall));
  // The card runs what it has of the path, then (starved: nothing sent again came through)
  // brakes along the path's tangent, every axis within its acceleration, and comes to rest:
  // off the circle by no more than a tangent of the braking distance from the path's speed
  // (100 mm/s, at most 105 measured in the first case).
  const auto machine = core::path_machine(s.rig.core().config());
  const double a = std::min(machine.axes[0].max_accel, machine.axes[1].max_accel);
  const double brake = 105.0 * 105.0 / (2 * a);
  const auto& m = s.rig.mechanics();
  double radial = 0;
  CHECK(s.run_until([&] {
    radial = std::max(radial, std::abs(Vec3(s.rig.position() - centre).head<2>().norm() - 20));
    return std::abs(m.velocity(0)) + std::abs(m.velocity(1)) + std::abs(m.velocity(2)) < 1e-6;
  }, 1.0));
  std::printf("card stream: braked to rest %.3f mm off the circle (a tangent of %.1f mm: %.3f mm)\n", radial, brake,
              std::hypot(20.0, brake) - 20);
  CHECK(radial < std::hypot(20.0, brake) - 20 + 0.05);
  // The line is good again: Reset resynchronises the stream; a GoTo runs over it afterwards.
  CHECK(s.rig.simple(CommandKind::Reset) == core::Refusal::None);
  s.rig.run(0.05);
  CHECK(s.rig.mode() == Mode::Free);
  const Vec3 target = s.rig.position() + Vec3(5, 5, 0);
  REQUIRE(s.rig.go_to(target, 50) == core::Refusal::None);
  CHECK(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 2));
  CHECK((s.rig.position() - target).cwiseAbs().maxCoeff() < 0.005);
}

TEST_CASE("card stream: a lost or damaged status frame is counted and the path goes on with the next") {
  for (const ChannelFault fault : {ChannelFault::Lose, ChannelFault::Corrupt}) {
    INFO((fault == ChannelFault::Lose ? "status frame lost" : "status frame damaged"));
    StreamRig s;
    s.queue(chord_circle(s.rig.position(), 20, 1.0, 2, 100));
    for (int i = 0; i < 400; ++i) s.step();
    REQUIRE(s.rig.mode() == Mode::Path);
    const auto before = s.session().errors();
    s.line().to_host().inject(fault);
    for (int i = 0; i < 30; ++i) s.step();
    CHECK(s.session().errors() == before + 1);  // counted once (Stats: LinkErrors)
    CHECK(s.rig.mode() == Mode::Path);
    CHECK(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 10));
    CHECK(s.rig.events().end() == std::find_if(s.rig.events().begin(), s.rig.events().end(),
                                               [](const Event& e) { return e.kind == EventKind::Fault; }));
    CHECK(s.rig.driver().link_errors() == before + 1);
  }
}

TEST_CASE("card stream: status frames that stop coming end in Fault CommLost within 30 ms") {
  StreamRig s;
  s.queue(chord_circle(s.rig.position(), 20, 1.0, 2, 100));
  for (int i = 0; i < 400; ++i) s.step();
  REQUIRE(s.rig.mode() == Mode::Path);
  int cycles = 0;
  while (!s.comm_lost() && cycles < 200) {
    s.line().to_host().inject(ChannelFault::Lose);
    s.step();
    ++cycles;
  }
  std::printf("card stream: status frames stopped -> Fault CommLost after %d ms\n", cycles);
  CHECK(s.comm_lost());
  CHECK(cycles <= 30);  // the last status frame came up to a status period (5 ms) before, then 20 periods
  CHECK_FALSE(s.faulted(core::FaultKind::LinkErrors));
}

TEST_CASE("card stream: a host that stops sending setpoints starves the card: it brakes on the path and says so, no fault") {
  StreamRig s;
  auto& drv = s.rig.driver();
  hal::MachineState ms;
  REQUIRE(drv.set_loops(true));
  const Vec3 start = s.rig.position();
  hal::Setpoint sp;
  sp.position = axes3(start);
  double v = 0;
  const Vec3 dir = Vec3(3, 4, 0).normalized();  // a diagonal: braking must keep to it
  for (int i = 0; i < 200; ++i) {  // accelerate to 50 mm/s, then cruise
    s.rig.clock().advance(MotionRig::kPeriod);
    REQUIRE(drv.read_state(ms));
    v = std::min(50.0, v + 1000 * 0.001);
    sp.position += axes3(dir * v * 0.001);
    sp.velocity = axes3(dir * v);
    REQUIRE(drv.follow(sp));
  }
  REQUIRE(!ms.faulted());
  REQUIRE(s.card().starvations() == 0);
  const Vec3 from = xyz(ms.position);
  int cycles = 0;
  while (!ms.any(st::kHostStarved) && cycles < 200) {  // the setpoints stop; the state is still read
    s.rig.clock().advance(MotionRig::kPeriod);
    REQUIRE(drv.read_state(ms));
    ++cycles;
  }
  std::printf("card stream: setpoints stopped -> the card starved, reported after %d ms\n", cycles);
  CHECK(s.card().starvations() == 1);
  CHECK(s.session().starvations() == 1);
  CHECK(ms.all(st::kHostStarved));
  CHECK_FALSE(ms.faulted());  // a stalled host is no fault: the loops hold the machine
  CHECK(ms.loops_closed());
  const double lead_ms = hal::StreamSettings{}.lead * 1000;  // the card runs the buffered path that long
  CHECK(cycles <= lead_ms + 15);
  for (int i = 0; i < 500; ++i) {
    s.rig.clock().advance(MotionRig::kPeriod);
    drv.read_state(ms);
  }
  CHECK(ms.motion_done());
  CHECK(ms.any(st::kHostStarved));  // until the next motion command
  const Vec3 moved = xyz(ms.position) - from;
  // Braked at 1000 mm/s² from 50 mm/s after the lead ran out: 1.25 mm, + the lead and the loop lag.
  CHECK(moved.norm() < 50 * 50 / 2000.0 + 50 * (lead_ms / 1000 + 0.02) + 0.2);
  // ... on the line it moved along: all axes came to rest together.
  CHECK((moved - moved.dot(dir) * dir).norm() < 0.01);
  // A new path starts at once, without a reset, and clears the report.
  const Vec3 here = xyz(ms.position);
  sp.position = axes3(here);
  for (int i = 0; i < 100; ++i) {
    s.rig.clock().advance(MotionRig::kPeriod);
    REQUIRE(drv.read_state(ms));
    sp.position.x() = here.x() + 5.0 * (i + 1) / 100;
    sp.velocity.setZero();
    sp.velocity.x() = i + 1 < 100 ? 50.0 : 0.0;
    REQUIRE(drv.follow(sp));
  }
  for (int i = 0; i < 300; ++i) {
    s.rig.clock().advance(MotionRig::kPeriod);
    drv.read_state(ms);
  }
  CHECK_FALSE(ms.faulted());
  CHECK_FALSE(ms.any(st::kHostStarved));
  CHECK(ms.position[0] == Approx(here.x() + 5).margin(0.01));
}

TEST_CASE("card stream: jog onto the cube, GoTo, stop and homing work over the stream") {
  SECTION("a motor hit measures the surface point within 1 um and retracts") {
    StreamRig s;
    REQUIRE(s.rig.start_mv({0, 0, -20}) == core::Refusal::None);
    std::vector<Event> pts;
    REQUIRE(s.run_until([&] {
      for (auto& e : s.rig.take(EventKind::MeasPt)) pts.push_back(e);
      return !pts.empty();
    }, 5.0));
    CHECK(pts.size() == 1);
    CHECK(pts[0].p.z() == Approx(80.0).margin(0.001));
    REQUIRE(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 5.0));
    s.rig.run(0.1);
    CHECK(s.rig.take(EventKind::MeasPt).empty());  // one edge, one point
    CHECK(s.rig.position().z() == Approx(82.5).margin(0.0005));
  }
  SECTION("GoTo ends in position; a stop brakes a jog to rest") {
    StreamRig s;
    const Vec3 target(460, 350, 120);
    REQUIRE(s.rig.go_to(target, 80) == core::Refusal::None);
    REQUIRE(s.rig.mode() == Mode::Move);
    REQUIRE(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 3.0));
    CHECK((s.rig.position() - target).cwiseAbs().maxCoeff() < 0.005);
    REQUIRE(s.rig.start_mv({50, 0, 0}) == core::Refusal::None);
    s.rig.run(0.3);
    s.rig.stop();
    REQUIRE(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 2.0));
    CHECK(s.rig.take(EventKind::Fault).empty());
  }
  SECTION("Home finds switch and index on every axis over the stream") {
    RigOptions o = streamed_options();
    o.sim.card.absolute_scales = false;
    o.core.referenced_at_start = false;
    StreamRig s(o);
    REQUIRE(s.rig.simple(CommandKind::Home) == core::Refusal::None);
    REQUIRE(s.run_until([&] { return s.rig.mode() != Mode::Home; }, 240.0));
    CHECK(s.rig.take(EventKind::Warn).empty());
    REQUIRE(s.rig.take(EventKind::Homed).size() == 1);
    s.rig.run(0.05);
    CHECK((s.rig.position() - xyz(s.rig.mechanics().carriage())).cwiseAbs().maxCoeff() < 0.001);
  }
}

TEST_CASE("card stream: frames damaged at random both ways, one in a hundred milliseconds each way: the path runs to its end") {
  for (unsigned seed : {1u, 2u, 3u, 4u, 5u}) {
    INFO("seed " << seed);
    StreamRig s;
    std::mt19937 rng(seed);
    std::bernoulli_distribution hit(0.01);
    s.queue(chord_circle(s.rig.position(), 20, 1.0, 2, 100));
    s.step();
    long cycles = 0;
    while (s.rig.mode() == Mode::Path && cycles < 10000) {
      if (hit(rng)) s.line().to_card().inject(ChannelFault::Corrupt);
      if (hit(rng)) s.line().to_host().inject(ChannelFault::Corrupt);
      s.step();
      ++cycles;
    }
    std::printf("card stream: random damage (seed %u): %s after %ld ms; %lu frames sent again, %lu link errors, %lu starvations\n",
                seed, s.rig.mode() == Mode::Idle ? "ended" : s.session().link_broken() ? "LinkErrors" : s.session().comm_lost() ? "CommLost" : "stopped",
                cycles, s.session().frames_resent(),
                s.session().errors(), s.card().starvations());
    CHECK(s.rig.mode() == Mode::Idle);
    CHECK(s.session().frames_resent() >= 1);
    CHECK(s.card().starvations() == 0);
    for (const Event& e : s.rig.events()) CHECK(e.kind != EventKind::Fault);
  }
}
