// Inspection evaluation against synthetic hits whose truth is known: a box placed turned and
// tilted on the machine, with faces off nominal by known amounts, a bore with known form and
// position probed obliquely, a tilted cylinder; a sphere and a cone placed without alignment.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>
#include <cmath>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/inspection.hpp"
#include "imess/metrology/inspection_plan.hpp"
#include "inspection_synthetic.hpp"

using namespace imess::metrology;
using imess::test::deg2rad;
using imess::test::SyntheticProbe;
using Eigen::Vector3d;

namespace {

const char* kBoxPlan = R"({
  "part": "box",
  "placement": {"origin": [400, 300, 0]},
  "alignment": {"primary": "bottom", "secondary": "front", "tertiary": "left"},
  "features": [
    {"name": "bottom", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1]},
    {"name": "front", "type": "plane", "point": [0, 0, 0], "normal": [0, -1, 0]},
    {"name": "left", "type": "plane", "point": [0, 0, 0], "normal": [-1, 0, 0]},
    {"name": "right", "type": "plane", "point": [120, 0, 0], "normal": [1, 0, 0]},
    {"name": "back", "type": "plane", "point": [0, 100, 0], "normal": [0, 1, 0]},
    {"name": "top", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1]},
    {"name": "bore", "type": "circle", "center": [60, 50, 40], "normal": [0, 0, 1], "diameter": 30, "inner": true},
    {"name": "bore_axis", "type": "cylinder", "point": [60, 50, 40], "axis": [0, 0, 1], "diameter": 30, "inner": true}
  ],
  "characteristics": [
    {"name": "length", "type": "distance", "features": ["left", "right"], "tolerance": 0.05},
    {"name": "width", "type": "distance", "features": ["front", "back"], "tolerance": 0.05},
    {"name": "height", "type": "distance", "features": ["bottom", "top"], "tolerance": 0.05},
    {"name": "bore_d", "type": "size", "feature": "bore", "tolerance": [-0.005, 0.005]},
    {"name": "bore_r", "type": "size", "feature": "bore", "radius": true, "tolerance": 0.01},
    {"name": "bore_pos", "type": "position", "feature": "bore", "tolerance": 0.05},
    {"name": "bore_round", "type": "roundness", "feature": "bore", "tolerance": 0.005},
    {"name": "right_flat", "type": "flatness", "feature": "right", "tolerance": 0.01},
    {"name": "back_perp", "type": "perpendicularity", "feature": "back", "datum": "bottom", "tolerance": 0.02},
    {"name": "top_par", "type": "parallelism", "feature": "top", "datum": "bottom", "tolerance": 0.02},
    {"name": "axis_perp", "type": "perpendicularity", "feature": "bore_axis", "datum": "bottom", "tolerance": 0.1},
    {"name": "axis_pos", "type": "position", "feature": "bore_axis", "tolerance": 0.1},
    {"name": "back_angle", "type": "angle", "features": ["back", "bottom"], "tolerance": 0.01},
    {"name": "axis_cyl", "type": "cylindricity", "feature": "bore_axis", "tolerance": 0.01}
  ]
})";

// The box as made: right face 0.03 long with a 4 um bump in its middle, back face leaning by
// back_tilt, top tilted by top_tilt, the bore 0.01 oversize, off centre, with a 3 um lobing,
// and its axis tilted by axis_tilt. Placed turned 0.4 deg about z and tilted 0.1 deg about x.
struct TrueBox {
  double back_tilt = deg2rad(0.02), top_tilt = deg2rad(0.01), axis_tilt = deg2rad(0.05);
  double bump = 0.004, lobe = 0.003, long_by = 0.03;
  Vector3d bore_centre{60.02, 49.99, 40};
  double bore_d = 30.01;
  SyntheticProbe probe;

