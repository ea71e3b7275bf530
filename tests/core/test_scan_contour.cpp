// Unknown contours in virtual time (planner::ScanContourShape, ScanPhase::Contour): the motion
// core on the simulated CMM with a measuring probe, both card links. The scan knows only its
// start, its constraint (a plane, a cylinder) and its stop body; it finds the cube's corner, its
// fillet and its top by the measured normal. Every point lies on the true surface within 1 µm,
// the deflection stays in its band, the scan ends at its stop body, Done as a Probe's (where
// the machine stands), backed off the surface.
#include <catch2/catch.hpp>

#include <cmath>
#include <optional>
#include <vector>

#include "scan_rig.hpp"

using namespace imess;
using namespace imess::test;
using core::FailReason;

namespace {

constexpr double kContourBall = 2.0;
constexpr double kCubeYaw = 0.3 * M_PI / 180;

// A point given in the cube's own frame (origin at its centre 460 350 40, x right, y back,
// z up), and a direction, in machine coordinates.
Vec3 cube_point(double x, double y, double z) {
  return Vec3(460 + std::cos(kCubeYaw) * x - std::sin(kCubeYaw) * y, 350 + std::sin(kCubeYaw) * x + std::cos(kCubeYaw) * y, 40 + z);
}
Vec3 cube_dir(double x, double y, double z) {
  return Vec3(std::cos(kCubeYaw) * x - std::sin(kCubeYaw) * y, std::sin(kCubeYaw) * x + std::cos(kCubeYaw) * y, z);
}
planner::Point3 pt(const Vec3& v) { return {v.x(), v.y(), v.z()}; }

// A contour scan's rig: Position, Approach and one Contour segment, no Leave.
class ContourRig : public ScanRig {
 public:
  using ScanRig::ScanRig;
  void plan(std::uint32_t id, const planner::ScanContourShape& shape, const planner::ScanSettings& s) {
    REQUIRE(ScanRig::plan(id, shape, s) == 3);  // Position, Approach, Contour
  }
};

planner::ScanSettings contour_settings(double speed, double step) {
  planner::ScanSettings s;
  s.tip_radius = kContourBall;
  s.speed = speed;
  s.step = step;
  s.travel_min = {0, 0, 0};
  s.travel_max = {1000, 1000, 600};
  return s;
}

// What every contour scan must show: Done as a Probe's, where the machine stands, backed off
// the surface; every point on the surface; the deflection in 0.3 ± 0.1 mm.
void check_contour(ContourRig& rig, std::uint32_t id, double clearance) {
  REQUIRE(rig.end);
  INFO("ended " << (rig.end->kind == EventKind::Done ? "Done" : "Failed") << " reason " << static_cast<int>(rig.end->fail)
                << " after " << rig.points.size() << " points");
  REQUIRE(rig.end->kind == EventKind::Done);
  CHECK(rig.end->id == id);
  CHECK(rig.end->probe_end);
  CHECK_FALSE(rig.over_range);
  auto& core = rig.core_rig();
  core.run(0.2);
  CHECK(core.mode() == Mode::Idle);
  CHECK((xyz(rig.end->end) - core.position()).norm() < 0.01);  // Done says where the machine stands
  CHECK(core.core().machine().deflection.norm() < 1e-9);       // off the surface ...
  CHECK(rig.scene().distance(core.position()) > kContourBall + clearance - 0.5);  // ... by about the clearance
  CHECK(rig.worst_surface_error() <= 0.001);
  const auto held = rig.following(50);
  REQUIRE(held.size() > 100);
  const auto [lo, hi] = std::minmax_element(held.begin(), held.end());
  CHECK(*lo >= 0.2);
  CHECK(*hi <= 0.4);
}

}  // namespace

TEST_CASE("an unknown contour in a horizontal plane round the cube's corner, stopping at a plane", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  // On the front face (y −50 in the cube's frame) 40 mm up, toward its right end; round the
  // sharp vertical edge at x 60; along the right face to the plane y −20.
  const Vec3 start = cube_point(30, -50, 0), n_front = cube_dir(0, -1, 0), n_right = cube_dir(1, 0, 0);
  ContourRig rig(start + 8 * n_front + Vec3(0, 0, 5), streamed);
  planner::ScanContourShape c;
  c.start = pt(start);
  c.start_normal = pt(n_front);
  c.constraint = planner::ContourConstraint::Plane;
  c.plane_normal = {0, 0, 1};
  c.direction = pt(start + cube_dir(10, 0, 0));
  c.stop = planner::StopBody::Plane;
  c.stop_point = pt(cube_point(60, -20, 0));
  c.stop_normal = pt(cube_dir(0, 1, 0));
  c.count = 1;
  c.stop_after = 10;
  c.end_normal = pt(n_right);
  const double step = 0.2;
  rig.plan(11, c, contour_settings(5, step));
  rig.run(11, 40);
  check_contour(rig, 11, 2);
  // It went round the corner: points on the front face, round the edge and on the right face.
  int front = 0, round = 0, right = 0;
  for (const auto& p : rig.points) {
    CHECK(std::fabs(p.p.z() - 40) < 0.01);  // in the plane through the start
    const Vec3 out = -p.dir;
    if (out.dot(n_front) > 0.9999) ++front;
    else if (out.dot(n_right) > 0.9999) ++right;
    else ++round;
  }
  CHECK(front >= static_cast<int>(0.9 * 30 / step));
  CHECK(right >= static_cast<int>(0.9 * 30 / step));
  CHECK(round >= 3);  // the ball rolled round the edge: the normal turned through the points
  // It ended at the stop plane: the last point within a step of it, not beyond it by more.
  const Vec3 stop = cube_point(60, -20, 0), stop_n = cube_dir(0, 1, 0);
  CHECK(std::fabs((rig.points.back().p - stop).dot(stop_n)) <= step + 0.01);
}

