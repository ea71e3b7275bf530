// relate() against geometry whose distances and angles are known by construction, and
// parse_fit_json()'s refusals (each names the source, the key and what is accepted).
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>
#include <nlohmann/json.hpp>

#include "feature_relation.hpp"
#include "fit_json_input.hpp"

using Eigen::Vector3d;
using imess::exchange::FitKind;
using imess::exchange::FitReport;
using imess::messcap::parse_fit_json;
using imess::messcap::relate;

namespace {

constexpr double kEps = 1e-9;

// A fitted feature as messcap fit reports it: `at` is the centre or the point on the axis or
// plane, `dir` the direction, normal or axis its kind has.
FitReport feature(FitKind kind, const Vector3d& at, const Vector3d& dir = Vector3d::Zero()) {
  FitReport f;
  f.kind = kind;
  const bool centred = kind == FitKind::Sphere || kind == FitKind::Circle;
  (centred ? f.center : f.point) = at;
  if (kind == FitKind::Plane || kind == FitKind::Circle) f.normal = dir.normalized();
  if (kind == FitKind::Line) f.direction = dir.normalized();
  if (kind == FitKind::Cylinder) f.axis = dir.normalized();
  return f;
}
FitReport sphere(const Vector3d& c) { return feature(FitKind::Sphere, c); }
FitReport plane(const Vector3d& p, const Vector3d& n) { return feature(FitKind::Plane, p, n); }
FitReport line(const Vector3d& p, const Vector3d& d) { return feature(FitKind::Line, p, d); }
FitReport cylinder(const Vector3d& p, const Vector3d& a) { return feature(FitKind::Cylinder, p, a); }
FitReport circle(const Vector3d& c, const Vector3d& n) { return feature(FitKind::Circle, c, n); }

Vector3d rotated_about_x(const Vector3d& v, double deg) {
  return Eigen::AngleAxisd(deg * std::numbers::pi / 180.0, Vector3d::UnitX()) * v;
}

bool near(const Vector3d& a, const Vector3d& b, double eps = kEps) { return (a - b).norm() <= eps; }

}  // namespace

TEST_CASE("relate: centre to centre is the distance of the centres, a sphere has no angle") {
  auto r = relate(sphere({1, 2, 3}), sphere({4, 6, 15}));
  REQUIRE(r.distance);
  CHECK(*r.distance == Approx(13.0).margin(kEps));  // 3-4-12
  CHECK(r.distance_rule == "point-point");
  CHECK(near(*r.from, {1, 2, 3}));
  CHECK(near(*r.to, {4, 6, 15}));
  CHECK_FALSE(r.angle_deg);
  REQUIRE(r.notes.size() == 1);
  CHECK_THAT(r.notes[0], Catch::Contains("sphere has no direction"));
}

TEST_CASE("relate: point to plane is the perpendicular, from the centre to its foot") {
  // The plane through (5, 5, 2) tilted 30 degrees about x; a centre 7 mm off it along the normal.
  const Vector3d n = rotated_about_x({0, 0, 1}, 30);
  const Vector3d foot = Vector3d(5, 5, 2) + rotated_about_x({0, 3, 0}, 30) + Vector3d(4, 0, 0);
  const Vector3d centre = foot + 7 * n;
  auto r = relate(sphere(centre), plane({5, 5, 2}, -n));  // the normal's sign does not matter
  REQUIRE(r.distance);
  CHECK(*r.distance == Approx(7.0).margin(kEps));
  CHECK(r.distance_rule == "point-plane");
  CHECK(near(*r.from, centre));
  CHECK(near(*r.to, foot));
  // Plane first: the same distance, from the foot (on A) to the centre (on B).
  auto back = relate(plane({5, 5, 2}, n), sphere(centre));
  CHECK(back.distance_rule == "plane-point");
  CHECK(*back.distance == Approx(7.0).margin(kEps));
  CHECK(near(*back.from, foot));
  CHECK(near(*back.to, centre));
}

