// Sphere fit: known solutions on full spheres and caps, large offsets, noise (checked for
// least-squares optimality), the exact 4-point case and degenerate input.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

double sphere_gradient_cosine(const Sphere& s, const std::vector<Eigen::Vector3d>& pts) {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(pts.size()), 4);
  Eigen::VectorXd r(static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector3d d = pts[i] - s.center;
    const auto k = static_cast<Eigen::Index>(i);
    r(k) = d.norm() - s.radius();
    J.row(k) << -d.transpose() / d.norm(), -1.0;
  }
  return max_gradient_cosine(J, r);
}

}  // namespace

TEST_CASE("sphere recovers known spheres: full, 60 and 20 degree caps, large offset", "[fit][sphere]") {
  Rng rng(41);
  const Eigen::Vector3d pole = Eigen::Vector3d(0.2, 0.3, 0.9).normalized();
  for (const double cap : {kPi, deg(60), deg(20)}) {
    for (const double off : {0.0, 1e4}) {
      INFO("cap " << cap << " offset " << off);
      const Eigen::Vector3d c(3 + off, -4 - off, 7 + off);
      const auto s = sphere_samples(rng, c, 12.5, pole, cap, 50, 0.01);
      const auto fit = fit_sphere(s.points);
      REQUIRE(fit.ok());
      Sphere truth;
      truth.center = c;
      truth.diameter = 25.0;
      const Deviation d = compare(*fit, truth);
      const double tol = off == 0.0 ? 1e-10 : 1e-8;
      CHECK(d.location < tol);
      CHECK(d.size < tol);
      CHECK(fit->stats.iterations < 30);
      CHECK(fit->stats.max_residual > 0.004);
      CHECK(fit->stats.min_residual < -0.004);
    }
  }
}

TEST_CASE("sphere with noise is a least-squares solution near the truth", "[fit][sphere]") {
  Rng rng(42);
  const Eigen::Vector3d c(100.0, -50.0, 25.0);
  std::vector<Eigen::Vector3d> pts;
  for (int i = 0; i < 80; ++i) {
    Eigen::Vector3d n = rng.unit_vector();
    if (n.z() < 0.0) n.z() = -n.z();  // a hemisphere, as probed on a table
    pts.push_back(c + (10.0 + rng.normal(0.001)) * n);
  }
  const auto fit = fit_sphere(pts);
  REQUIRE(fit.ok());
  CHECK(sphere_gradient_cosine(*fit, pts) < 1e-9);
  CHECK((fit->center - c).norm() < 0.002);
  CHECK(std::abs(fit->radius() - 10.0) < 0.002);
}

TEST_CASE("sphere through four points is exact", "[fit][sphere]") {
  const Eigen::Vector3d c(1.0, 2.0, 3.0);
  const std::vector<Eigen::Vector3d> pts{c + Eigen::Vector3d(5, 0, 0), c + Eigen::Vector3d(0, 5, 0),
                                         c + Eigen::Vector3d(0, 0, 5), c + Eigen::Vector3d(-3, -4, 0)};
  const auto fit = fit_sphere(pts);
  REQUIRE(fit.ok());
  CHECK((fit->center - c).norm() < 1e-13);
  CHECK(fit->diameter == Approx(10.0).epsilon(1e-14));
  CHECK(fit->stats.rms < 1e-13);
}

TEST_CASE("sphere rejects coplanar, collinear and too few points", "[fit][sphere][errors]") {
  std::vector<Eigen::Vector3d> ring;
  for (int i = 0; i < 12; ++i) ring.emplace_back(10 * std::cos(i * 0.5), 10 * std::sin(i * 0.5), 4.0);
  auto f = fit_sphere(ring);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CoplanarPoints);
  CHECK_THAT(f.error().message, Catch::Contains("sphere") && Catch::Contains("coplanar"));

  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}, {4, 0, 0}};
  CHECK(fit_sphere(line).error().code == FitErrorCode::CollinearPoints);
  const std::vector<Eigen::Vector3d> three{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  CHECK(fit_sphere(three).error().code == FitErrorCode::TooFewPoints);
}