TEST_CASE("an unknown contour in a vertical plane over the front-top fillet, stopping at a sphere", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  // Up the front face at x −20 (clear of the bore), over the fillet (r 10), along the top
  // toward the back, to a sphere Ø 4 on the top at y −25.
  const Vec3 start = cube_point(-20, -50, 10), n_front = cube_dir(0, -1, 0);
  const Vec3 centre = cube_point(-20, -25, 40);
  ContourRig rig(start + 8 * n_front, streamed);
  planner::ScanContourShape c;
  c.start = pt(start);
  c.start_normal = pt(n_front);
  c.constraint = planner::ContourConstraint::Plane;
  c.plane_normal = pt(cube_dir(1, 0, 0));
  c.direction = pt(start + Vec3(0, 0, 10));
  c.stop = planner::StopBody::Sphere;
  c.stop_point = pt(centre);
  c.stop_diameter = 4;
  c.end_normal = {0, 0, 1};
  const double step = 0.2;
  rig.plan(12, c, contour_settings(5, step));
  rig.run(12, 40);
  check_contour(rig, 12, 2);
  int face = 0, fillet = 0, top = 0;
  for (const auto& p : rig.points) {
    const Vec3 out = -p.dir;
    if (out.dot(n_front) > 0.9999) ++face;
    else if (out.z() > 0.9999) ++top;
    else ++fillet;
  }
  CHECK(face >= static_cast<int>(0.9 * 20 / step));         // z 50 … 70
  CHECK(fillet >= static_cast<int>(0.9 * M_PI * 5 / step));  // a quarter round of r 10
  CHECK(top >= static_cast<int>(0.9 * 13 / step));           // y −40 … −27 to the sphere's edge
  // It ended in the sphere, where the contour comes closest to its centre (on the top: at it).
  CHECK((rig.points.back().p - centre).norm() <= step + 0.01);
}

TEST_CASE("an unknown contour on a cylinder round the bore, stopping at a plane after one turn", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  // On the cube's top, 25 mm from the bore's axis, the ball kept on the cylinder about it:
  // counter-clockwise once round; the plane y 350 through the axis is crossed half-way (1)
  // and at the start again (2).
  ContourRig rig(Vec3(485, 350, 90), streamed);
  planner::ScanContourShape c;
  c.start = {485, 350, 80};
  c.start_normal = {0, 0, 1};
  c.constraint = planner::ContourConstraint::Cylinder;
  c.axis_point = {460, 350, 0};
  c.axis = {0, 0, 1};
  c.direction = {485, 360, 80};
  c.stop = planner::StopBody::Plane;
  c.stop_point = {460, 350, 80};
  c.stop_normal = {0, 1, 0};
  c.count = 2;
  c.stop_after = 5;
  c.end_normal = {0, 0, 1};
  const double step = 0.5;
  rig.plan(13, c, contour_settings(20, step));
  rig.run(13, 30);
  check_contour(rig, 13, 2);
  double turned = 0, last = 0;  // the angle swept about the axis, degrees
  for (std::size_t i = 0; i < rig.points.size(); ++i) {
    const Vec3& p = rig.points[i].p;
    CHECK(std::fabs(std::hypot(p.x() - 460, p.y() - 350) - 25) < 0.01);  // on the cylinder
    const double a = std::atan2(p.y() - 350, p.x() - 460) * 180 / M_PI;
    if (i > 0) turned += std::remainder(a - last, 360.0);
    last = a;
  }
  CHECK(turned > 360 - 360 * step / (2 * M_PI * 25) - 0.5);
  CHECK(turned < 360 + 360 * step / (2 * M_PI * 25) + 0.5);
  CHECK(std::fabs(rig.points.back().p.y() - 350) <= step + 0.01);
}

