// Measuring by hand with the loops open: direction from the last >= 1 mm of travel (the
// travel itself, not its reverse), at most one point per second.
#include <catch2/catch.hpp>

#include "core_rig.hpp"

using namespace imess::test;
using imess::core::Warning;

namespace {
std::vector<Event> points_after(CoreRig& rig, double seconds) {
  std::vector<Event> pts;
  for (int i = 0; i < seconds * 1000; ++i) {
    rig.step();
    for (auto& e : rig.take(EventKind::MeasPt)) pts.push_back(e);
  }
  return pts;
}
}  // namespace

TEST_CASE("a hand push onto the top face gives the compensated surface point") {
  CoreRig rig;
  REQUIRE(rig.mode() == Mode::Free);
  rig.hand({0, 0, -20}, 10);  // from z 100 down to 80: contact at 82
  auto pts = points_after(rig, 2.5);
  REQUIRE(pts.size() == 1);
  CHECK(pts[0].p.z() == Approx(80.0).margin(0.001));
  CHECK(pts[0].dir.isApprox(Vec3(0, 0, -1), 1e-6));  // travel direction, not its reverse
}

TEST_CASE("an oblique hand push compensates along the travel") {
  CoreRig rig;
  Vec3 d = Vec3(3, 4, -20);
  rig.hand(d, 10);
  auto pts = points_after(rig, 3.0);
  REQUIRE(pts.size() == 1);
  CHECK(pts[0].dir.isApprox(d.normalized(), 1e-4));
}

TEST_CASE("a second hand hit within a second is ignored with a warning") {
  CoreRig rig;
  rig.go_to({430, 330, 83.5});
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5.0));
  rig.simple(CommandKind::Free);
  rig.clear_events();
  rig.hand({0, 0, -2}, 10);  // 1.5 mm of travel before contact
  rig.run(0.3);
  REQUIRE(rig.take(EventKind::MeasPt).size() == 1);
  rig.hand({0, 0, 2}, 20);   // lift...
  rig.run(0.15);
  rig.hand({0, 0, -2}, 20);  // ...and touch again at once
  rig.run(0.3);
  CHECK(rig.take(EventKind::MeasPt).empty());
  auto w = rig.take(EventKind::Warn);
  REQUIRE(w.size() == 1);
  CHECK(w[0].warning == Warning::HandHitTooSoon);
  rig.hand({0, 0, 2}, 20);
  rig.run(1.0);
  rig.hand({0, 0, -2}, 20);  // more than a second later: accepted
  rig.run(0.3);
  CHECK(rig.take(EventKind::MeasPt).size() == 1);
}

TEST_CASE("a hand hit without 1 mm of travel has no direction and is refused") {
  CoreRig rig;
  rig.go_to({430, 330, 82.6});
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5.0));
  rig.simple(CommandKind::Free);
  rig.clear_events();
  rig.hand({0, 0, -0.8}, 5);  // only 0.6 mm of travel before contact
  rig.run(0.5);
  CHECK(rig.take(EventKind::MeasPt).empty());
  auto w = rig.take(EventKind::Warn);
  REQUIRE(w.size() == 1);
  CHECK(w[0].warning == Warning::HandHitNoTravel);
}