  TrueBox() {
    probe.truth = Frame((Eigen::AngleAxisd(deg2rad(0.4), Vector3d::UnitZ()) *
                         Eigen::AngleAxisd(deg2rad(0.1), Vector3d::UnitX())).toRotationMatrix(),
                        Vector3d(400.3, 299.8, 0.2));
    for (Vector3d p : {Vector3d(-20, -20, 0), Vector3d(140, -20, 0), Vector3d(140, 120, 0), Vector3d(-20, 120, 0)})
      probe.touch("bottom", p, Vector3d::UnitZ());
    for (double x : {20.0, 100.0})
      for (double z : {15.0, 65.0}) probe.touch("front", {x, 0, z}, -Vector3d::UnitY());
    for (double y : {20.0, 80.0})
      for (double z : {15.0, 65.0}) probe.touch("left", {0, y, z}, -Vector3d::UnitX());
    for (double y : {20.0, 80.0})
      for (double z : {15.0, 65.0}) probe.touch("right", {120 + long_by, y, z}, Vector3d::UnitX());
    probe.touch("right", {120 + long_by + bump, 50, 40}, Vector3d::UnitX());
    for (double x : {20.0, 100.0})
      for (double z : {15.0, 65.0}) probe.touch("back", back_point(x, z), back_normal());
    for (double x : {20.0, 100.0})
      for (double y : {30.0, 85.0}) probe.touch("top", top_point(x, y), top_normal());
    for (int k = 0; k < 8; ++k) {
      const double a = deg2rad(10 + 45 * k);
      const Vector3d radial(std::cos(a), std::sin(a), 0);
      const double e = k % 2 ? -lobe : lobe;
      const Vector3d s = bore_centre + (0.5 * bore_d + e) * radial;
      // 25 degrees off the surface normal: compensation along the approach would be wrong.
      const Vector3d approach = Eigen::AngleAxisd(deg2rad(25), Vector3d::UnitZ()) * radial;
      probe.touch("bore", s, -radial, approach);
    }
    for (double h : {-25.0, 25.0})
      for (int k = 0; k < 6; ++k) {
        const double a = deg2rad(60 * k + (h > 0 ? 30 : 0));
        const Vector3d u = Vector3d::UnitX(), v = axis().cross(u).normalized();
        const Vector3d radial = std::cos(a) * u + std::sin(a) * v;
        probe.touch("bore_axis", bore_centre + h * axis() + 0.5 * bore_d * radial, -radial);
      }
  }
  Vector3d back_normal() const { return {0, std::cos(back_tilt), std::sin(back_tilt)}; }
  Vector3d back_point(double x, double z) const {
    return Vector3d(60, 100, 40) + (x - 60) * Vector3d::UnitX() + (z - 40) * Vector3d(0, -std::sin(back_tilt), std::cos(back_tilt));
  }
  Vector3d top_normal() const { return {-std::sin(top_tilt), 0, std::cos(top_tilt)}; }
  Vector3d top_point(double x, double y) const {
    return Vector3d(60, 50, 80) + (x - 60) * Vector3d(std::cos(top_tilt), 0, std::sin(top_tilt)) + (y - 50) * Vector3d::UnitY();
  }
  Vector3d axis() const { return {0, -std::sin(axis_tilt), std::cos(axis_tilt)}; }
};

const CharacteristicResult& find(const InspectionResult& r, const std::string& name) {
  for (const auto& c : r.characteristics)
    if (c.spec.name == name) return c;
  FAIL("no characteristic " << name);
  throw;
}

}  // namespace