TEST_CASE("an unknown contour whose stop body is not met within its length fails PartNotFound, backed off", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  const Vec3 start = cube_point(0, -50, 0), n_front = cube_dir(0, -1, 0);
  ContourRig rig(start + 8 * n_front, streamed);
  planner::ScanContourShape c;
  c.start = pt(start);
  c.start_normal = pt(n_front);
  c.plane_normal = {0, 0, 1};
  c.direction = pt(start + cube_dir(10, 0, 0));
  c.stop = planner::StopBody::Sphere;  // far off the contour
  c.stop_point = {100, 100, 100};
  c.stop_diameter = 5;
  c.end_normal = pt(n_front);
  c.max_length = 10;
  rig.plan(14, c, contour_settings(5, 0.5));
  rig.run(14, 20);
  REQUIRE(rig.end);
  CHECK(rig.end->kind == EventKind::Failed);
  CHECK(rig.end->fail == FailReason::PartNotFound);
  CHECK(rig.points.size() >= 18);  // 10 mm of the front face
  CHECK(rig.points.size() <= 22);
  CHECK(rig.worst_surface_error() <= 0.001);
  rig.core_rig().run(1);
  CHECK(rig.core_rig().mode() == Mode::Idle);
  CHECK(rig.core_rig().core().machine().deflection.norm() < 1e-9);
}

TEST_CASE("an unknown contour with a touch-trigger probe fails NoMeasuringProbe off the part", "[scan]") {
  RigOptions o = default_options();
  o.sim.mechanics.probe.ball_radius = kContourBall;
  o.sim.mechanics.start = axes3(Vec3(485, 350, 90));
  CoreRig rig(o);
  rig.run(0.2);
  planner::Machine m = planner::make_machine("XYZ", 0, 1000, 150, 1000);
  m.axes[2].travel_max = 600;
  planner::Planner plan(m);
  plan.set_position({485, 350, 90});
  planner::ScanContourShape c;
  c.start = {485, 350, 80};
  c.start_normal = {0, 0, 1};
  c.plane_normal = {0, 1, 0};
  c.direction = {495, 350, 80};
  c.stop_point = {500, 350, 80};
  c.stop_diameter = 2;
  c.end_normal = {0, 0, 1};
  const auto requests = planner::scan_requests(15, plan.position(), c, contour_settings(5, 0.1));
  for (const auto& r : std::get<std::vector<planner::Request>>(requests))
    if (const auto res = plan.append(r); !res.ok()) FAIL(planner::describe(res, m));
  plan.flush();
  planner::PlannedSegment seg;
  while (plan.take(seg)) REQUIRE(rig.core().submit_segment({seg, rig.core().stop_ticket(), 0}));
  std::vector<Event> failed;
  REQUIRE(rig.run_until([&] {
    for (const auto& e : rig.take(EventKind::Failed)) failed.push_back(e);
    return !failed.empty();
  }, 20));
  CHECK(failed.size() == 1);
  CHECK(failed[0].fail == FailReason::NoMeasuringProbe);
  rig.run(1);
  CHECK(rig.mode() == Mode::Idle);
  CHECK(rig.position().z() > 80 + kContourBall);
}

TEST_CASE("an unknown contour seeks its surface beyond a nominal start up to the clearance, else PartNotFound", "[scan]") {
  const bool streamed = GENERATE(false, true);
  INFO((streamed ? "streamed" : "request/reply"));
  const Vec3 face = cube_point(0, -50, 0), n_front = cube_dir(0, -1, 0);
  for (const double off : {1.5, 3.0}) {
    INFO("the nominal start " << off << " mm off the front face");
    const Vec3 start = face + off * n_front;
    ContourRig rig(start + 8 * n_front, streamed);
    planner::ScanContourShape c;
    c.start = pt(start);
    c.start_normal = pt(n_front);
    c.plane_normal = {0, 0, 1};
    c.direction = pt(start + cube_dir(10, 0, 0));
    c.stop = planner::StopBody::Plane;
    c.stop_point = pt(cube_point(10, -50, 0));
    c.stop_normal = pt(cube_dir(1, 0, 0));
    c.end_normal = pt(n_front);
    rig.plan(16, c, contour_settings(5, 0.5));  // clearance 2
    rig.run(16, 20);
    REQUIRE(rig.end);
    if (off < 2) {
      CHECK(rig.end->kind == EventKind::Done);
      CHECK(rig.points.size() >= 18);  // 10 mm of the front face
      CHECK(rig.worst_surface_error() <= 0.001);
    } else {
      CHECK(rig.end->kind == EventKind::Failed);
      CHECK(rig.end->fail == FailReason::PartNotFound);
      CHECK(rig.points.empty());
    }
    rig.core_rig().run(0.5);
    CHECK(rig.core_rig().mode() == Mode::Idle);
    CHECK(rig.core_rig().core().machine().deflection.norm() < 1e-9);
  }
}
