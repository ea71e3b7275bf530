// Arcs and helices: native geometry, length, centripetal limit, travel at the extreme
// points, radius mismatch, planes other than XY.
#include <catch2/catch.hpp>

#include <numbers>

#include "planner_rig.hpp"

using namespace imess::test;

namespace {

Arc arc_xy(std::uint32_t id, Pose end, double cx, double cy, bool ccw, double feed) {
  Arc a;
  a.id = id;
  a.target = end;
  a.centre = {cx, cy, 0};
  a.ccw = ccw;
  a.feed = feed;
  return a;
}

PlannedSegment only(Planner& p) {
  p.flush();
  PlannedSegment s;
  REQUIRE(p.take(s));
  return s;
}
}  // namespace

TEST_CASE("arcs: a quarter circle is native, its length is Rφ and the samples lie on it") {
  Planner p(make_machine("XYZ", -100, 100, 100, 1000));
  p.set_position(pose_of({10, 0, 0}));
  const auto r = run(p, {arc_xy(1, pose_of({0, 10, 0}), 0, 0, true, 20)});
  REQUIRE(r.segments.size() == 1);
  CHECK(r.segments[0].kind == SegmentKind::Arc);
  CHECK(r.segments[0].length == Approx(10 * std::numbers::pi / 2));
  for (const auto& t : r.ticks) {
    CHECK(std::hypot(t.pose[0], t.pose[1]) == Approx(10).epsilon(1e-12));
    CHECK(t.pose[0] >= -1e-12);  // ccw from +X to +Y stays in the first quadrant
    CHECK(t.pose[1] >= -1e-12);
  }
  CHECK(r.ticks.back().pose == pose_of({0, 10, 0}));
  check_limits(p.machine(), r);
}

TEST_CASE("arcs: clockwise goes the other way round, end == start is a full circle, turns add") {
  Planner p(make_machine("XYZ", -100, 100, 100, 1000));
  p.set_position(pose_of({10, 0, 0}));
  p.append(arc_xy(1, pose_of({0, 10, 0}), 0, 0, false, 20));
  CHECK(only(p).length == Approx(10 * 3 * std::numbers::pi / 2));
  p.set_position(pose_of({10, 0, 0}));
  p.append(arc_xy(2, pose_of({10, 0, 0}), 0, 0, true, 20));
  CHECK(only(p).length == Approx(20 * std::numbers::pi));
  p.set_position(pose_of({10, 0, 0}));
  Arc a = arc_xy(3, pose_of({0, 10, 0}), 0, 0, true, 20);
  a.turns = 2;
  p.append(a);
  CHECK(only(p).length == Approx(10 * (std::numbers::pi / 2 + 4 * std::numbers::pi)));
}

TEST_CASE("arcs: a helix has L = √((Rφ)² + h²) and moves the other axes linearly") {
  Machine m = make_machine("XYZA", -100, 100, 100, 1000);
  Planner p(m);
  p.set_position(pose_of({10, 0, 0, 0}));
  Arc a = arc_xy(1, pose_of({10, 0, 5, 90}), 0, 0, true, 20);
  const auto r = run(p, {a});
  const auto& s = r.segments.at(0);
  CHECK(s.length == Approx(std::hypot(10 * 2 * std::numbers::pi, 5)));
  for (const auto& t : r.ticks) {
    CHECK(std::hypot(t.pose[0], t.pose[1]) == Approx(10).epsilon(1e-12));
    CHECK(t.pose[3] == Approx(t.pose[2] / 5 * 90).margin(1e-9));  // A follows Z linearly
  }
  CHECK(r.ticks.back().pose == pose_of({10, 0, 5, 90}));
  check_limits(m, r);
}

TEST_CASE("arcs: the centripetal limit v ≤ √(0.87·a·R) and tangential 0.5·a") {
  Machine m = make_machine("XYZ", -100, 100, 500, 1000);
  Planner p(m);
  p.set_position(pose_of({5, 0, 0}));
  const auto r = run(p, {arc_xy(1, pose_of({5, 0, 0}), 0, 0, true, 500)});
  const auto& s = r.segments.at(0);
  CHECK(s.vc == Approx(std::sqrt(std::sqrt(0.75) * 1000 * 5)));
  CHECK(s.a == Approx(500));
  const auto rep = check_limits(m, r);
  CHECK(rep.worst_a_ratio > 0.85);  // the limit is used (centripetal alone: 0.87), not just respected
  CHECK(rep.worst_a_ratio <= 1 + 1e-6);
}

