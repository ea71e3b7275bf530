// Line fits (2-D, 3-D): known solutions, exact interpolation, large offsets, degenerate input.
#include <catch2/catch.hpp>

#include <limits>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

TEST_CASE("line3d recovers a known line from balanced deviations", "[fit][line]") {
  Rng rng(11);
  for (const Eigen::Vector3d& offset : {Eigen::Vector3d(1.0, 2.0, 3.0), Eigen::Vector3d(1e4, -2e4, 1.5e4)}) {
    const Eigen::Vector3d dir = Eigen::Vector3d(0.3, -0.5, 0.8).normalized();
    const auto pts = line_samples(rng, offset, dir, 50, 120.0, 0.02);
    const auto fit = fit_line3d(pts);
    REQUIRE(fit.ok());
    const Deviation d = compare(*fit, Line3{offset, dir, {}});
    CHECK(d.location < 1e-9);
    CHECK(d.orientation < 1e-12);
    CHECK(fit->stats.point_count == 50);
    CHECK(fit->stats.iterations == 0);
    CHECK(fit->stats.max_residual > 0.005);  // residuals are distances: the deviations show up
    CHECK(fit->stats.min_residual >= 0.0);
    CHECK(fit->direction.norm() == Approx(1.0).epsilon(1e-15));
  }
}

TEST_CASE("line3d through two points is exact", "[fit][line]") {
  const std::vector<Eigen::Vector3d> pts{{1, 2, 3}, {4, 6, 3}};
  const auto fit = fit_line3d(pts);
  REQUIRE(fit.ok());
  CHECK(fit->distance(pts[0]) < 1e-14);
  CHECK(fit->distance(pts[1]) < 1e-14);
  CHECK(direction_angle(fit->direction, Eigen::Vector3d(3, 4, 0)) < 1e-15);
  CHECK(fit->direction.x() > 0.0);  // canonical sign: largest component positive
  CHECK(fit->stats.rms < 1e-14);
}

TEST_CASE("line2d recovers a known line and reports signed residuals", "[fit][line]") {
  Rng rng(12);
  const Eigen::Vector2d c(-300.0, 4000.0);
  const Eigen::Vector2d dir = Eigen::Vector2d(-1.0, 0.2).normalized();
  // 2-D deviations orthogonal to [1, t] along the left normal.
  const auto pts3 = line_samples(rng, Eigen::Vector3d(c.x(), c.y(), 0.0), Eigen::Vector3d(dir.x(), dir.y(), 0.0),
                                 40, 80.0, 0.0);
  std::vector<Eigen::Vector2d> pts;
  Eigen::MatrixXd J(40, 2);
  for (Eigen::Index i = 0; i < 40; ++i) {
    pts.emplace_back(pts3[static_cast<std::size_t>(i)].x(), pts3[static_cast<std::size_t>(i)].y());
    J(i, 0) = 1.0;
    J(i, 1) = dir.dot(pts.back() - c);
  }
  const Eigen::VectorXd e = orthogonal_to(J, alternating(rng, 40, 0.05));
  const Eigen::Vector2d normal(-dir.y(), dir.x());
  for (Eigen::Index i = 0; i < 40; ++i) pts[static_cast<std::size_t>(i)] += e(i) * normal;
  const auto fit = fit_line2d(pts);
  REQUIRE(fit.ok());
  CHECK(direction_angle(fit->direction, dir) < 1e-12);
  CHECK(std::abs(Line2{c, dir, {}}.signed_distance(fit->point)) < 1e-9);
  CHECK(fit->direction.x() > 0.0);  // canonical: largest |component| (x) positive
  const double sign = fit->direction.dot(dir) > 0 ? 1.0 : -1.0;
  CHECK(fit->stats.max_residual == Approx(sign > 0 ? e.maxCoeff() : -e.minCoeff()).margin(1e-9));
  CHECK(fit->stats.min_residual == Approx(sign > 0 ? e.minCoeff() : -e.maxCoeff()).margin(1e-9));
}

TEST_CASE("line fits reject too few, coincident and non-finite points", "[fit][line][errors]") {
  const std::vector<Eigen::Vector3d> one{{1, 2, 3}};
  auto f1 = fit_line3d(one);
  REQUIRE_FALSE(f1.ok());
  CHECK(f1.error().code == FitErrorCode::TooFewPoints);
  CHECK_THAT(f1.error().message, Catch::Contains("line3d") && Catch::Contains("at least 2"));
  CHECK_THROWS_AS(f1.value(), BadFitAccess);

  const std::vector<Eigen::Vector3d> same{{1e4, 2, 3}, {1e4, 2, 3}, {1e4, 2, 3}};
  auto f2 = fit_line3d(same);
  REQUIRE_FALSE(f2.ok());
  CHECK(f2.error().code == FitErrorCode::CoincidentPoints);

  const std::vector<Eigen::Vector2d> nan{{0, 0}, {1, std::numeric_limits<double>::quiet_NaN()}};
  auto f3 = fit_line2d(nan);
  REQUIRE_FALSE(f3.ok());
  CHECK(f3.error().code == FitErrorCode::NonFiniteInput);
  CHECK_THAT(f3.error().message, Catch::Contains("point 1"));
}