TEST_CASE("inspection of a box: the alignment takes up the placement, characteristics show the part's truth", "[inspection]") {
  const InspectionPlan plan = parse_inspection_plan(kBoxPlan, "box.plan.json");
  const TrueBox box;
  const InspectionResult r = evaluate_inspection(plan, box.probe.hits);

  // The datums are true planes at x = 0, y = 0, z = 0 of the part: the frame is the truth.
  REQUIRE(r.alignment.measured);
  CHECK((r.alignment.part_to_machine.rotation() - box.probe.truth.rotation()).cwiseAbs().maxCoeff() < 1e-9);
  CHECK((r.alignment.part_to_machine.translation() - box.probe.truth.translation()).norm() < 1e-8);
  const Eigen::AngleAxisd turn(box.probe.truth.rotation());
  CHECK((r.alignment.rotation_deg - turn.angle() * 180 / M_PI * turn.axis()).norm() < 1e-9);
  CHECK(r.alignment.rotation_deg.z() == Approx(0.4).margin(1e-3));

  for (const auto& f : r.features) {
    INFO(f.name << ": " << f.error);
    CHECK(f.actual.has_value());
    CHECK(f.compensated);
  }
  // Opposite faces: the mean of both ways across (docs/metrology.md).
  CHECK(find(r, "length").actual == Approx(120 + box.long_by + box.bump / 5).margin(1e-9));
  CHECK(find(r, "length").nominal == Approx(120).margin(1e-12));
  CHECK(find(r, "width").actual == Approx(0.5 * (100 + 100 * std::cos(box.back_tilt))).margin(1e-9));
  CHECK(find(r, "height").actual == Approx(0.5 * (80 + 80 * std::cos(box.top_tilt))).margin(1e-9));
  // The oblique bore hits are compensated along the fitted normal: the diameter is exact, and
  // the points as messd compensated them (along the approach) are not on the true circle.
  CHECK(find(r, "bore_d").actual == Approx(box.bore_d).margin(1e-9));
  CHECK(find(r, "bore_d").deviation == Approx(0.01).margin(1e-9));
  CHECK_FALSE(find(r, "bore_d").in_tolerance);
  CHECK(find(r, "bore_r").actual == Approx(box.bore_d / 2).margin(1e-9));
  CHECK(find(r, "bore_r").in_tolerance);
  const Vector3d hit_part = box.probe.truth.point_from_parent(box.probe.hits.at(25).point);
  REQUIRE(box.probe.hits.at(25).feature == "bore");
  const double naive = (hit_part - box.bore_centre).head<2>().norm() - 0.5 * box.bore_d - box.lobe;
  CHECK(std::abs(naive) > 0.1 * 2.0 * (1 - std::cos(deg2rad(25))));
  CHECK(find(r, "bore_pos").actual == Approx(2 * Eigen::Vector2d(0.02, -0.01).norm()).margin(1e-9));
  CHECK((*find(r, "bore_pos").actual_location - box.bore_centre).norm() < 1e-9);
  CHECK(find(r, "bore_round").actual == Approx(2 * box.lobe).margin(1e-9));
  CHECK_FALSE(find(r, "bore_round").in_tolerance);
  CHECK(find(r, "right_flat").actual == Approx(box.bump).margin(1e-9));
  // Orientation zones over the probed extent: 50 mm up the back face, 80 mm across the top,
  // 50 mm along the bore's axis.
  CHECK(find(r, "back_perp").actual == Approx(50 * std::sin(box.back_tilt)).margin(1e-9));
  CHECK(find(r, "top_par").actual == Approx(80 * std::sin(box.top_tilt)).margin(1e-9));
  CHECK(find(r, "axis_perp").actual == Approx(50 * std::sin(box.axis_tilt)).margin(1e-9));
  const double end_off = std::max(Eigen::Vector2d(0.02, -0.01 - 25 * std::sin(box.axis_tilt)).norm(),
                                  Eigen::Vector2d(0.02, -0.01 + 25 * std::sin(box.axis_tilt)).norm());
  CHECK(find(r, "axis_pos").actual == Approx(2 * end_off).margin(1e-8));
  CHECK(find(r, "back_angle").nominal == Approx(90).margin(1e-12));
  CHECK(find(r, "back_angle").deviation == Approx(-0.02).margin(1e-9));
  CHECK(find(r, "axis_cyl").actual < 1e-9);
  CHECK_FALSE(find(r, "back_angle").in_tolerance);
  CHECK(r.out_of_tolerance() == 3);  // bore_d, bore_round, back_angle
  CHECK(r.not_evaluated() == 0);

  // Per point: the right face's points stand 0.03 (the middle one 0.034) out of the material.
  int right = 0;
  for (const auto& p : r.points) {
    if (p.feature != "right") continue;
    ++right;
    const double want = p.part.y() == Approx(50).margin(1e-6) ? box.long_by + box.bump : box.long_by;
    CHECK(p.deviation == Approx(want).margin(1e-9));
    REQUIRE(p.form);
  }
  CHECK(right == 5);
  // The first bore point: from the nominal circle it stands as far as the true surface point
  // does (into the material = negative for a bore), from the fitted one by its lobe.
  const auto& bore_point = r.points.at(25);
  CHECK(bore_point.feature == "bore");
  const Vector3d true_surface = box.bore_centre + (0.5 * box.bore_d + box.lobe) * Vector3d(std::cos(deg2rad(10)), std::sin(deg2rad(10)), 0);
  CHECK((bore_point.part - true_surface).norm() < 1e-9);
  CHECK(bore_point.deviation == Approx(-((true_surface - Vector3d(60, 50, 40)).head<2>().norm() - 15)).margin(1e-9));
  CHECK(*bore_point.form == Approx(-box.lobe).margin(1e-9));
}

