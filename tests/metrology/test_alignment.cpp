// 3-2-1 and plane + two holes alignment from fitted features.
#include <catch2/catch.hpp>

#include <Eigen/Geometry>

#include "imess/metrology/alignment.hpp"
#include "imess/metrology/fit.hpp"

using namespace imess::metrology;

namespace {

// The part's true placement on the machine.
const Frame& part() {
  static const Frame f(Eigen::AngleAxisd(0.3, Eigen::Vector3d(0.2, -0.1, 1.0).normalized()).toRotationMatrix(),
                       Eigen::Vector3d(250.0, -120.0, 40.0));
  return f;
}

std::vector<Eigen::Vector3d> to_machine(const std::vector<Eigen::Vector3d>& part_points) {
  std::vector<Eigen::Vector3d> out;
  for (const auto& p : part_points) out.push_back(part().point_to_parent(p));
  return out;
}

void check_same(const Frame& got, const Frame& want) {
  CHECK((got.rotation() - want.rotation()).cwiseAbs().maxCoeff() < 1e-12);
  CHECK((got.translation() - want.translation()).norm() < 1e-10);
}

}  // namespace

TEST_CASE("3-2-1 alignment recovers the part frame", "[alignment]") {
  // Primary: three points on the part's z = 0 face.
  const auto plane = fit_plane(to_machine({{10, 10, 0}, {90, 15, 0}, {40, 70, 0}}));
  REQUIRE(plane.ok());
  Plane primary = *plane;
  if (primary.normal.dot(part().direction_to_parent(Eigen::Vector3d::UnitZ())) < 0) primary.normal = -primary.normal;
  // Secondary: two points on the y = 0 side face, at different heights (the line is not in the plane).
  const auto line = fit_line3d(to_machine({{5, 0, -3}, {80, 0, -8}}));
  REQUIRE(line.ok());
  Line3 secondary = *line;
  if (secondary.direction.dot(part().direction_to_parent(Eigen::Vector3d::UnitX())) < 0)
    secondary.direction = -secondary.direction;
  // Tertiary: one point on the x = 0 face.
  const Eigen::Vector3d origin_point = part().point_to_parent({0, 25, -4});
  check_same(align_321(primary, secondary, origin_point), part());
}

TEST_CASE("plane + two holes alignment recovers the part frame", "[alignment]") {
  Plane primary;
  primary.point = part().point_to_parent({30, 30, 0});
  primary.normal = part().direction_to_parent(Eigen::Vector3d::UnitZ());
  // Hole centres measured at some depth below the face: projected into the plane.
  const Eigen::Vector3d hole1 = part().point_to_parent({0, 0, -6});
  const Eigen::Vector3d hole2 = part().point_to_parent({120, 0, -2});
  check_same(align_plane_two_holes(primary, hole1, hole2), part());
}

TEST_CASE("alignment errors", "[alignment][errors]") {
  const Plane primary{{0, 0, 0}, {0, 0, 1}, {}};
  const Line3 vertical{{1, 1, 0}, {0, 0, 1}, {}};
  CHECK_THROWS_WITH(align_321(primary, vertical, {0, 0, 0}), Catch::Contains("perpendicular"));
  CHECK_THROWS_WITH(align_plane_two_holes(primary, {5, 5, 0}, {5, 5, 10}), Catch::Contains("coincide"));
  const Plane bad{{0, 0, 0}, {0, 0, 0}, {}};
  CHECK_THROWS_AS(align_plane_two_holes(bad, {0, 0, 0}, {1, 0, 0}), AlignmentError);
}