TEST_CASE("relate: a circle is its centre for distances and its axis for angles") {
  auto r = relate(circle({10, 20, 35}, {0, 0, 1}), plane({0, 0, 5}, {0, 0, 1}));
  CHECK(*r.distance == Approx(30.0).margin(kEps));
  CHECK(r.distance_rule == "point-plane");
  CHECK(*r.angle_deg == Approx(90.0).margin(1e-9));  // a bore square to its face
  CHECK(r.angle_rule == "axis-plane");
  CHECK(r.notes.empty());
  // A circle whose axis leans 30 degrees from a cylinder's: 30 degrees.
  auto tilted = relate(circle({0, 0, 0}, rotated_about_x({0, 0, 1}, 30)), cylinder({0, 50, 0}, {0, 0, 1}));
  CHECK(*tilted.angle_deg == Approx(30.0).margin(1e-9));
  CHECK(tilted.angle_rule == "axis-axis");
  CHECK(tilted.distance_rule == "point-axis");
  CHECK(*tilted.distance == Approx(50.0).margin(kEps));
}

TEST_CASE("relate: parallel planes are B's point to plane A, whatever the normals' signs") {
  auto r = relate(plane({0, 0, 0}, {0, 0, 1}), plane({30, -20, 7.5}, {0, 0, -1}));
  REQUIRE(r.distance);
  CHECK(*r.distance == Approx(7.5).margin(kEps));
  CHECK(r.distance_rule == "plane-plane parallel");
  CHECK(near(*r.from, {30, -20, 0}));
  CHECK(near(*r.to, {30, -20, 7.5}));
  CHECK(*r.angle_deg == Approx(0.0).margin(1e-6));
  CHECK(r.angle_rule == "plane-plane");

  // Half a degree off parallel still has a distance: B's point to A (A is the reference).
  auto tilted = relate(plane({0, 0, 0}, {0, 0, 1}), plane({0, 0, 4}, rotated_about_x({0, 0, 1}, 0.5)));
  CHECK(*tilted.distance == Approx(4.0).margin(kEps));
  CHECK(*tilted.angle_deg == Approx(0.5).margin(1e-9));
}

TEST_CASE("relate: planes at an angle have no distance, only the angle, and the note says why") {
  auto r = relate(plane({0, 0, 0}, {0, 0, 1}), plane({0, 0, 10}, rotated_about_x({0, 0, 1}, 60)));
  CHECK_FALSE(r.distance);
  CHECK_FALSE(r.from);
  CHECK(*r.angle_deg == Approx(60.0).margin(1e-9));
  REQUIRE(r.notes.size() == 1);
  CHECK_THAT(r.notes[0], Catch::Contains("not parallel (60 deg > 1 deg)"));
  // 120 degrees between the normals is the same pair of planes: 60.
  auto obtuse = relate(plane({0, 0, 0}, {0, 0, 1}), plane({0, 0, 10}, rotated_about_x({0, 0, 1}, 120)));
  CHECK(*obtuse.angle_deg == Approx(60.0).margin(1e-9));
}

TEST_CASE("relate: skew axes meet at their common perpendicular") {
  // Built from the answer: feet fa, fb = fa + 4 n with n square to both directions.
  const Vector3d ua = Vector3d(1, 1, 0).normalized(), ub = Vector3d(0, 1, 2).normalized();
  const Vector3d n = ua.cross(ub).normalized();
  const Vector3d fa = Vector3d(1, 2, 3) + 2 * ua, fb = fa + 4 * n;
  auto r = relate(line({1, 2, 3}, ua), cylinder(fb - 3 * ub, -ub));
  REQUIRE(r.distance);
  CHECK(*r.distance == Approx(4.0).margin(kEps));
  CHECK(r.distance_rule == "axis-axis skew");
  CHECK(near(*r.from, fa, 1e-9));
  CHECK(near(*r.to, fb, 1e-9));
  const double expected_angle = std::acos(std::abs(ua.dot(ub))) * 180.0 / std::numbers::pi;
  CHECK(*r.angle_deg == Approx(expected_angle).margin(1e-9));
  // Intersecting axes: distance 0 at the crossing.
  auto crossing = relate(line({0, 0, 0}, {1, 0, 0}), line({5, -3, 0}, {0, 1, 0}));
  CHECK(*crossing.distance == Approx(0.0).margin(kEps));
  CHECK(near(*crossing.from, {5, 0, 0}));
  CHECK(*crossing.angle_deg == Approx(90.0).margin(1e-9));
}

TEST_CASE("relate: parallel axes are B's point to axis A") {
  auto r = relate(cylinder({0, 0, 0}, {0, 0, 1}), cylinder({30, 40, 5}, {0, 0, -1}));
  REQUIRE(r.distance);
  CHECK(*r.distance == Approx(50.0).margin(kEps));
  CHECK(r.distance_rule == "axis-axis parallel");
  CHECK(near(*r.from, {0, 0, 5}));
  CHECK(near(*r.to, {30, 40, 5}));
  CHECK(*r.angle_deg == Approx(0.0).margin(1e-6));
}

