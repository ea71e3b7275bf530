// An inspection plan's scans ("scan": a circle or a line measured with a measuring probe): what
// the reader takes from the feature when the scan does not say it, where a scan starts and
// ends and which way the surface faces there, and the message a bad scan gets.
#include <catch2/catch.hpp>

#include <cmath>
#include <fstream>
#include <sstream>

#include "imess/metrology/inspection_plan.hpp"

using namespace imess::metrology;
using Eigen::Vector3d;

namespace {

std::string plan_of(const std::string& feature) {
  return R"({"part": "p", "features": [)" + feature + R"(], "characteristics": []})";
}

std::string scan_error(const std::string& feature) {
  try {
    parse_inspection_plan(plan_of(feature), "s.json");
  } catch (const InspectionPlanError& e) {
    return e.what();
  }
  return "(accepted)";
}

const std::string kBore = R"({"name": "b", "type": "circle", "center": [60, 50, 40], "normal": [0, 0, 2], "diameter": 30, "inner": true, )";

}  // namespace

TEST_CASE("plan scans: a circle's centre, axis and side come from its feature — start, end and normals", "[inspection][plan][scan]") {
  const auto plan = parse_inspection_plan(
      plan_of(kBore + R"("scan": {"circle": {"start": [75, 50, 40], "sweep": 450}, "step": 0.05, "speed": 12}})"), "s.json");
  const auto& f = plan.feature("b");
  REQUIRE(f.probes.empty());
  REQUIRE(f.scans.size() == 1);
  const ScanPath& s = f.scans[0];
  CHECK(s.kind == ScanPath::Kind::Circle);
  CHECK((s.center - Vector3d(60, 50, 40)).norm() < 1e-12);
  CHECK((s.axis - Vector3d::UnitZ()).norm() < 1e-12);
  CHECK(s.bore);
  CHECK(s.sweep_deg == 450);
  CHECK(s.step == 0.05);
  CHECK(s.speed == 12);
  // A bore's surface faces its axis: at the start (+x of the centre) the outward normal is -x.
  CHECK((s.normal_at_start() - Vector3d(-1, 0, 0)).norm() < 1e-12);
  // 450 degrees right-handed about +z: a quarter turn past the start, at +y.
  CHECK((s.end_point() - Vector3d(60, 65, 40)).norm() < 1e-9);
  CHECK((s.normal_at_end() - Vector3d(0, -1, 0)).norm() < 1e-9);
  CHECK(s.length() == Approx(15 * 2.5 * M_PI));
}

TEST_CASE("plan scans: a boss, lines on a plane, several scans of a cylinder", "[inspection][plan][scan]") {
  const auto boss = parse_inspection_plan(
      plan_of(R"({"name": "s", "type": "cylinder", "point": [0, 0, 0], "axis": [0, 0, 1], "diameter": 10,
                  "scan": [{"circle": {"center": [0, 0, 5], "start": [0, 5, 5], "sweep": -90}},
                           {"circle": {"center": [0, 0, 20], "start": [0, 5, 20]}}]})"),
      "s.json");
  const auto& scans = boss.feature("s").scans;
  REQUIRE(scans.size() == 2);
  CHECK_FALSE(scans[0].bore);
  CHECK((scans[0].normal_at_start() - Vector3d(0, 1, 0)).norm() < 1e-12);  // away from the axis
  CHECK((scans[0].end_point() - Vector3d(5, 0, 5)).norm() < 1e-9);         // -90: clockwise seen from +z
  CHECK(scans[1].sweep_deg == 360);                                        // the default: one turn
  CHECK_FALSE(scans[1].step.has_value());
  CHECK_FALSE(scans[1].speed.has_value());

  const auto top = parse_inspection_plan(
      plan_of(R"({"name": "t", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1],
                  "scan": [{"line": {"from": [10, 25, 80], "to": [110, 25, 80]}},
                           {"line": {"from": [110, 85, 80], "to": [10, 85, 80], "normal": [1, 0, 1]}}]})"),
      "s.json");
  const auto& lines = top.feature("t").scans;
  REQUIRE(lines.size() == 2);
  CHECK(lines[0].kind == ScanPath::Kind::Line);
  CHECK((lines[0].normal - Vector3d::UnitZ()).norm() < 1e-12);  // the plane's
  CHECK((lines[1].normal - Vector3d::UnitZ()).norm() < 1e-12);  // its part along the line dropped
  CHECK((lines[1].end_point() - Vector3d(10, 85, 80)).norm() < 1e-12);
  CHECK(lines[1].length() == Approx(100));
}