TEST_CASE("arcs: the travel check includes the arc's extreme points, not only its ends") {
  Machine m = make_machine("XYZ", 0, 100, 100, 1000);
  m.axes[0].travel_max = 80;
  Planner p(m);
  p.set_position(pose_of({50, 10, 0}));
  // ccw from the bottom of the circle around (50, 50) passes x = 90 > 80.
  const AppendResult r = p.append(arc_xy(7, pose_of({50, 90, 0}), 50, 50, true, 20));
  CHECK(r.error == PlanError::OutOfTravel);
  CHECK(r.id == 7);
  CHECK(r.axis == 0);
  CHECK(r.value == Approx(90));
  // cw passes x = 10: inside.
  CHECK(p.append(arc_xy(8, pose_of({50, 90, 0}), 50, 50, false, 20)).ok());
}

TEST_CASE("arcs: an end that is not on the circle is refused with the mismatch") {
  Planner p(make_machine("XYZ", -100, 100, 100, 1000));
  p.set_position(pose_of({10, 0, 0}));
  const AppendResult r = p.append(arc_xy(3, pose_of({0, 11, 0}), 0, 0, true, 20));
  CHECK(r.error == PlanError::ArcRadiusMismatch);
  CHECK(r.id == 3);
  CHECK(r.value == Approx(1));
  CHECK(describe(r, p.machine()).find("not on the circle") != std::string::npos);
  CHECK(p.append(arc_xy(4, pose_of({0, 10.001, 0}), 0, 0, true, 20)).ok());  // within tolerance
  p.set_position(pose_of({0, 0, 0}));
  CHECK(p.append(arc_xy(5, pose_of({0, 0, 0}), 0, 0, true, 20)).error == PlanError::ArcDegenerate);
  Arc bad = arc_xy(6, pose_of({0, 0, 0}), 1, 0, true, 20);
  bad.plane_axes = {0, 0, 2};
  CHECK(p.append(bad).error == PlanError::ArcBadPlane);
}

TEST_CASE("arcs: any plane given by a normal (YZ, and a tilted one)") {
  Machine m = make_machine("XYZ", -100, 100, 100, 1000);
  SECTION("YZ plane, normal +X") {
    Planner p(m);
    p.set_position(pose_of({0, 10, 0}));
    Arc a;
    a.id = 1;
    a.target = pose_of({0, 0, 10});
    a.normal = {1, 0, 0};
    a.feed = 20;
    const auto r = run(p, {a});
    CHECK(r.segments.at(0).length == Approx(10 * std::numbers::pi / 2));
    for (const auto& t : r.ticks) CHECK(std::hypot(t.pose[1], t.pose[2]) == Approx(10).epsilon(1e-12));
    CHECK(r.ticks.back().pose == pose_of({0, 0, 10}));
    check_limits(m, r);
  }
  SECTION("tilted plane: the samples stay on the sphere and the plane") {
    const double s3 = 1 / std::sqrt(3.0);
    Planner p(m);
    // start and end on the circle of radius √2·10 about the origin in the plane x+y+z = 0
    p.set_position(pose_of({10, -10, 0}));
    Arc a;
    a.id = 1;
    a.target = pose_of({0, 10, -10});
    a.normal = {s3, s3, s3};
    a.feed = 30;
    const auto r = run(p, {a});
    for (const auto& t : r.ticks) {
      CHECK(std::sqrt(t.pose[0] * t.pose[0] + t.pose[1] * t.pose[1] + t.pose[2] * t.pose[2]) ==
            Approx(std::sqrt(200.0)).epsilon(1e-12));
      CHECK(t.pose[0] + t.pose[1] + t.pose[2] == Approx(0).margin(1e-9));
    }
    CHECK(r.ticks.back().pose == pose_of({0, 10, -10}));
    check_limits(m, r);
  }
}
