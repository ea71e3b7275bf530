// Plane fit: known solutions, exact 3-point case, large offsets, collinear/coincident input.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

TEST_CASE("plane recovers a known plane from balanced deviations", "[fit][plane]") {
  Rng rng(21);
  for (const Eigen::Vector3d& c : {Eigen::Vector3d(0.5, -2.0, 3.0), Eigen::Vector3d(1e4, 1e4, -1e4)}) {
    const Eigen::Vector3d n = Eigen::Vector3d(0.1, 0.2, -1.0).normalized();
    const auto s = plane_samples(rng, c, n, 60, 40.0, 0.01);
    const auto fit = fit_plane(s.points);
    REQUIRE(fit.ok());
    const Deviation d = compare(*fit, Plane{c, n, {}});
    CHECK(d.location < 1e-9);
    CHECK(d.orientation < 1e-11);
    CHECK(fit->normal.z() > 0.0);  // canonical sign: largest |component| positive
    // Residuals are the deviations along the fitted normal.
    Eigen::VectorXd dev(60);
    for (Eigen::Index i = 0; i < 60; ++i) dev(i) = n.dot(s.points[static_cast<std::size_t>(i)] - c);
    if (fit->normal.dot(n) < 0.0) dev = -dev;
    CHECK(fit->stats.max_residual == Approx(dev.maxCoeff()).margin(1e-9));
    CHECK(fit->stats.min_residual == Approx(dev.minCoeff()).margin(1e-9));
    CHECK(fit->stats.rms == Approx(std::sqrt(dev.squaredNorm() / 60.0)).margin(1e-9));
    CHECK(fit->stats.form() > 0.005);
  }
}

TEST_CASE("plane through three points is exact", "[fit][plane]") {
  const std::vector<Eigen::Vector3d> pts{{0, 0, 1}, {10, 0, 2}, {0, 10, 3}};
  const auto fit = fit_plane(pts);
  REQUIRE(fit.ok());
  for (const auto& p : pts) CHECK(std::abs(fit->signed_distance(p)) < 1e-14);
  CHECK(direction_angle(fit->normal, Eigen::Vector3d(-0.1, -0.2, 1.0)) < 1e-14);
}

TEST_CASE("plane rejects collinear, coincident and too few points", "[fit][plane][errors]") {
  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {5, 5, 5}};
  auto f = fit_plane(line);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CollinearPoints);
  CHECK_THAT(f.error().message, Catch::Contains("plane") && Catch::Contains("collinear"));

  const std::vector<Eigen::Vector3d> same{{1, 1, 1}, {1, 1, 1}, {1, 1, 1}};
  CHECK(fit_plane(same).error().code == FitErrorCode::CoincidentPoints);

  const std::vector<Eigen::Vector3d> two{{1, 1, 1}, {2, 1, 1}};
  CHECK(fit_plane(two).error().code == FitErrorCode::TooFewPoints);
}