TEST_CASE("relate: an axis and a plane: a distance only when the axis lies along the plane") {
  auto along = relate(line({4, 5, 3}, {1, 1, 0}), plane({0, 0, 0}, {0, 0, 1}));
  REQUIRE(along.distance);
  CHECK(*along.distance == Approx(3.0).margin(kEps));
  CHECK(along.distance_rule == "axis-plane parallel");
  CHECK(near(*along.from, {4, 5, 3}));
  CHECK(near(*along.to, {4, 5, 0}));
  CHECK(*along.angle_deg == Approx(0.0).margin(1e-6));
  CHECK(along.angle_rule == "axis-plane");

  auto square = relate(plane({0, 0, 0}, {0, 0, 1}), cylinder({1, 1, 1}, {0, 0, 1}));
  CHECK_FALSE(square.distance);
  CHECK(*square.angle_deg == Approx(90.0).margin(1e-9));
  CHECK(square.angle_rule == "plane-axis");
  auto leaning = relate(cylinder({1, 1, 1}, rotated_about_x({0, 1, 0}, 25)), plane({0, 0, 0}, {0, 0, 1}));
  CHECK(*leaning.angle_deg == Approx(25.0).margin(1e-9));
}

TEST_CASE("relate: the JSON names the rules and leaves out what is undefined") {
  auto j = nlohmann::json::parse(imess::messcap::to_json(relate(sphere({0, 0, 0}), sphere({0, 0, 2}))));
  CHECK(j["a"] == "sphere");
  CHECK(j["distance"].get<double>() == Approx(2.0));
  CHECK(j["distance_rule"] == "point-point");
  CHECK(j["to"][2].get<double>() == Approx(2.0));
  CHECK_FALSE(j.contains("angle_deg"));
  CHECK(j["notes"].size() == 1);
}

TEST_CASE("parse_fit_json: reads what messcap fit prints, refuses what it cannot use") {
  auto f = parse_fit_json(R"({"type":"cylinder","point":[1,2,3],"axis":[0,0,2],"diameter":20,"rms":0.1,"n":9})", "a.json");
  CHECK(f.kind == FitKind::Cylinder);
  CHECK(near(*f.point, {1, 2, 3}));
  CHECK(near(*f.axis, {0, 0, 1}));  // made unit
  CHECK(*f.diameter == 20);

  using Catch::Contains;
  CHECK_THROWS_WITH(parse_fit_json("{\"type\":\"plane\",\"point\":[0,0,0]}", "b.json"),
                    Contains("b.json: a fitted plane needs 'normal'"));
  CHECK_THROWS_WITH(parse_fit_json(R"({"type":"torus"})", "c.json"),
                    Contains("c.json: unknown feature kind 'torus'; accepted: line, line2d"));
  CHECK_THROWS_WITH(parse_fit_json(R"({"center":[0,0,0]})", "d.json"), Contains("no \"type\""));
  CHECK_THROWS_WITH(parse_fit_json(R"({"type":"sphere","center":[0,0]})", "e.json"),
                    Contains("'center' must be three numbers [x, y, z], not [0,0]"));
  CHECK_THROWS_WITH(parse_fit_json(R"({"type":"line","point":[0,0,0],"direction":[0,0,0]})", "f.json"),
                    Contains("'direction' must be a direction, not the zero vector"));
  CHECK_THROWS_WITH(parse_fit_json("plane 0 0 0", "g.json"), Contains("g.json: not valid JSON"));
  CHECK_THROWS_WITH(parse_fit_json("[1,2]", "h.json"), Contains("expected one JSON object"));
}

// Issue 26, 7: a number beyond a double escaped as nlohmann's out_of_range.
TEST_CASE("parse_fit_json names the key of a number beyond a double") {
  CHECK_THROWS_AS(parse_fit_json(R"({"type":"sphere","center":[0,1e400,0]})", "s.json"), imess::messcap::FitJsonError);
  CHECK_THROWS_WITH(parse_fit_json(R"({"type":"sphere","center":[0,1e400,0]})", "s.json"),
                    Catch::StartsWith("s.json: key 'center[1]' holds a number too large for a double ('1e400')"));
}
