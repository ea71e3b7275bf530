// Probe compensation: features fitted to ball centres and offset by the tip radius on the side
// shown by the approach directions (plane, circle, sphere, cylinder, cone), and the errors.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "imess/metrology/probe_compensation.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

constexpr double kTip = 1.5;  // tip radius, mm

// Ball centres for contact points `feet` with outward normals `normals`: the probe touches from
// outside the material when `outer`, i.e. centre = foot + r n and motion along -n; otherwise
// (bore) centre = foot - r n and motion along +n. `tilt` adds a tangential part to the motion.
struct Hits {
  std::vector<Eigen::Vector3d> centres;
  std::vector<Eigen::Vector3d> approach;
};
Hits probe(const std::vector<Eigen::Vector3d>& feet, const std::vector<Eigen::Vector3d>& normals, bool outer,
           double tilt = 0.0) {
  Hits h;
  for (std::size_t i = 0; i < feet.size(); ++i) {
    const Eigen::Vector3d n = normals[i];
    Eigen::Vector3d t;
    Eigen::Vector3d unused;
    basis_of(n, t, unused);
    const double s = outer ? 1.0 : -1.0;
    h.centres.push_back(feet[i] + s * kTip * n);
    h.approach.push_back(-s * n + tilt * t);
  }
  return h;
}

}  // namespace

