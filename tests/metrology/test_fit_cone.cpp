// Cone fit (NIST convention): known solutions for several apex angles on full and partial
// surfaces, large offsets, axis sense, noise (least-squares optimality), caller start, errors.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

double cone_gradient_cosine(const Cone& k, const std::vector<Eigen::Vector3d>& pts) {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(pts.size()), 8);
  Eigen::VectorXd r(static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i)
    r(static_cast<Eigen::Index>(i)) = cone_row(k, pts[i], &J, static_cast<Eigen::Index>(i));
  return max_gradient_cosine(J, r);
}

Cone make_cone(const Eigen::Vector3d& point, const Eigen::Vector3d& dir, double radius, double apex) {
  Cone k;
  k.point = point;
  k.direction = dir.normalized();
  k.apex_angle_rad = apex;
  k.distance = radius * std::cos(0.5 * apex);  // orthogonal distance for that cross-section radius
  return k;
}

}  // namespace

TEST_CASE("cone geometry helpers agree with the NIST signed distance", "[fit][cone]") {
  const Cone k = make_cone({1, 2, 3}, {0, 0, 1}, 10.0, deg(60));
  CHECK(k.radius_at(0.0) == Approx(10.0));
  CHECK(k.radius_at(5.0) == Approx(10.0 + 5.0 * std::tan(deg(30))));
  CHECK(std::abs(k.signed_distance(Eigen::Vector3d(1 + 10.0, 2, 3))) < 1e-14);
  CHECK(k.signed_distance(Eigen::Vector3d(1, 2, 3)) == Approx(-k.distance));
  const Cone moved = k.moved_to(Eigen::Vector3d(7, 7, 8));  // foot: (1, 2, 8)
  CHECK((moved.point - Eigen::Vector3d(1, 2, 8)).norm() < 1e-14);
  CHECK(moved.radius_at(0.0) == Approx(k.radius_at(5.0)));
  CHECK(k.apex_angle_deg() == Approx(60.0));
}

TEST_CASE("cone recovers known cones: apex 10/60/120 degrees, full and partial, offsets", "[fit][cone]") {
  Rng rng(61);
  const Eigen::Vector3d dir = Eigen::Vector3d(-0.3, 0.2, 0.9).normalized();
  for (const double span : {2 * kPi, deg(180), deg(90)}) {
    for (const double apex : {deg(10), deg(60), deg(120)}) {
      for (const double off : {0.0, 1e4}) {
        INFO("span " << span << " apex " << apex << " offset " << off);
        const Cone truth = make_cone(Eigen::Vector3d(3 + off, -4 - off, 7 + off), dir, 15.0, apex);
        const auto s = cone_samples(rng, truth, span, -5.0, 10.0, 80, 0.01);
        const auto fit = fit_cone(s.points);
        REQUIRE(fit.ok());
        const Deviation d = compare(*fit, truth);
        const double tol = off == 0.0 ? 1e-10 : 1e-8;
        CHECK(d.location < tol);
        CHECK(d.size < tol);
        CHECK(d.orientation < tol / 10.0);
        CHECK(d.apex_angle < tol / 10.0);
        CHECK(fit->direction.dot(dir) > 0.0);  // axis points toward increasing radius
        CHECK(fit->stats.form() > 0.009);
      }
    }
  }
}

TEST_CASE("cone axis sense follows the widening, whichever way the data are ordered", "[fit][cone]") {
  Rng rng(62);
  const Cone truth = make_cone({0, 0, 0}, {0, 0, -1}, 6.0, deg(40));  // widens toward -z
  const auto s = cone_samples(rng, truth, 2 * kPi, -3.0, 3.0, 40, 0.0);
  const auto fit = fit_cone(s.points);
  REQUIRE(fit.ok());
  CHECK(fit->direction.z() < -0.999999);
  CHECK(fit->apex_angle_deg() == Approx(40.0).epsilon(1e-10));
  CHECK(fit->stats.rms < 1e-12);
}

TEST_CASE("cone with noise is a least-squares solution near the truth", "[fit][cone]") {
  Rng rng(63);
  const Cone truth = make_cone({20, -10, 50}, {0.1, 0.9, 0.2}, 12.0, deg(45));
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(truth.direction, u, v);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 100; ++i) {
    const double th = rng.uniform(0.0, 2 * kPi);
    const double h = rng.uniform(-4.0, 4.0);
    const Eigen::Vector3d radial = std::cos(th) * u + std::sin(th) * v;
    const Eigen::Vector3d n = std::cos(truth.half_angle()) * radial - std::sin(truth.half_angle()) * truth.direction;
    pts.push_back(truth.point + h * truth.direction + truth.radius_at(h) * radial + rng.normal(0.001) * n);
  }
  const auto fit = fit_cone(pts);
  REQUIRE(fit.ok());
  CHECK(cone_gradient_cosine(*fit, pts) < 1e-9);
  const Deviation d = compare(*fit, truth);
  CHECK(d.location < 0.005);
  CHECK(d.size < 0.005);
  CHECK(d.apex_angle < 1e-3);
}

TEST_CASE("cone refines from a caller's start", "[fit][cone]") {
  Rng rng(64);
  const Cone truth = make_cone({1, 1, 1}, {1, 0, 0}, 20.0, deg(30));
  const auto s = cone_samples(rng, truth, deg(60), 0.0, 8.0, 40, 0.005);
  Cone start = truth;
  start.point += Eigen::Vector3d(0.5, 0.3, -0.4);
  start.direction = Eigen::Vector3d(1.0, 0.03, -0.02);
  start.apex_angle_rad = deg(33);
  const auto fit = fit_cone(s.points, start);
  REQUIRE(fit.ok());
  const Deviation d = compare(*fit, truth);
  CHECK(d.location < 1e-9);
  CHECK(d.apex_angle < 1e-10);
}

TEST_CASE("cone rejects coplanar and too few points", "[fit][cone][errors]") {
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i < 12; ++i) ring.emplace_back(10 * std::cos(i * 0.5), 10 * std::sin(i * 0.5), 4.0);
  auto f = fit_cone(ring);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CoplanarPoints);
  CHECK_THAT(f.error().message, Catch::Contains("cone"));
  const std::vector<Eigen::Vector3d> five{{1, 0, 0}, {0, 1, 0}, {-1, 0, 1}, {0, -1, 1}, {2, 0, 2}};
  CHECK(fit_cone(five).error().code == FitErrorCode::TooFewPoints);
}

TEST_CASE("cone: a large cloud (starts chosen on a subsample) still gives the exact fit", "[fit][cone]") {
  Rng rng(65);
  const Cone truth = make_cone({-80, 40, 10}, {0.2, -0.3, -1.0}, 9.0, deg(75));
  const auto s = cone_samples(rng, truth, deg(270), -3.0, 5.0, 3000, 0.003);
  const auto fit = fit_cone(s.points);
  REQUIRE(fit.ok());
  const Deviation d = compare(*fit, truth);
  CHECK(d.location < 1e-10);
  CHECK(d.size < 1e-10);
  CHECK(d.apex_angle < 1e-11);
  CHECK(fit->stats.point_count == 3000);
}
