// Scanning in virtual time (docs/scanning.md): the motion core on the simulated CMM whose probe
// measures its deflection, both card links, scans planned by planner::scan_requests. Every
// scan point lies on the true surface (the scene's signed distance) within 1 µm, the deflection
// stays in its band while following, contact is never lost and the range never reached; the
// scan ends Done at its planned end. Scans that cannot hold contact stop with their reason.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "imess/sim/analog_probe.hpp"
#include "scan_rig.hpp"

using namespace imess;
using namespace imess::test;
using core::FailReason;

namespace {

constexpr double kBall = 2.0;
// The streamed card's status frames with a measuring probe: a fresh sample this often, s
// (docs/servo-card-link.md, "The measuring probe").
constexpr double kStreamSamplePeriod = 0.006;

planner::ScanSettings settings(double speed, double step) {
  planner::ScanSettings s;
  s.tip_radius = kBall;
  s.speed = speed;
  s.step = step;
  s.approach_speed = 5;
  s.feed = 50;
  return s;
}

// The cube's right face (local x = 60), turned by its yaw: a point on it and its outward normal.
Vec3 cube_face_point(double y_local, double z) {
  const double yaw = 0.3 * M_PI / 180;
  const Vec3 local(60, y_local, 0);
  return Vec3(460 + std::cos(yaw) * local.x() - std::sin(yaw) * local.y(), 350 + std::sin(yaw) * local.x() + std::cos(yaw) * local.y(), z);
}
Vec3 cube_face_normal() {
  const double yaw = 0.3 * M_PI / 180;
  return Vec3(std::cos(yaw), std::sin(yaw), 0);
}

planner::Point3 p3(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

struct Case {
  const char* name;
  Vec3 start;  // where the machine stands
  planner::ScanShape shape;
  double length;  // mm along the ball centre's path
};

std::vector<Case> cases() {
  std::vector<Case> out;
  // The bore (Ø 30 at 460 350, vertical), a full circle 20 mm below the top.
  planner::ScanCircleShape bore;
  bore.centre = {460, 350, 60};
  bore.start = {475, 350, 60};
  bore.sweep = 360;
  bore.radial = -1;
  out.push_back({"bore", Vec3(460, 350, 60), bore, 2 * M_PI * (15 - 1.7)});
  // A ring on the cube's top round the bore (the surface square to the circle's axis).
  planner::ScanCircleShape ring_on_top;
  ring_on_top.centre = {460, 350, 80};
  ring_on_top.start = {485, 350, 80};
  ring_on_top.sweep = 180;
  ring_on_top.radial = 1;
  ring_on_top.axial = 1;
  out.push_back({"ring on the top", Vec3(485, 350, 90), ring_on_top, M_PI * 25});
  // The cube's top, a line clear of the bore and the fillet.
  out.push_back({"top face", Vec3(430, 330, 90), planner::ScanLineShape{{430, 330, 80}, {490, 330, 80}, {0, 0, 1}}, 60});
  // The cube's right face, turned by the yaw.
  const Vec3 a = cube_face_point(-30, 40), b = cube_face_point(30, 40);
  out.push_back({"right face", a + 6 * cube_face_normal(), planner::ScanLineShape{p3(a), p3(b), p3(cube_face_normal())}, 60});
  // The reference sphere (Ø 25 at 750 650 60): circles at three heights above its stem.
  for (const double h : {0.0, 5.0, 9.0}) {
    planner::ScanCircleShape ring;
    const double r = std::sqrt(12.5 * 12.5 - h * h);
    ring.centre = {750, 650, 60 + h};
    ring.start = {750 + r, 650, 60 + h};
    ring.sweep = h == 5.0 ? -270 : 360;
    ring.radial = 1;
    ring.axial = h / 12.5;
    out.push_back({h == 0 ? "sphere equator" : h == 5 ? "sphere at 5" : "sphere at 9", Vec3(750 + r + 8, 650, 60 + h + 8), ring,
                   std::fabs(ring.sweep) / 360 * 2 * M_PI * (r + 1.7 * std::sqrt(1 - ring.axial * ring.axial))});
  }
  return out;
}

}  // namespace

TEST_CASE("scans of the bore, the faces and the sphere: every point on the surface within 1 um, the deflection in its band",
          "[scan][long]") {
  const bool streamed = GENERATE(false, true);
  for (const Case& c : cases())
    for (const double speed : {5.0, 15.0})
      for (const double step : {0.05, 0.5}) {
        INFO(c.name << (streamed ? ", streamed" : ", request/reply") << ", " << speed << " mm/s, step " << step << " mm");
        ScanRig rig(c.start, streamed);
        rig.plan(7, c.shape, settings(speed, step));
        rig.run(7, c.length / speed + 30);
        REQUIRE(rig.end);
        CHECK(rig.end->kind == EventKind::Done);
        CHECK_FALSE(rig.over_range);
        // Points: as many as the step gives along the path (on the stream no closer than its
        // status frames come, at most every 6 ms with a measuring probe), every one on the surface,
        // its direction the surface's inward normal.
        const double spacing = streamed ? std::max(step, speed * kStreamSamplePeriod) : step;
        CHECK(rig.points.size() >= static_cast<std::size_t>(0.9 * c.length / spacing));
        CHECK(rig.points.size() <= static_cast<std::size_t>(1.1 * c.length / step) + 2);
        CHECK(rig.worst_surface_error() <= 0.001);
        const auto& scene = rig.core_rig().mechanics().scene();
        for (const auto& p : rig.points) {
          CHECK(p.id == 7);
          CHECK(p.radius == kBall);
          CHECK(p.dir.dot(-sim::surface_normal(scene, p.p - 0.01 * p.dir)) > 0.9999);
        }
        // The deflection held within 0.3 ± 0.1 mm while following (after 50 ms of settling
        // from the approach's corner).
        const auto held = rig.following(50);
        REQUIRE(held.size() > 100);
        const auto [lo, hi] = std::minmax_element(held.begin(), held.end());
        CHECK(*lo >= 0.2);
        CHECK(*hi <= 0.4);
        // It ends where it was planned, off the surface.
        CHECK(rig.core_rig().core().machine().deflection.norm() < 1e-9);
      }
}

TEST_CASE("a scan that loses the surface, presses beyond the range or has no measuring probe stops with its reason", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  SECTION("a line running off the cube's edge: Failed ScanLostContact, the machine stops near the edge") {
    ScanRig rig(Vec3(470, 330, 90), streamed);
    rig.plan(3, planner::ScanLineShape{{470, 330, 80}, {560, 330, 80}, {0, 0, 1}}, settings(5, 0.1));
    rig.run(3, 40);
    REQUIRE(rig.end);
    CHECK(rig.end->kind == EventKind::Failed);
    CHECK(rig.end->fail == FailReason::ScanLostContact);
    CHECK_FALSE(rig.over_range);
    rig.core_rig().run(1);
    CHECK(rig.core_rig().mode() == Mode::Idle);
    // The right edge lies near x 520; the machine stopped soon after the ball left it.
    CHECK(rig.core_rig().position().x() < 522 + 2 + 5 * 0.5);
    CHECK(rig.core_rig().position().z() > 80 + 2 - planner::kMaxScanCorrection - 0.5);
    for (const auto& p : rig.points) CHECK(std::fabs(rig.core_rig().mechanics().scene().distance(p.p)) <= 0.001);
  }
  SECTION("a nominal surface 1.5 mm above the part: no contact, Failed ScanLostContact") {
    ScanRig rig(Vec3(430, 330, 95), streamed);
    rig.plan(4, planner::ScanLineShape{{430, 330, 81.5}, {490, 330, 81.5}, {0, 0, 1}}, settings(5, 0.1));
    rig.run(4, 40);
    REQUIRE(rig.end);
    CHECK(rig.end->fail == FailReason::ScanLostContact);
    CHECK(rig.points.empty());
  }
  SECTION("a nominal surface 2 mm inside the part: Failed ScanOverRange, backed off until free") {
    // Deeper than the largest correction and the range allow; a clearance of 3 mm keeps the
    // move to the clearance point off the part (else that move's touch is an unexpected hit).
    ScanRig rig(Vec3(430, 330, 95), streamed);
    auto s = settings(5, 0.1);
    s.clearance = 3;
    rig.plan(5, planner::ScanLineShape{{430, 330, 78}, {490, 330, 78}, {0, 0, 1}}, s);
    rig.run(5, 40);
    REQUIRE(rig.end);
    CHECK(rig.end->kind == EventKind::Failed);
    CHECK(rig.end->fail == FailReason::ScanOverRange);
    rig.core_rig().run(2);
    CHECK(rig.core_rig().core().machine().deflection.norm() < 1e-9);
    CHECK(rig.core_rig().mode() == Mode::Idle);
  }
}

TEST_CASE("a scan with a touch-trigger probe fails NoMeasuringProbe at the clearance point, off the part", "[scan]") {
  RigOptions o = analog_options(Vec3(430, 330, 95), false);
  o.sim.mechanics.probe.type = sim::ProbeType::Trigger;
  CoreRig rig(o);
  rig.run(0.2);
  queue_scan(rig, 9, planner::ScanLineShape{{430, 330, 80}, {490, 330, 80}, {0, 0, 1}}, settings(5, 0.1));
  std::vector<Event> failed;
  REQUIRE(rig.run_until([&] {
    for (const auto& e : rig.take(EventKind::Failed)) failed.push_back(e);
    return !failed.empty();
  }, 20));
  CHECK(failed.size() == 1);
  CHECK(failed[0].fail == core::FailReason::NoMeasuringProbe);
  rig.run(1);
  CHECK(rig.mode() == Mode::Idle);
  CHECK(rig.position().z() > 80 + kBall);  // never touched the top
}