TEST_CASE("plane: shifted by r toward the material, normal out of the material", "[compensation][plane]") {
  Rng rng(71);
  const Eigen::Vector3d n = Eigen::Vector3d(0.05, -0.02, 1.0).normalized();
  const auto s = plane_samples(rng, {0, 0, 5}, n, 20, 30.0, 0.0);
  SECTION("top face probed downward") {
    const Hits h = probe(s.feet, s.normals, true, 0.5);  // approach 27 degrees off the normal
    const auto fit = fit_plane_probed(h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    CHECK(std::abs(n.dot(fit->point - Eigen::Vector3d(0, 0, 5))) < 1e-12);
    CHECK(direction_angle(fit->normal, n) < 1e-12);
    CHECK(fit->normal.dot(n) > 0.0);  // points up, out of the material below
  }
  SECTION("underside probed upward") {
    std::vector<Eigen::Vector3d> down(s.normals.size(), -n);
    const Hits h = probe(s.feet, down, true);
    const auto fit = fit_plane_probed(h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    CHECK(std::abs(n.dot(fit->point - Eigen::Vector3d(0, 0, 5))) < 1e-12);
    CHECK(fit->normal.dot(n) < 0.0);  // points down, out of the material above
  }
}

TEST_CASE("circle: bore gets radius + r, shaft radius - r", "[compensation][circle]") {
  const Eigen::Vector3d c(10, 20, 30);
  std::vector<Eigen::Vector3d> feet;
  std::vector<Eigen::Vector3d> normals;
  for (int i = 0; i < 8; ++i) {
    const double th = 0.3 + i * 0.7;
    normals.emplace_back(std::cos(th), std::sin(th), 0.0);
    feet.push_back(c + 10.0 * normals.back());
  }
  for (const bool outer : {false, true}) {
    INFO((outer ? "shaft" : "bore"));
    const Hits h = probe(feet, normals, outer, 0.3);
    const auto centres_only = fit_circle3d(h.centres);
    REQUIRE(centres_only.ok());
    CHECK(centres_only->diameter == Approx(outer ? 23.0 : 17.0));
    const auto side = material_side(*centres_only, h.centres, h.approach);
    REQUIRE(side.ok());
    CHECK(*side == (outer ? MaterialSide::Outer : MaterialSide::Inner));
    const auto fit = fit_circle3d_probed(h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    CHECK(fit->diameter == Approx(20.0).epsilon(1e-13));
    CHECK((fit->center - c).norm() < 1e-12);
  }
  // The same in 2-D.
  std::vector<Eigen::Vector2d> c2;
  std::vector<Eigen::Vector2d> a2;
  for (std::size_t i = 0; i < feet.size(); ++i) {
    const Eigen::Vector2d n(normals[i].x(), normals[i].y());
    c2.emplace_back(Eigen::Vector2d(feet[i].x(), feet[i].y()) - kTip * n);  // bore
    a2.push_back(n);
  }
  const auto bore = fit_circle2d_probed(c2, a2, kTip);
  REQUIRE(bore.ok());
  CHECK(bore->diameter == Approx(20.0).epsilon(1e-13));
}

TEST_CASE("sphere: ball and hollow sphere, and the effective tip radius from a reference sphere",
          "[compensation][sphere]") {
  Rng rng(72);
  const Eigen::Vector3d c(-5, 7, 100);
  const auto s = sphere_samples(rng, c, 12.5, Eigen::Vector3d::UnitZ(), deg(80), 25, 0.0);
  for (const bool outer : {true, false}) {
    const Hits h = probe(s.feet, s.normals, outer);
    const auto fit = fit_sphere_probed(h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    CHECK(fit->diameter == Approx(25.0).epsilon(1e-13));
    CHECK((fit->center - c).norm() < 1e-12);
  }
  // Qualification: a ring a little above the equator plus the pole on a 25 mm reference ball.
  std::vector<Eigen::Vector3d> centres;
  for (int i = 0; i < 8; ++i) {
    const double az = i * kPi / 4;
    const double el = deg(10);
    centres.push_back(c + (12.5 + kTip) * Eigen::Vector3d(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el)));
  }
  centres.push_back(c + (12.5 + kTip) * Eigen::Vector3d::UnitZ());
  const auto qual = fit_sphere(centres);
  REQUIRE(qual.ok());
  CHECK(qual->radius() - 12.5 == Approx(kTip).epsilon(1e-12));
}

TEST_CASE("cylinder: bore and shaft", "[compensation][cylinder]") {
  Rng rng(73);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.1, 0.2, 1.0).normalized();
  const auto s = cylinder_samples(rng, {1, 2, 3}, axis, 15.0, 2 * kPi, 30.0, 30, 0.0);
  for (const bool outer : {true, false}) {
    const Hits h = probe(s.feet, s.normals, outer, 0.2);
    const auto fit = fit_cylinder_probed(h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    CHECK(fit->diameter == Approx(30.0).epsilon(1e-12));
    CHECK(direction_angle(fit->direction, axis) < 1e-12);
  }
}

TEST_CASE("cone: outer and inner keep the angle and shift the surface by r", "[compensation][cone]") {
  Rng rng(74);
  Cone truth;
  truth.point = Eigen::Vector3d(0, 0, 0);
  truth.direction = Eigen::Vector3d(0, 0.1, 1).normalized();
  truth.apex_angle_rad = deg(50);
  truth.distance = 12.0 * std::cos(deg(25));
  const auto s = cone_samples(rng, truth, 2 * kPi, -4.0, 6.0, 40, 0.0);
  for (const bool outer : {true, false}) {
    INFO((outer ? "outer" : "inner"));
    const Hits h = probe(s.feet, s.normals, outer);
    const auto centres_fit = fit_cone(h.centres);
    REQUIRE(centres_fit.ok());
    CHECK(centres_fit->apex_angle_deg() == Approx(50.0).epsilon(1e-12));
    const auto fit = compensate(*centres_fit, h.centres, h.approach, kTip);
    REQUIRE(fit.ok());
    const Deviation d = compare(*fit, truth);
    CHECK(d.location < 1e-11);
    CHECK(d.size < 1e-11);
    CHECK(d.apex_angle < 1e-12);
  }
}

TEST_CASE("compensation errors: mixed sides, bad inputs, too small shafts", "[compensation][errors]") {
  const Eigen::Vector3d c(0, 0, 0);
  std::vector<Eigen::Vector3d> feet;
  std::vector<Eigen::Vector3d> normals;
  for (int i = 0; i < 6; ++i) {
    normals.emplace_back(std::cos(i * 1.0), std::sin(i * 1.0), 0.0);
    feet.push_back(c + 10.0 * normals.back());
  }
  Hits h = probe(feet, normals, false);
  h.approach[3] = -h.approach[3];
  auto mixed = fit_circle3d_probed(h.centres, h.approach, kTip);
  REQUIRE_FALSE(mixed.ok());
  CHECK(mixed.error().code == FitErrorCode::InconsistentApproach);
  CHECK_THAT(mixed.error().message, Catch::Contains("hit 3"));

  h = probe(feet, normals, false);
  h.approach.pop_back();
  CHECK(fit_circle3d_probed(h.centres, h.approach, kTip).error().code == FitErrorCode::InvalidArgument);
  h = probe(feet, normals, false);
  CHECK(fit_circle3d_probed(h.centres, h.approach, -0.5).error().code == FitErrorCode::InvalidArgument);
  h.approach[0].setZero();
  CHECK(fit_circle3d_probed(h.centres, h.approach, kTip).error().code == FitErrorCode::InvalidArgument);

  // Every approach tangential to the circle: the side cannot be told.
  h = probe(feet, normals, false);
  for (std::size_t i = 0; i < h.approach.size(); ++i) h.approach[i] = Eigen::Vector3d::UnitZ().cross(normals[i]);
  CHECK(fit_circle3d_probed(h.centres, h.approach, kTip).error().code == FitErrorCode::InconsistentApproach);

  // A shaft whose centres lie on a circle smaller than the tip radius.
  std::vector<Eigen::Vector3d> small;
  std::vector<Eigen::Vector3d> inward;
  for (const auto& n : normals) {
    small.push_back(c + 1.0 * n);
    inward.push_back(-n);
  }
  CHECK(fit_circle3d_probed(small, inward, kTip).error().code == FitErrorCode::NonPositiveSize);
}
