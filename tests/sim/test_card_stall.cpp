// A stalled host over the streamed card (virtual time): the motion loop misses cycles while
// the card runs the buffered path on its own clock. Shorter than the lead: nothing changes
// (no starvation, the path stays on the circle, every id Done). Longer: the card brakes on
// the path, the core warns HostStall with the stall's length, the path's ids fail HostStall
// — no fault — and the next path runs at once, without a Reset.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdio>

#include "card_stream_rig.hpp"

using namespace imess;
using namespace imess::test;

namespace {

// The loop stands still for `seconds`: the clock moves on, no cycle runs (a page fault, a
// descheduled thread); the in-process card catches up on the next poll, as a real one ran.
void stall(StreamRig& s, double seconds) { s.rig.clock().advance(std::chrono::duration_cast<hal::Nanos>(std::chrono::duration<double>(seconds))); }

int count(const std::vector<Event>& events, EventKind kind) {
  return static_cast<int>(std::count_if(events.begin(), events.end(), [&](const Event& e) { return e.kind == kind; }));
}

}  // namespace

TEST_CASE("card stall: stalls shorter than the lead change nothing: no starvation, on the circle, every id Done") {
  StreamRig s;
  const double lead = hal::StreamSettings{}.lead;
  const double pause = 0.7 * lead;
  const Vec3 start = s.rig.position(), centre = start + Vec3(20, 0, 0);
  const auto path = chord_circle(start, 20, 1.0, 1, 100);
  s.queue(path);
  s.step();
  REQUIRE(s.rig.mode() == Mode::Path);
  double radial = 0;
  int stalls = 0;
  for (long cycle = 0; s.rig.mode() == Mode::Path && cycle < 10000; ++cycle) {
    if (cycle > 300 && cycle % 97 == 0) {  // every ~0.1 s once at speed
      stall(s, pause);
      ++stalls;
    }
    s.step();
    if (cycle > 300) radial = std::max(radial, std::abs((s.rig.position() - centre).head<2>().norm() - 20));
  }
  std::printf("card stall: %d stalls of %.1f ms (lead %.1f ms): radial error %.4f mm, starvations %lu\n", stalls,
              pause * 1000, lead * 1000, radial, s.card().starvations());
  CHECK(stalls >= 5);
  CHECK(s.rig.mode() == Mode::Idle);
  CHECK(s.card().starvations() == 0);
  CHECK_FALSE(s.comm_lost());
  CHECK(count(s.rig.events(), EventKind::Done) == static_cast<int>(path.size()));
  CHECK(count(s.rig.events(), EventKind::Failed) == 0);
  CHECK(radial < 0.05);  // the card's cubic across the wider knots, and the loop's lag
}

TEST_CASE("card stall: a stall longer than the lead: the card brakes on the path, Warn HostStall, ids fail, ready at once") {
  StreamRig s;
  const Vec3 start = s.rig.position();
  s.queue(chord_circle(start, 20, 1.0, 1, 100));
  for (int i = 0; i < 400; ++i) s.step();  // at speed on the circle
  REQUIRE(s.rig.mode() == Mode::Path);
  const double lead = s.session().lead();
  stall(s, 0.150);
  REQUIRE(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 2));
  const auto& ev = s.rig.events();
  const auto warn = std::find_if(ev.begin(), ev.end(), [](const Event& e) { return e.kind == EventKind::Warn; });
  REQUIRE(warn != ev.end());
  CHECK(warn->warning == core::Warning::HostStall);
  CHECK(warn->value >= 150);  // ms: the loop's longest gap, the stall itself
  CHECK(warn->value <= 152);
  CHECK(s.card().starvations() == 1);
  CHECK(count(ev, EventKind::Fault) == 0);
  CHECK(count(ev, EventKind::Failed) > 0);
  for (const auto& e : ev)
    if (e.kind == EventKind::Failed) CHECK(e.fail == core::FailReason::HostStall);
  // The next path starts from where the machine stands and runs to its end.
  s.rig.clear_events();
  s.queue_from_here({[&] {
    planner::Line l;
    l.id = 1000;
    l.target = pose_of(s.rig.position() + Vec3(-10, -10, 0));
    l.feed = 50;
    return planner::Request(l);
  }()});
  REQUIRE(s.run_until([&] { return count(s.rig.events(), EventKind::Done) == 1; }, 3));
  CHECK(count(s.rig.events(), EventKind::Fault) == 0);
  CHECK(count(s.rig.events(), EventKind::Warn) == 0);
  // The lead grew: a card that starved doubles it (up to max_lead).
  std::printf("card stall: lead %.0f ms before a 150 ms stall, %.0f ms after\n", lead * 1000, s.session().lead() * 1000);
  CHECK(s.session().lead() >= 1.95 * lead);  // (the memory of stalls fades slowly while following)
  CHECK(s.session().lead() <= hal::StreamSettings{}.max_lead);
}

TEST_CASE("card stall: a stop during a streamed path brakes to rest and the machine stands idle") {
  StreamRig s;
  s.queue(chord_circle(s.rig.position(), 20, 1.0, 1, 100));
  for (int i = 0; i < 400; ++i) s.step();
  REQUIRE(s.rig.mode() == Mode::Path);
  s.rig.stop();
  CHECK(s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 1));
  const Vec3 rest = s.rig.position();
  for (int i = 0; i < 500; ++i) s.step();
  std::printf("card stall: stopped, mode %d, moved %.4f mm in 0.5 s after\n", static_cast<int>(s.rig.mode()), (s.rig.position() - rest).norm());
  CHECK((s.rig.position() - rest).norm() < 0.005);  // the position loop settles within its in-position window
}

TEST_CASE("card stall: a feed hold, its resume and a stop on a streamed path: the machine comes to rest") {
  StreamRig s;
  const Vec3 start = s.rig.position();
  std::vector<planner::Request> path;
  for (int i = 0; i < 3; ++i) {
    planner::Line l;
    l.id = static_cast<std::uint32_t>(i + 1);
    l.target = pose_of(start + Vec3(30.0 * (i + 1), -10.0 * (i + 1), 0));
    l.feed = 100;
    path.push_back(l);
  }
  s.queue(path);
  for (int i = 0; i < 300; ++i) s.step();
  REQUIRE(s.rig.simple(CommandKind::Pause) == core::Refusal::None);
  for (int i = 0; i < 500; ++i) s.step();
  REQUIRE(s.rig.simple(CommandKind::Resume) == core::Refusal::None);
  for (int i = 0; i < 300; ++i) s.step();
  s.rig.stop();
  const bool rested = s.run_until([&] { return s.rig.mode() == Mode::Idle; }, 1);
  std::printf("card stall: hold, resume, stop: mode %d, card following %d, starvations %lu\n", static_cast<int>(s.rig.mode()),
              0, s.card().starvations());
  CHECK(rested);
}
