// ISO 10360-6 style comparison metrics.
#include <catch2/catch.hpp>

#include <cmath>
#include <numbers>

#include "imess/metrology/compare.hpp"

using namespace imess::metrology;

TEST_CASE("direction angle ignores the sign and is exact for tiny angles", "[compare]") {
  const Eigen::Vector3d x = Eigen::Vector3d::UnitX();
  CHECK(direction_angle(x, -x) == 0.0);
  CHECK(direction_angle(x, Eigen::Vector3d::UnitY()) == Approx(std::numbers::pi / 2));
  for (const double t : {1e-9, 1e-7, 1e-3, 0.5}) {
    const Eigen::Vector3d b(std::cos(t), std::sin(t), 0.0);
    CHECK(direction_angle(x, b) == Approx(t).epsilon(1e-12));
    CHECK(direction_angle(x, Eigen::Vector3d(-b)) == Approx(t).epsilon(1e-12));
    CHECK(direction_angle(x, Eigen::Vector3d(3.0 * b)) == Approx(t).epsilon(1e-12));  // not unit
  }
  CHECK(direction_angle(Eigen::Vector2d(1, 0), Eigen::Vector2d(0, -2)) == Approx(std::numbers::pi / 2));
}

TEST_CASE("line and axis location is a point-to-line distance both ways", "[compare]") {
  const Line3 ref{{0, 0, 0}, {0, 0, 1}, {}};
  // Tested point far along the axis: only its distance from the reference line counts.
  Line3 tested{{0.001, 0, 500}, {0, 0, 1}, {}};
  Deviation d = compare(tested, ref);
  CHECK(d.location == Approx(0.001));
  CHECK(d.orientation == 0.0);
  // Tilted tested line through the reference point: reference point to tested line = 0, but the
  // tested point 100 mm up lies 100 * 1e-6 off the reference line; the larger one is reported.
  const double t = 1e-6;
  tested = Line3{{100 * std::sin(t), 0, 100 * std::cos(t)}, {std::sin(t), 0, std::cos(t)}, {}};
  d = compare(tested, ref);
  CHECK(d.location == Approx(100 * std::sin(t)).epsilon(1e-9));
  CHECK(d.orientation == Approx(t).epsilon(1e-9));
}

TEST_CASE("plane, circle, sphere and cylinder deviations", "[compare]") {
  const Plane pr{{0, 0, 0}, {0, 0, 1}, {}};
  const Plane pt{{30, 40, 0.002}, {0, 0, -1}, {}};
  Deviation d = compare(pt, pr);
  CHECK(d.location == Approx(0.002));
  CHECK(d.orientation == 0.0);

  Circle3 cr;
  cr.center = {1, 2, 3};
  cr.normal = {0, 0, 1};
  cr.diameter = 20.0;
  Circle3 ct = cr;
  ct.center += Eigen::Vector3d(0.003, 0.004, 0.0);
  ct.diameter = 20.0005;
  d = compare(ct, cr);
  CHECK(d.location == Approx(0.005));
  CHECK(d.size == Approx(0.0005));

  Sphere sr;
  sr.center = {0, 0, 0};
  sr.diameter = 25.0;
  Sphere st = sr;
  st.diameter = 24.999;
  CHECK(compare(st, sr).size == Approx(0.001));

  Cylinder yr;
  yr.point = {0, 0, 0};
  yr.direction = {1, 0, 0};
  yr.diameter = 10.0;
  Cylinder yt = yr;
  yt.point = {-70, 0.0, 0.0002};
  yt.direction = {-1, 0, 0};
  d = compare(yt, yr);
  CHECK(d.location == Approx(0.0002));
  CHECK(d.orientation == 0.0);
}

TEST_CASE("cone size compares diameters at the reference point's cross-section", "[compare]") {
  Cone ref;
  ref.point = {0, 0, 0};
  ref.direction = {0, 0, 1};
  ref.apex_angle_rad = std::numbers::pi / 3;
  ref.distance = 10.0 * std::cos(std::numbers::pi / 6);
  // The same cone described from another axis point: no deviation.
  const Cone same = ref.moved_to({0, 0, 7});
  Deviation d = compare(same, ref);
  CHECK(d.location < 1e-14);
  CHECK(d.size < 1e-13);
  CHECK(d.apex_angle < 1e-15);
  // A surface moved out by 0.001 along its normal: the diameter grows by 2 * 0.001 / cos(phi).
  Cone bigger = ref;
  bigger.distance += 0.001;
  d = compare(bigger, ref);
  CHECK(d.size == Approx(0.002 / std::cos(std::numbers::pi / 6)));
  Cone wider = ref;
  wider.apex_angle_rad += 1e-6;
  CHECK(compare(wider, ref).apex_angle == Approx(1e-6));
}
