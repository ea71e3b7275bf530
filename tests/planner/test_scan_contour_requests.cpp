// planner::scan_requests for an unknown contour (ScanContourShape): Position and Approach as a
// line scan's, then one Contour segment toward the direction point within the travel, carrying
// what the motion loop steers and stops by; shapes that make no scan are refused with why.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "imess/planner/scan.hpp"

using namespace imess::planner;

namespace {

ScanContourShape corner_shape() {
  ScanContourShape c;
  c.start = {490, 300, 40};
  c.start_normal = {0, -2, 0};  // any length
  c.constraint = ContourConstraint::Plane;
  c.plane_normal = {0, 0, 3};
  c.direction = {500, 300, 45};  // ahead (+x), partly out of the plane
  c.stop = StopBody::Plane;
  c.stop_point = {520, 330, 40};
  c.stop_normal = {0, 1, 0};
  c.count = 2;
  c.stop_after = 10;
  c.end_normal = {1, 0, 0};
  return c;
}

ScanSettings contour_scan_settings() {
  ScanSettings s;
  s.tip_radius = 2;
  s.deflection = 0.3;
  s.clearance = 2;
  s.travel_min = {0, 0, 0};
  s.travel_max = {1000, 1000, 600};
  return s;
}

std::string refusal(const ScanContourShape& c, const ScanSettings& s = contour_scan_settings()) {
  const auto r = scan_requests(1, Pose{}, c, s);
  return std::holds_alternative<std::string>(r) ? std::get<std::string>(r) : std::string("(planned)");
}

}  // namespace

TEST_CASE("an unknown contour plans Position, Approach and one Contour segment toward its direction point", "[scan]") {
  Pose from{};
  from[0] = 480, from[1] = 280, from[2] = 60;
  const auto r = scan_requests(4, from, corner_shape(), contour_scan_settings());
  REQUIRE(std::holds_alternative<std::vector<Request>>(r));
  const auto& list = std::get<std::vector<Request>>(r);
  REQUIRE(list.size() == 3);
  const auto& position = std::get<Line>(list[0]);
  const auto& approach = std::get<Line>(list[1]);
  const auto& contour = std::get<Line>(list[2]);
  CHECK(position.scan.phase == ScanPhase::Position);
  CHECK(approach.scan.phase == ScanPhase::Approach);
  CHECK(contour.scan.phase == ScanPhase::Contour);
  for (const auto& l : {position, approach, contour}) CHECK(l.id == 4);
  // The ball centre touches at 1.7 mm off the start along its normal; the clearance point 2 mm beyond.
  CHECK(position.target[1] == Approx(300 - 1.7 - 2));
  CHECK(approach.target[0] == Approx(490));
  CHECK(approach.target[1] == Approx(300 - 1.7));
  CHECK(approach.target[2] == Approx(40));
  // The Contour runs along +x in the plane (the direction point's height dropped) to the
  // travel's end at x 1000.
  CHECK(contour.target[0] == Approx(1000).margin(0.01));
  CHECK(contour.target[1] == Approx(300 - 1.7));
  CHECK(contour.target[2] == Approx(40));
  const ScanContour& k = contour.scan.contour;
  CHECK(k.constraint == ContourConstraint::Plane);
  CHECK(k.plane_normal[2] == Approx(1));
  CHECK(k.direction[0] == Approx(1));  // plane normal × start normal, turned toward the direction point
  CHECK(k.stop == StopBody::Plane);
  CHECK(k.stop_normal[1] == Approx(1));
  CHECK(k.count == 2);
  CHECK(k.stop_after == 10);
  CHECK(k.end_normal[0] == Approx(1));
  CHECK(k.clearance == 2);
  CHECK(contour.scan.normal[1] == Approx(-1));
  CHECK(contour.scan.deflection == 0.3);

  SECTION("the longest length bounds it") {
    auto c = corner_shape();
    c.max_length = 25;
    const auto& line = std::get<Line>(std::get<std::vector<Request>>(scan_requests(4, from, c, contour_scan_settings()))[2]);
    CHECK(line.target[0] == Approx(515));
  }
  SECTION("a sphere's and a cylinder's diameter become radii; a cylinder constraint keeps its axis") {
    auto c = corner_shape();
    c.stop = StopBody::Sphere;
    c.stop_diameter = 4;
    c.constraint = ContourConstraint::Cylinder;
    c.axis_point = {460, 350, 0};
    c.axis = {0, 0, 5};
    const auto& line = std::get<Line>(std::get<std::vector<Request>>(scan_requests(4, from, c, contour_scan_settings()))[2]);
    CHECK(line.scan.contour.stop_radius == 2);
    CHECK(line.scan.contour.constraint == ContourConstraint::Cylinder);
    CHECK(line.scan.contour.axis[2] == Approx(1));
    // The cylinder's tangent orthogonal to the start normal, toward the direction point.
    const auto& t = line.scan.contour.direction;
    CHECK(t[0] * 10 + t[2] * 5 > 0);
    CHECK(std::hypot(t[0], t[1], t[2]) == Approx(1));
  }
}

TEST_CASE("an unknown contour that makes no scan is refused, saying why", "[scan]") {
  auto c = corner_shape();
  c.start_normal = {0, 0, 0};
  CHECK(refusal(c) == "the start's surface normal must not be zero");
  c = corner_shape();
  c.plane_normal = {0, 0, 0};
  CHECK(refusal(c) == "the scanning plane's normal must not be zero");
  c = corner_shape();
  c.plane_normal = {0, 1, 0};
  CHECK(refusal(c).find("its normal along the start normal") != std::string::npos);
  c = corner_shape();
  c.direction = c.start;
  CHECK(refusal(c) == "the direction point must not be the start");
  c = corner_shape();
  c.direction = {490, 290, 40};  // straight off the surface
  CHECK(refusal(c).find("ahead along the contour") != std::string::npos);
  c = corner_shape();
  c.constraint = ContourConstraint::Cylinder;
  c.axis = {0, 0, 1};
  c.axis_point = {490, 300 - 1.7, 0};  // through the ball centre at the start
  CHECK(refusal(c) == "the start must lie off the cylinder's axis");
  c = corner_shape();
  c.stop = StopBody::Sphere;
  c.stop_diameter = 0;
  CHECK(refusal(c) == "the stop body's diameter must be above 0");
  c = corner_shape();
  c.stop_normal = {0, 0, 0};
  CHECK(refusal(c) == "the stop plane's normal must not be zero");
  c = corner_shape();
  c.count = 0;
  CHECK(refusal(c) == "the stop body's count must be a whole number from 1");
  c = corner_shape();
  c.end_normal = {0, 0, 0};
  CHECK(refusal(c) == "the end normal (the back-off's direction) must not be zero");
  c = corner_shape();
  auto s = contour_scan_settings();
  s.travel_max[0] = 490.5;
  CHECK(refusal(c, s) == "the direction leads out of the travel within 1 mm of the start");
}
