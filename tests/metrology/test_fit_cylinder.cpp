// Cylinder fit: known solutions on full and partial (90, 30 degree) surfaces, long and short,
// large offsets, noise (checked for least-squares optimality), caller start, degenerate input.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

double cylinder_gradient_cosine(const Cylinder& cyl, const std::vector<Eigen::Vector3d>& pts) {
  const Eigen::Vector3d a = cyl.direction.normalized();
  Eigen::MatrixXd J(static_cast<Eigen::Index>(pts.size()), 7);
  Eigen::VectorXd r(static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d d = pts[i] - cyl.point;
    const Eigen::Vector3d radial = d - d.dot(a) * a;
    const auto k = static_cast<Eigen::Index>(i);
    r(k) = radial.norm() - cyl.radius();
    rigid_row(J, k, pts[i], cyl.point, radial.normalized());
    J(k, 6) = -1.0;
  }
  return max_gradient_cosine(J, r);
}

}  // namespace

TEST_CASE("cylinder recovers known cylinders on full and partial surfaces", "[fit][cylinder]") {
  Rng rng(51);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.3, -0.2, 0.9).normalized();
  for (const double span : {2 * kPi, deg(90), deg(30)}) {
    for (const double length : {60.0, 5.0}) {
      for (const double off : {0.0, 1e4}) {
        INFO("span " << span << " length " << length << " offset " << off);
        const Eigen::Vector3d c(3 + off, -4 - off, 7 + off);
        const auto s = cylinder_samples(rng, c, axis, 20.0, span, length, 60, 0.01);
        const auto fit = fit_cylinder(s.points);
        REQUIRE(fit.ok());
        Cylinder truth;
        truth.point = c;
        truth.direction = axis;
        truth.diameter = 40.0;
        const Deviation d = compare(*fit, truth);
        const double tol = off == 0.0 ? 1e-10 : 1e-8;
        CHECK(d.location < tol);
        CHECK(d.size < tol);
        CHECK(d.orientation < tol / 10.0);
        // The reported axis point is the foot of the data centroid.
        Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
        for (const auto& p : s.points) centroid += p / 60.0;
        CHECK(std::abs((centroid - fit->point).dot(fit->direction)) < 1e-9);
        CHECK(fit->direction.norm() == Approx(1.0).epsilon(1e-14));
        CHECK(fit->stats.form() > 0.009);
      }
    }
  }
}

TEST_CASE("cylinder with noise is a least-squares solution near the truth", "[fit][cylinder]") {
  Rng rng(52);
  const Eigen::Vector3d c(-40.0, 25.0, 300.0);
  const Eigen::Vector3d axis = Eigen::Vector3d(1.0, 0.1, -0.05).normalized();
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  basis_of(axis, u, v);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 90; ++i) {
    const double th = rng.uniform(0.0, 2 * kPi);
    pts.push_back(c + rng.uniform(-20.0, 20.0) * axis + (8.0 + rng.normal(0.001)) * (std::cos(th) * u + std::sin(th) * v));
  }
  const auto fit = fit_cylinder(pts);
  REQUIRE(fit.ok());
  CHECK(cylinder_gradient_cosine(*fit, pts) < 1e-9);
  CHECK(point_line_distance(c, fit->point, fit->direction) < 0.002);
  CHECK(direction_angle(fit->direction, axis) < 1e-3);
  CHECK(std::abs(fit->radius() - 8.0) < 0.002);
}

TEST_CASE("cylinder refines from a caller's start", "[fit][cylinder]") {
  Rng rng(53);
  const Eigen::Vector3d axis = Eigen::Vector3d(0.0, 1.0, 0.2).normalized();
  const auto s = cylinder_samples(rng, Eigen::Vector3d(5, 5, 5), axis, 30.0, deg(20), 10.0, 30, 0.005);
  Cylinder start;
  start.point = Eigen::Vector3d(5.5, 4.0, 5.2);
  start.direction = Eigen::Vector3d(0.05, 1.0, 0.15);
  start.diameter = 58.0;
  const auto fit = fit_cylinder(s.points, start);
  REQUIRE(fit.ok());
  Cylinder truth;
  truth.point = Eigen::Vector3d(5, 5, 5);
  truth.direction = axis;
  truth.diameter = 60.0;
  const Deviation d = compare(*fit, truth);
  CHECK(d.location < 1e-9);
  CHECK(d.size < 1e-9);

  start.diameter = -1.0;
  CHECK(fit_cylinder(s.points, start).error().code == FitErrorCode::InvalidArgument);
}

TEST_CASE("cylinder rejects a single ring, too few points and collinear points", "[fit][cylinder][errors]") {
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i < 12; ++i) ring.emplace_back(10 * std::cos(i * 0.5), 10 * std::sin(i * 0.5), 4.0);
  auto f = fit_cylinder(ring);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CoplanarPoints);
  CHECK_THAT(f.error().message, Catch::Contains("cylinder") && Catch::Contains("two heights"));

  const std::vector<Eigen::Vector3d> four{{1, 0, 0}, {0, 1, 0}, {-1, 0, 1}, {0, -1, 1}};
  CHECK(fit_cylinder(four).error().code == FitErrorCode::TooFewPoints);
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}};
  CHECK(fit_cylinder(line).error().code == FitErrorCode::CollinearPoints);
}

TEST_CASE("cylinder: a large cloud (starts chosen on a subsample) still gives the exact fit", "[fit][cylinder]") {
  Rng rng(54);
  const Eigen::Vector3d axis = Eigen::Vector3d(-0.4, 0.1, 0.9).normalized();
  const auto s = cylinder_samples(rng, {500, -300, 20}, axis, 6.0, deg(120), 25.0, 3000, 0.003);
  const auto fit = fit_cylinder(s.points);
  REQUIRE(fit.ok());
  Cylinder truth;
  truth.point = {500, -300, 20};
  truth.direction = axis;
  truth.diameter = 12.0;
  const Deviation d = compare(*fit, truth);
  CHECK(d.location < 1e-10);
  CHECK(d.size < 1e-10);
  CHECK(fit->stats.point_count == 3000);
}

TEST_CASE("cylinder: an axis-parallel bore written to 4 decimals passes the stationarity check", "[fit][cylinder]") {
  // Ball centres of a bore along z (radius 9 after a 1 mm tip), surface points rounded to 4
  // decimals and approach directions to 6: residuals of a few 1e-5 mm, the axis within 3e-6 rad
  // of z. The independent check once measured cosines of 1e-5 here (a finite-difference column of
  // the direction's z component, nearly zero, was rounding noise) and had to be skipped.
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 12; ++i) {
    const double t = 0.5 * i;
    const auto round_to = [](double v, double unit) { return std::round(v / unit) * unit; };
    const Eigen::Vector3d surface(round_to(100 + 10 * std::cos(t), 1e-4), round_to(50 + 10 * std::sin(t), 1e-4),
                                  5.0 * (i % 3));
    const Eigen::Vector3d approach(round_to(std::cos(t), 1e-6), round_to(std::sin(t), 1e-6), 0.0);
    pts.push_back(surface - approach);
  }
  const auto f = fit_cylinder(pts);
  REQUIRE(f.ok());
  CHECK(f->stats.rms < 1e-4);
  CHECK(f->stats.rms > 1e-6);  // not exact data: the check was not bypassed as interpolation
  CHECK(f->diameter == Approx(18.0).margin(1e-4));
  CHECK(cylinder_gradient_cosine(*f, pts) < 1e-8);
}
