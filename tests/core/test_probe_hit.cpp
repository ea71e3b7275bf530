// Motor probe hits: latched point, radius correction along the motion, retract 0.5 mm.
#include <catch2/catch.hpp>

#include "core_rig.hpp"

using namespace imess::test;

TEST_CASE("jogging -Z onto the cube top measures the true surface point and retracts 0.5 mm") {
  CoreRig rig;
  REQUIRE(rig.mode() == Mode::Free);
  const Vec3 start = rig.position();
  REQUIRE(rig.start_mv({0, 0, -20}) == imess::core::Refusal::None);
  REQUIRE(rig.mode() == Mode::Jog);
  REQUIRE(rig.run_until([&] { return !rig.take(EventKind::MeasPt).empty() || rig.mode() == Mode::Retract; }, 3.0));
  // The MeasPt event was taken in the predicate; run on to the end of the retract and look again.
  rig.clear_events();
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5.0));
  REQUIRE_FALSE(rig.mechanics().tip_contact());
  CHECK(rig.position().z() == Approx(80.0 + 2.0 + 0.5).margin(0.005));  // in-position window
  rig.run(0.1);
  // Retract: 0.5 mm behind the latched ball centre (which sits at top + r = 82).
  CHECK(rig.position().z() == Approx(80.0 + 2.0 + 0.5).margin(0.0002));
  CHECK(rig.position().x() == Approx(start.x()).margin(1e-3));
  CHECK(rig.position().y() == Approx(start.y()).margin(1e-3));
}

TEST_CASE("the measured point is the surface point within 1 um, whatever the jog speed") {
  for (double pct : {2.0, 20.0, 100.0}) {
    CoreRig rig;
    rig.start_mv({0, 0, -pct});
    std::vector<Event> pts;
    REQUIRE(rig.run_until([&] {
      for (auto& e : rig.take(EventKind::MeasPt)) pts.push_back(e);
      return !pts.empty();
    }, 20.0));
    INFO("speed " << pct << " %");
    CHECK(pts[0].p.z() == Approx(80.0).margin(0.001));
    CHECK(pts[0].compensated);
    CHECK(pts[0].dir.isApprox(Vec3(0, 0, -1)));
    REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 6.0));
  }
}

TEST_CASE("an oblique jog compensates along its own direction") {
  // From above the cube top, move down and sideways: the hit is on the top face, the point
  // is the ball centre plus r along the (oblique) motion — the known approach-angle error.
  CoreRig rig;
  Vec3 dir = Vec3(1, 0, -1).normalized();
  rig.start_mv(20 * dir);
  std::vector<Event> pts;
  REQUIRE(rig.run_until([&] {
    for (auto& e : rig.take(EventKind::MeasPt)) pts.push_back(e);
    return !pts.empty();
  }, 5.0));
  double r = 2.0, alpha = M_PI / 4;
  // Ball centre at z = 82 on contact; compensated point r·cos(45°) lower.
  CHECK(pts[0].p.z() == Approx(82.0 - r * std::cos(alpha)).margin(0.001));
  CHECK(pts[0].dir.isApprox(dir, 1e-9));
}

TEST_CASE("ForcePt reports the current position without correction") {
  CoreRig rig;
  rig.clear_events();
  REQUIRE(rig.simple(CommandKind::ForcePt) == imess::core::Refusal::None);
  auto pts = rig.take(EventKind::MeasPt);
  REQUIRE(pts.size() == 1);
  CHECK_FALSE(pts[0].compensated);
  CHECK(pts[0].p.isApprox(rig.position(), 1e-9));
}

TEST_CASE("a hit during GoTo is an unexpected hit: warned, retracted, no point") {
  CoreRig rig;
  rig.go_to({430, 330, 60});  // straight down through the cube top
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Retract; }, 3.0));
  CHECK(rig.take(EventKind::MeasPt).empty());
  auto w = rig.take(EventKind::Warn);
  REQUIRE(w.size() == 1);
  CHECK(w[0].warning == imess::core::Warning::UnexpectedHit);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5.0));
}

TEST_CASE("GoTo ends on the target") {
  CoreRig rig;
  REQUIRE(rig.go_to({300, 200, 150}, 80) == imess::core::Refusal::None);
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 10.0));
  CHECK((rig.position() - Vec3(300, 200, 150)).cwiseAbs().maxCoeff() < 0.005);  // in-position window
  rig.run(0.1);
  CHECK((rig.position() - Vec3(300, 200, 150)).norm() < 0.0002);  // settled
}

TEST_CASE("a normally-closed probe (TipReversed) measures the same point") {
  auto o = default_options();
  o.sim.mechanics.probe.normally_closed = true;  // the switch opens on contact
  o.tip_reversed = true;                         // and messd is told so
  CoreRig rig(o);
  CHECK_FALSE(rig.core().machine().tip_touched);
  rig.start_mv({0, 0, -20});
  std::vector<Event> pts;
  REQUIRE(rig.run_until([&] {
    for (auto& e : rig.take(EventKind::MeasPt)) pts.push_back(e);
    return !pts.empty();
  }, 3.0));
  CHECK(pts[0].p.z() == Approx(80.0).margin(0.001));
  REQUIRE(rig.run_until([&] { return rig.mode() == Mode::Idle; }, 5.0));
  CHECK_FALSE(rig.core().machine().tip_touched);
}

TEST_CASE("a normally-closed probe that messd thinks is normally open reads as touched") {
  auto o = default_options();
  o.sim.mechanics.probe.normally_closed = true;  // wrong stylus file: TipReversed false
  CoreRig rig(o);
  CHECK(rig.core().machine().tip_touched);
  CHECK(rig.start_mv({0, 0, -20}) == imess::core::Refusal::TipTouched);  // safe: it will not move
}