TEST_CASE("inspection without approach directions: plain fits of the points as given", "[inspection]") {
  const InspectionPlan plan = parse_inspection_plan(kBoxPlan, "box.plan.json");
  TrueBox box;
  // The same part without probe data: the reported points (on the surface for hits along the
  // normal) as plain points.
  std::vector<MeasuredPoint> plain;
  for (const auto& h : box.probe.hits) {
    if (h.feature == "bore") continue;  // oblique hits are not surface points
    MeasuredPoint p = h;
    p.approach.reset();
    p.radius = 0;
    plain.push_back(p);
  }
  const InspectionResult r = evaluate_inspection(plan, plain);
  CHECK_FALSE(r.features.at(0).compensated);
  CHECK(find(r, "length").actual == Approx(120 + box.long_by + box.bump / 5).margin(1e-9));
  CHECK(find(r, "right_flat").actual == Approx(box.bump).margin(1e-9));
  // No bore points: its characteristics are not evaluated, and say why.
  CHECK_FALSE(find(r, "bore_d").evaluated());
  CHECK_THAT(find(r, "bore_d").error, Catch::Contains("bore") && Catch::Contains("no points"));
  CHECK(r.not_evaluated() == 4);
}

TEST_CASE("inspection errors: unknown features, mixed points, alignment without points", "[inspection]") {
  const InspectionPlan plan = parse_inspection_plan(kBoxPlan, "box.plan.json");
  TrueBox box;
  auto hits = box.probe.hits;
  hits.push_back({"lid", {0, 0, 0}, std::nullopt, 0});
  CHECK_THROWS_WITH(evaluate_inspection(plan, hits), Catch::Contains("'lid'") && Catch::Contains("bottom, front"));

  hits = box.probe.hits;
  hits.push_back({"right", {520, 350, 40}, std::nullopt, 0});
  const auto r = evaluate_inspection(plan, hits);
  CHECK_THAT(r.features.at(3).error, Catch::Contains("right") && Catch::Contains("all hits"));
  CHECK_FALSE(find(r, "length").evaluated());

  std::vector<MeasuredPoint> no_front;
  for (const auto& h : box.probe.hits)
    if (h.feature != "front") no_front.push_back(h);
  CHECK_THROWS_AS(evaluate_inspection(plan, no_front), InspectionError);
  CHECK_THROWS_WITH(evaluate_inspection(plan, no_front), Catch::Contains("alignment") && Catch::Contains("front"));
}

TEST_CASE("inspection by placement: a sphere and a cone on a part turned 90 degrees", "[inspection]") {
  const InspectionPlan plan = parse_inspection_plan(R"({
    "part": "knob",
    "placement": {"origin": [100, 200, 0], "x_axis": [0, 1, 0]},
    "features": [
      {"name": "ball", "type": "sphere", "center": [10, 0, 5], "diameter": 20},
      {"name": "taper", "type": "cone", "point": [-30, 0, 10], "axis": [0, 0, 1], "diameter": 20, "apex_angle_deg": 60}
    ],
    "characteristics": [
      {"name": "ball_d", "type": "size", "feature": "ball", "tolerance": 0.01},
      {"name": "ball_pos", "type": "position", "feature": "ball", "tolerance": 0.01},
      {"name": "taper_d", "type": "size", "feature": "taper", "tolerance": 0.01}
    ]
  })", "knob");
  SyntheticProbe probe;
  probe.truth = plan.placement;
  const Vector3d ball(10.003, -0.004, 5);
  for (int k = 0; k < 8; ++k) {
    const double a = deg2rad(45 * k), el = deg2rad(k % 2 ? 20 : 60);
    const Vector3d n(std::cos(el) * std::cos(a), std::cos(el) * std::sin(a), std::sin(el));
    probe.touch("ball", ball + 10.006 * n, n);
  }
  // The cone as made: 0.02 larger across at the nominal axis point, same angle.
  const double phi = deg2rad(30), r0 = 10.01;
  for (double h : {-5.0, 5.0})
    for (int k = 0; k < 6; ++k) {
      const double a = deg2rad(60 * k + (h > 0 ? 30 : 0));
      const Vector3d radial(std::cos(a), std::sin(a), 0);
      const Vector3d n = std::cos(phi) * radial - std::sin(phi) * Vector3d::UnitZ();
      probe.touch("taper", Vector3d(-30, 0, 10 + h) + (r0 + h * std::tan(phi)) * radial, n);
    }
  const auto r = evaluate_inspection(plan, probe.hits);
  CHECK_FALSE(r.alignment.measured);
  CHECK(find(r, "ball_d").actual == Approx(20.012).margin(1e-9));
  CHECK(find(r, "ball_pos").actual == Approx(2 * Eigen::Vector2d(0.003, -0.004).norm()).margin(1e-9));
  CHECK(find(r, "taper_d").actual == Approx(2 * r0).margin(1e-8));
  CHECK(r.features.at(1).actual->apex_angle_deg == Approx(60).margin(1e-8));
  // Machine coordinates of the ball's points are the placement's: part x runs along machine y.
  CHECK(r.points.at(0).measured.point.y() > 200);
}
