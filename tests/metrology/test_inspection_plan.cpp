// The inspection plan reader and the labelled point reader: what they accept, and the message
// a bad file gets (file: key path: what was expected).
#include <catch2/catch.hpp>

#include <fstream>
#include <sstream>

#include "imess/metrology/inspection_plan.hpp"
#include "imess/metrology/inspection_points.hpp"

using namespace imess::metrology;

namespace {

std::string plan_with(const std::string& features, const std::string& characteristics, const std::string& extra = "") {
  return R"({"part": "p", )" + extra + R"("features": [)" + features + R"(], "characteristics": [)" + characteristics + "]}";
}
const std::string kPlane = R"({"name": "a", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 2]})";
const std::string kCircle = R"({"name": "c", "type": "circle", "center": [1, 2, 3], "normal": [0, 0, 1], "diameter": 10})";

std::string error_of(const std::string& text) {
  try {
    parse_inspection_plan(text, "t.json");
  } catch (const InspectionPlanError& e) {
    return e.what();
  }
  return "(accepted)";
}

}  // namespace

TEST_CASE("inspection plan: features, probes, placement and characteristics are read", "[inspection][plan]") {
  const auto plan = parse_inspection_plan(
      plan_with(kPlane + R"(, {"name": "c", "type": "circle", "center": [1, 2, 3], "normal": [0, 0, 1], "diameter": 10,
                 "inner": true, "moves": "lift", "probe": [[6, 2, 3, 1, 0, 0], {"point": [1, 7, 3], "approach": [0, 3, 0]}]})",
                R"({"name": "d", "type": "size", "feature": "c", "tolerance": [-0.01, 0.02]},
                   {"name": "f", "type": "flatness", "feature": "a", "tolerance": 0.005},
                   {"name": "g", "type": "distance", "features": ["a", "c"], "nominal": 3.5, "tolerance": 0.1})",
                R"("placement": {"origin": [10, 20, 30], "x_axis": [0, 1, 0]}, "probing": {"clearance": 4, "safe_z": 60, "tip_radius": 1.5},)"),
      "t.json");
  REQUIRE(plan.features.size() == 2);
  CHECK(plan.features[0].nominal.direction == Eigen::Vector3d::UnitZ());  // normalised
  const auto& c = plan.feature("c");
  CHECK(c.nominal.kind == FeatureKind::Circle);
  CHECK(c.nominal.inner);
  CHECK(c.lift_between);
  REQUIRE(c.probes.size() == 2);
  CHECK(c.probes[1].approach == Eigen::Vector3d::UnitY());
  CHECK(plan.placement.point_to_parent(Eigen::Vector3d(1, 0, 0)).isApprox(Eigen::Vector3d(10, 21, 30)));
  CHECK(plan.probing.clearance == 4);
  CHECK(*plan.probing.tip_radius == 1.5);
  REQUIRE(plan.characteristics.size() == 3);
  CHECK(plan.characteristics[0].lower == -0.01);
  CHECK(plan.characteristics[0].upper == 0.02);
  CHECK(plan.characteristics[1].lower == 0);
  CHECK(plan.characteristics[1].upper == 0.005);
  CHECK(*plan.characteristics[2].nominal == 3.5);
  CHECK(plan.characteristics[2].lower == -0.1);
}

TEST_CASE("inspection plan: bad plans name the key and what was expected", "[inspection][plan]") {
  CHECK(error_of("{") .find("t.json: not valid JSON at line 1, column 2") != std::string::npos);
  CHECK(error_of(R"({"features": []})") == "t.json: part: missing (expected the part's name)");
  CHECK(error_of(plan_with("", "")) == "t.json: features: expected a non-empty array of features");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "torus"})", "")) ==
        "t.json: features[0].type: 'torus' is not a feature type; expected one of point, line, plane, circle, sphere, cylinder, cone");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "plane", "point": [0, 0], "normal": [0, 0, 1]})", "")) ==
        "t.json: features[0].point: expected [x, y, z] (3 numbers)");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]})", "")) ==
        "t.json: features[0].normal: expected a direction [i, j, k] of non-zero length");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "circle", "center": [0, 0, 0], "normal": [0, 0, 1], "diameter": -1})", "")) ==
        "t.json: features[0].diameter: expected a number above 0");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "diameter": 3})", "")) ==
        "t.json: features[0].diameter: unknown key; accepted here: name, type, point, normal, probe, scan, moves");
  CHECK(error_of(plan_with(R"({"name": "a", "type": "plane", "point": [0, 0, 0], "normal": [0, 0, 1], "probe": [[1, 2, 3]]})", "")) ==
        "t.json: features[0].probe[0]: expected [x, y, z, i, j, k] (surface point and approach) or {\"point\", \"approach\"}");
  CHECK(error_of(plan_with(kPlane + "," + kPlane, "")) == "t.json: features[1].name: 'a' is used twice");
  CHECK(error_of(plan_with(kPlane, R"({"name": "s", "type": "size", "feature": "a", "tolerance": 0.1})")) ==
        "t.json: characteristics[0].feature: size applies to a circle, sphere, cylinder or cone, and 'a' is a plane");
  CHECK(error_of(plan_with(kCircle, R"({"name": "s", "type": "sphericity", "feature": "c", "tolerance": 0.1})")) ==
        "t.json: characteristics[0].feature: sphericity applies to a sphere, and 'c' is a circle");
  CHECK(error_of(plan_with(kPlane, R"({"name": "s", "type": "flatness", "feature": "b", "tolerance": 0.1})")) ==
        "t.json: characteristics[0].feature: no feature named 'b' in the plan");
  CHECK(error_of(plan_with(kPlane, R"({"name": "s", "type": "flatness", "feature": "a", "tolerance": [0, 1]})")) ==
        "t.json: characteristics[0].tolerance: a flatness tolerance is one zone width, a number above 0");
  CHECK(error_of(plan_with(kCircle, R"({"name": "s", "type": "size", "feature": "c", "tolerance": [0.1, -0.1]})")) ==
        "t.json: characteristics[0].tolerance: expected lower < upper");
  CHECK(error_of(plan_with(kCircle, R"({"name": "s", "type": "size", "feature": "c"})")) ==
        "t.json: characteristics[0].tolerance: missing (expected t (for ±t) or [lower, upper])");
  CHECK(error_of(plan_with(kPlane + "," + kCircle, R"({"name": "s", "type": "parallelism", "feature": "a", "tolerance": 0.1})")) ==
        "t.json: characteristics[0].datum: missing (expected the datum feature's name)");
  CHECK(error_of(plan_with(kPlane + "," + kCircle, R"({"name": "s", "type": "distance", "features": ["a"], "tolerance": 0.1})")) ==
        "t.json: characteristics[0].features: expected [\"first\", \"second\"] (two feature names)");
  CHECK(error_of(plan_with(kPlane + "," + kCircle, "", R"("alignment": {"primary": "c", "secondary": "a", "tertiary": "a"},)")) ==
        "t.json: alignment.primary: expected the name of a plane feature");
  CHECK(error_of(plan_with(kPlane, "", R"("placement": {"origin": [0, 0, 0], "x_axis": [1, 0, 0], "z_axis": [1, 1, 0]},)"))
            .find("t.json: placement: x_axis and z_axis must be perpendicular") == 0);
  CHECK(error_of(plan_with(kPlane, "", R"("probing": {"tip_radius": 60},)")) ==
        "t.json: probing.tip_radius: expected a radius of 0 … 50 mm");
}

