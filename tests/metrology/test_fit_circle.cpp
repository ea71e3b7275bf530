// Circle fits (2-D and NIST-style 3-D): known solutions on full circles and 30 degree arcs,
// large offsets, noise (checked for least-squares optimality), exact and degenerate cases.
#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

// Least-squares optimality of a 2-D circle fit, judged independently of the library.
double circle2_gradient_cosine(const Circle2& c, const std::vector<Eigen::Vector2d>& pts) {
  Eigen::MatrixXd J(static_cast<Eigen::Index>(pts.size()), 3);
  Eigen::VectorXd r(static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Eigen::Vector2d d = pts[i] - c.center;
    const auto k = static_cast<Eigen::Index>(i);
    r(k) = d.norm() - c.radius();
    J.row(k) << -d.x() / d.norm(), -d.y() / d.norm(), -1.0;
  }
  return max_gradient_cosine(J, r);
}

}  // namespace

TEST_CASE("circle2d recovers known circles: full, 30 degree arc, large offset", "[fit][circle]") {
  Rng rng(31);
  struct Case {
    Eigen::Vector2d c;
    double r;
    double start;
    double span;
    double tol_loc;
  };
  const Case cases[] = {
      {{3.0, -4.0}, 25.0, 0.3, 2 * kPi, 1e-11},
      {{3.0, -4.0}, 25.0, 0.3, deg(30), 1e-9},
      {{1e4, -1e4}, 12.5, 1.0, 2 * kPi, 1e-9},
      {{1e4, -1e4}, 12.5, 1.0, deg(30), 1e-7},
  };
  for (const auto& k : cases) {
    INFO("centre " << k.c.transpose() << " span " << k.span);
    const auto pts = circle2_samples(rng, k.c, k.r, k.start, k.span, 40, 0.01);
    const auto fit = fit_circle2d(pts);
    REQUIRE(fit.ok());
    const Deviation d = compare(*fit, Circle2{k.c, 2 * k.r, {}});
    CHECK(d.location < k.tol_loc);
    CHECK(d.size < k.tol_loc);
    CHECK(fit->stats.point_count == 40);
    CHECK(fit->stats.iterations >= 1);
    CHECK(fit->stats.iterations < 50);
    CHECK(fit->stats.form() > 0.005);
  }
}

TEST_CASE("circle2d with noise is a least-squares solution near the truth", "[fit][circle]") {
  Rng rng(32);
  const Eigen::Vector2d c(-20.0, 7.0);
  std::vector<Eigen::Vector2d> pts;
  for (int i = 0; i < 60; ++i) {
    const double th = deg(40) + deg(90) * i / 59.0;  // a quarter arc
    pts.push_back(c + (15.0 + rng.normal(0.002)) * Eigen::Vector2d(std::cos(th), std::sin(th)));
  }
  const auto fit = fit_circle2d(pts);
  REQUIRE(fit.ok());
  CHECK(circle2_gradient_cosine(*fit, pts) < 1e-9);
  CHECK((fit->center - c).norm() < 0.01);
  CHECK(std::abs(fit->radius() - 15.0) < 0.01);
  CHECK(fit->stats.rms == Approx(0.002).epsilon(0.3));
}

TEST_CASE("circle2d through three points is exact", "[fit][circle]") {
  const std::vector<Eigen::Vector2d> pts{{10, 0}, {0, 10}, {-6, -8}};
  const auto fit = fit_circle2d(pts);
  REQUIRE(fit.ok());
  CHECK(fit->center.norm() < 1e-13);
  CHECK(fit->diameter == Approx(20.0).epsilon(1e-15));
  CHECK(fit->stats.rms < 1e-13);
}

TEST_CASE("circle2d rejects collinear, coincident and too few points", "[fit][circle][errors]") {
  const std::vector<Eigen::Vector2d> line{{0, 0}, {1, 2}, {2, 4}, {3, 6}};
  auto f = fit_circle2d(line);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CollinearPoints);
  CHECK_THAT(f.error().message, Catch::Contains("circle2d"));
  const std::vector<Eigen::Vector2d> two{{0, 0}, {1, 2}};
  CHECK(fit_circle2d(two).error().code == FitErrorCode::TooFewPoints);
  const std::vector<Eigen::Vector2d> same{{5, 5}, {5, 5}, {5, 5}};
  CHECK(fit_circle2d(same).error().code == FitErrorCode::CoincidentPoints);
}

TEST_CASE("circle3d recovers known circles (plane, project, 2-D circle)", "[fit][circle]") {
  Rng rng(33);
  struct Case {
    Eigen::Vector3d c;
    Eigen::Vector3d n;
    double r;
    double span;
    double tol;
  };
  const Case cases[] = {
      {{10.0, 20.0, -5.0}, Eigen::Vector3d(0.2, -0.3, 0.9).normalized(), 30.0, 2 * kPi, 1e-10},
      {{10.0, 20.0, -5.0}, Eigen::Vector3d(0.2, -0.3, 0.9).normalized(), 30.0, deg(30), 1e-8},
      {{1e4, 2e4, -1e4}, Eigen::Vector3d(1.0, 1.0, 1.0).normalized(), 8.0, 2 * kPi, 1e-9},
      {{1e4, 2e4, -1e4}, Eigen::Vector3d(1.0, 1.0, 1.0).normalized(), 8.0, deg(30), 1e-7},
  };
  for (const auto& k : cases) {
    INFO("centre " << k.c.transpose() << " span " << k.span);
    const auto pts = circle3_samples(rng, k.c, k.n, k.r, 0.7, k.span, 36, 0.01, 0.005);
    const auto fit = fit_circle3d(pts);
    REQUIRE(fit.ok());
    Circle3 truth;
    truth.center = k.c;
    truth.normal = k.n;
    truth.diameter = 2 * k.r;
    const Deviation d = compare(*fit, truth);
    CHECK(d.location < k.tol);
    CHECK(d.size < k.tol);
    CHECK(d.orientation < 1e-9);
    CHECK(fit->plane_stats.form() > 0.0025);  // the out-of-plane deviations are reported
    CHECK(fit->stats.form() > 0.005);
  }
}

TEST_CASE("circle3d through three points is exact, and collinear points are rejected", "[fit][circle]") {
  const std::vector<Eigen::Vector3d> pts{{1, 0, 5}, {0, 1, 5}, {-1, 0, 5}};
  const auto fit = fit_circle3d(pts);
  REQUIRE(fit.ok());
  CHECK((fit->center - Eigen::Vector3d(0, 0, 5)).norm() < 1e-14);
  CHECK(fit->diameter == Approx(2.0).epsilon(1e-15));
  CHECK(direction_angle(fit->normal, Eigen::Vector3d::UnitZ()) < 1e-15);

  const std::vector<Eigen::Vector3d> line{{0, 0, 0}, {1, 1, 0}, {2, 2, 0}};
  auto f = fit_circle3d(line);
  REQUIRE_FALSE(f.ok());
  CHECK(f.error().code == FitErrorCode::CollinearPoints);
  CHECK_THAT(f.error().message, Catch::Contains("circle3d"));
}