TEST_CASE("plan scans: a bad scan names its key and what is accepted", "[inspection][plan][scan]") {
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40]}, "line": {}}})") ==
        "s.json: features[0].scan: expected {\"circle\": {…}} or {\"line\": {…}}, with optional \"step\" and \"speed\" "
        "(one of circle and line)");
  CHECK(scan_error(kBore + R"("scan": {"step": 0.1}})").find("(one of circle and line)") != std::string::npos);
  CHECK(scan_error(kBore + R"("scan": []})") == "s.json: features[0].scan: expected a scan or a non-empty array of scans");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [60, 50, 10]}}})") ==
        "s.json: features[0].scan.circle.start: the start lies on the scan's axis; expected a surface point off it "
        "(its distance from the axis is the scan's radius)");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40], "sweep": 0}}})") ==
        "s.json: features[0].scan.circle.sweep: expected a sweep other than 0 degrees");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40], "sweep": 40000}}})") ==
        "s.json: features[0].scan.circle.sweep: expected -36000 … 36000 degrees (right hand about the axis)");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40], "surface": "hole"}}})") ==
        "s.json: features[0].scan.circle.surface: expected \"bore\" (the surface faces the axis) or \"boss\" (it faces away)");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40], "radius": 15}}})") ==
        "s.json: features[0].scan.circle.radius: unknown key; accepted here: center, axis, start, sweep, surface");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40]}, "step": 0}})") ==
        "s.json: features[0].scan.step: expected 0.001 … 100 mm between points");
  CHECK(scan_error(kBore + R"("scan": {"circle": {"start": [75, 50, 40]}, "speed": 500}})") ==
        "s.json: features[0].scan.speed: expected 0.1 … 100 mm/s");
  // A sphere has no axis of its own; a plane no centre; a line no normal but a plane's or point's.
  CHECK(scan_error(R"({"name": "s", "type": "sphere", "center": [0, 0, 0], "diameter": 25,
                       "scan": {"circle": {"start": [12.5, 0, 0]}}})")
            .find("s.json: features[0].scan.circle.axis: missing (expected the axis [i, j, k] the scan goes round") == 0);
  CHECK(scan_error(R"({"name": "t", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1],
                       "scan": {"circle": {"axis": [0, 0, 1], "start": [1, 0, 80]}}})")
            .find("s.json: features[0].scan.circle.center: missing") == 0);
  CHECK(scan_error(R"({"name": "l", "type": "line", "point": [0, 0, 0], "direction": [1, 0, 0],
                       "scan": {"line": {"from": [0, 0, 0], "to": [10, 0, 0]}}})")
            .find("s.json: features[0].scan.line.normal: missing") == 0);
  CHECK(scan_error(R"({"name": "t", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1],
                       "scan": {"line": {"from": [0, 0, 80], "to": [0, 0, 90]}}})") ==
        "s.json: features[0].scan.line.normal: the normal runs along the line; expected the outward normal of the "
        "surface the line lies on");
  CHECK(scan_error(R"({"name": "t", "type": "plane", "point": [0, 0, 80], "normal": [0, 0, 1],
                       "scan": {"line": {"from": [0, 0, 80], "to": [0, 0, 80]}}})") ==
        "s.json: features[0].scan.line.to: expected an end other than the start");
}

TEST_CASE("the shipped bore-scan plan is a valid plan: every feature scanned", "[inspection][plan][scan]") {
  std::ifstream in(std::string(IMESS_SOURCE_DIR) + "/examples/cube-bore-scan.plan.json");
  REQUIRE(in);
  std::stringstream text;
  text << in.rdbuf();
  const auto plan = parse_inspection_plan(text.str(), "cube-bore-scan.plan.json");
  for (const auto& f : plan.features) {
    INFO(f.name);
    CHECK_FALSE(f.scans.empty());
  }
}