TEST_CASE("the shipped cube plan is a valid plan", "[inspection][plan]") {
  std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/examples/cube-1996.plan.json");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const auto plan = parse_inspection_plan(text.str(), "cube-1996.plan.json");
  CHECK(plan.alignment.has_value());
  for (const auto& f : plan.features) {
    INFO(f.name);
    CHECK_FALSE(f.probes.empty());
  }
}

TEST_CASE("measured points: text lines and messcap's JSON, with errors by line or key", "[inspection][points]") {
  const auto pts = parse_measured_points("# a comment\nbore 1 2 3 0 0 -2 2\n\ntop 4 5 6   # plain\nforced 7 8 9 0 0 0 0\n", "p.txt");
  REQUIRE(pts.size() == 3);
  CHECK(pts[0].feature == "bore");
  CHECK(*pts[0].approach == Eigen::Vector3d(0, 0, -1));
  CHECK(pts[0].radius == 2);
  CHECK_FALSE(pts[1].approach);
  CHECK_FALSE(pts[2].approach);  // messd's ForcePt: no approach, no radius
  CHECK_THROWS_WITH(parse_measured_points("a 1 2\n", "p.txt"), Catch::StartsWith("p.txt:1: expected FEATURE x y z"));
  CHECK_THROWS_WITH(parse_measured_points("\na 1 2 x\n", "p.txt"), "p.txt:2: 'x' (word 4) is not a finite number");
  CHECK_THROWS_WITH(parse_measured_points("a 1 2 3 0 0 0 2\n", "p.txt"),
                    "p.txt:1: a point with tip radius 2.000000 needs an approach direction i j k");

  const auto js = parse_measured_points(
      R"({"points": [{"feature": "top", "machine": [1, 2, 3], "approach": [0, 0, -1], "radius": 2, "xyz": [0, 0, 0]},
                     {"feature": "left", "machine": [4, 5, 6]}]})", "r.json");
  REQUIRE(js.size() == 2);
  CHECK(js[0].radius == 2);
  CHECK_FALSE(js[1].approach);
  CHECK_THROWS_WITH(parse_measured_points(R"({"points": [{"feature": "top", "xyz": [1, 2, 3]}]})", "r.json"),
                    "r.json: points[0].machine: missing (the measured point in machine coordinates)");
}

// Issue 26, 7: a number beyond a double escaped from both readers as nlohmann's out_of_range.
TEST_CASE("inspection plan and points: a number beyond a double names the file and the key", "[inspection][plan]") {
  CHECK_THROWS_AS(parse_inspection_plan(R"({"part": 3999999999999999999999999999e999999999})", "t.json"),
                  InspectionPlanError);
  CHECK_THROWS_WITH(parse_inspection_plan(R"({"part": "p", "features": [{"name": "a", "type": "plane", "point": [0, -1e999, 0]}]})", "t.json"),
                    Catch::StartsWith("t.json: key 'features[0].point[1]' holds a number too large for a double ('-1e999')"));
  CHECK_THROWS_WITH(parse_inspection_plan("3999999999999999999999999999e999999999", "t.json"),
                    Catch::StartsWith("t.json: the document holds a number too large for a double"));
  CHECK_THROWS_AS(parse_measured_points(R"({"points": [{"feature": "a", "machine": [1e400, 0, 0]}]})", "m.json"),
                  MeasuredPointsError);
  CHECK_THROWS_WITH(parse_measured_points(R"({"points": [{"feature": "a", "machine": [1e400, 0, 0]}]})", "m.json"),
                    Catch::StartsWith("m.json: key 'points[0].machine[0]' holds a number too large for a double"));
}
