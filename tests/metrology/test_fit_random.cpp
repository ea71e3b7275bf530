// Randomised fits: for every feature, 500 random instances with fixed seeds (random position,
// orientation and size; minimal point counts up to 12 points; arcs, caps and sectors down to 30
// degrees; a quarter exact, the others with deviations made orthogonal to the Jacobian so the
// generator stays a least-squares solution). Exact data must give the generator (relative error
// below 1e-6 of the size). Data with deviations must give a least-squares solution: stationary by
// this file's own Jacobian and with a sum of squares no larger than the generator's. Minimal
// cylinder and cone sets must be refused as ambiguous (several exact solutions). No misses are
// tolerated. IMESS_PRINT_FITS=1 prints the worst figures per feature; IMESS_FIT_SEEDS=N draws N
// instances per feature instead of 500 (a wider check, docs/metrology.md 2.7).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdint>
#include <cstdlib>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include <catch2/catch.hpp>

#include "imess/metrology/compare.hpp"
#include "imess/metrology/fit.hpp"
#include "synthetic.hpp"

using namespace imess::metrology;
using namespace imess::metrology::test;

namespace {

constexpr int kDefaultSeeds = 500;
constexpr long kMaxSeeds = 1000000;

// Draws per feature: 500, or the count in IMESS_FIT_SEEDS (1 to 1000000).
int draw_count() {
  static const int n = [] {
    const char* env = std::getenv("IMESS_FIT_SEEDS");
    if (env == nullptr) return kDefaultSeeds;
    char* end = nullptr;
    const long v = std::strtol(env, &end, 10);
    if (end == env || *end != '\0' || v < 1 || v > kMaxSeeds)
      throw std::invalid_argument("IMESS_FIT_SEEDS='" + std::string(env) +
                                  "': expected a whole number of draws per feature from 1 to 1000000");
    return static_cast<int>(v);
  }();
  return n;
}
constexpr double kRelTol = 1e-6;  // closeness to the generator, relative to its size
constexpr double kCosTol = 1e-6;  // stationarity with the test's own Jacobian

// WorstFit figures of one feature, printed at the end of its test case on request.
struct WorstFit {
  const char* feature;
  int draws = draw_count();
  double error = 0.0;   // relative to size: max(location, size) / size, orientation in rad
  double cosine = 0.0;
  int ambiguous = 0;
  int misses = 0;  // cylinder, cone: a higher minimum than the generator's, or a refusal
  int lower = 0;   // cylinder, cone: a minimum lower than the generator's (the fit is right)
  int cylinders = 0;  // cone: refused as a cylinder that fits no worse than the generator (right)
  void add(const Deviation& d, double size, double cos) {
    error = std::max({error, d.location / size, d.size / size, d.orientation, d.apex_angle});
    cosine = std::max(cosine, cos);
  }
  ~WorstFit() {
    if (std::getenv("IMESS_PRINT_FITS") == nullptr) return;
    std::printf("%-9s worst relative error %.2e  worst gradient cosine %.2e  ambiguous minimal sets %d"
                "  lower minimum %d  missed %d  (of %d)",
                feature, error, cosine, ambiguous, lower, misses, draws);
    if (cylinders > 0) std::printf("  cylinder fits better %d", cylinders);
    std::printf("\n");
  }
};

Eigen::Vector3d random_point(Rng& rng) { return {rng.uniform(-500, 500), rng.uniform(-500, 500), rng.uniform(-500, 500)}; }

// Largest gradient cosine of residuals r with rows of J, or 0 when the residuals are rounding.
double cosine_if_residual(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, double size) {
  if (r.norm() <= 1e-9 * size * std::sqrt(static_cast<double>(r.size()))) return 0.0;
  return max_gradient_cosine(J, r);
}

// A point count from the minimum up to 12 (a quarter of the draws at the minimum).
std::size_t count(Rng& rng, std::size_t minimum) {
  return rng.uniform(0, 1) < 0.25 ? minimum : minimum + static_cast<std::size_t>(rng.uniform(0, 12.999 - minimum));
}

}  // namespace

TEST_CASE("random lines and planes are their exact least-squares fits", "[fit][random]") {
  WorstFit wl{"line3d"};
  WorstFit wp{"plane"};
  for (int seed = 0; seed < draw_count(); ++seed) {
    Rng rng(1000 + seed);
    const double size = rng.uniform(1, 200);
    const Eigen::Vector3d c = random_point(rng);
    const Eigen::Vector3d dir = rng.unit_vector();
    const auto pts = line_samples(rng, c, dir, count(rng, 2), size, rng.uniform(0, 0.01) * size);
    auto line = fit_line3d(pts);
    REQUIRE(line.ok());
    Deviation d;
    d.orientation = direction_angle(line->direction, dir);
    d.location = point_line_distance(line->point, c, dir);
    wl.add(d, size, 0.0);
    CHECK(d.orientation < kRelTol);
    CHECK(d.location < kRelTol * size);

    const auto s = plane_samples(rng, c, dir, count(rng, 3), 0.5 * size, rng.uniform(0, 0.01) * size);
    auto plane = fit_plane(s.points);
    REQUIRE(plane.ok());
    Eigen::MatrixXd J(static_cast<Eigen::Index>(s.points.size()), 6);
    Eigen::VectorXd r(J.rows());
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      r(i) = plane->normal.dot(s.points[i] - plane->point);
      rigid_row(J, i, s.points[i], plane->point, plane->normal);
    }
    Deviation dp;
    dp.orientation = direction_angle(plane->normal, dir);
    dp.location = std::abs(dir.dot(plane->point - c));
    const double cos = cosine_if_residual(J, r, size);
    wp.add(dp, size, cos);
    CHECK(dp.orientation < kRelTol);
    CHECK(dp.location < kRelTol * size);
    CHECK(cos < kCosTol);
  }
}

TEST_CASE("random circles on arcs down to 30 degrees are their exact least-squares fits", "[fit][random]") {
  WorstFit w2{"circle2d"};
  WorstFit w3{"circle3d"};
  for (int seed = 0; seed < draw_count(); ++seed) {
    Rng rng(2000 + seed);
    const double radius = rng.uniform(1, 200);
    const double span = deg(rng.uniform(30, 360));
    const double start = rng.uniform(0, 2 * kPi);
    const Eigen::Vector2d c2(rng.uniform(-500, 500), rng.uniform(-500, 500));
    const auto pts = circle2_samples(rng, c2, radius, start, span, count(rng, 3), rng.uniform(0, 0.01) * radius);
    auto f = fit_circle2d(pts);
    INFO("seed " << seed << " span " << span);
    REQUIRE(f.ok());
    Eigen::MatrixXd J(static_cast<Eigen::Index>(pts.size()), 3);
    Eigen::VectorXd r(J.rows());
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      const Eigen::Vector2d d = pts[static_cast<std::size_t>(i)] - f->center;
      r(i) = d.norm() - f->radius();
      J.row(i) << -d.x() / d.norm(), -d.y() / d.norm(), -1.0;
    }
    Deviation d;
    d.location = (f->center - c2).norm();
    d.size = std::abs(f->diameter - 2 * radius);
    const double cos = cosine_if_residual(J, r, radius);
    w2.add(d, radius, cos);
    CHECK(d.location < kRelTol * radius);
    CHECK(d.size < kRelTol * radius);
    CHECK(cos < kCosTol);

    const Eigen::Vector3d c3 = random_point(rng);
    const Eigen::Vector3d n = rng.unit_vector();
    const auto p3 = circle3_samples(rng, c3, n, radius, start, span, count(rng, 3), rng.uniform(0, 0.01) * radius,
                                    rng.uniform(0, 0.01) * radius);
    auto g = fit_circle3d(p3);
    REQUIRE(g.ok());
    Deviation d3;
    d3.location = (g->center - c3).norm();
    d3.size = std::abs(g->diameter - 2 * radius);
    d3.orientation = direction_angle(g->normal, n);
    w3.add(d3, radius, 0.0);
    CHECK(d3.location < kRelTol * radius);
    CHECK(d3.size < kRelTol * radius);
    CHECK(d3.orientation < kRelTol);
  }
}

TEST_CASE("random spheres on caps down to 30 degrees are their exact least-squares fits", "[fit][random]") {
  WorstFit w{"sphere"};
  for (int seed = 0; seed < draw_count(); ++seed) {
    Rng rng(3000 + seed);
    const double radius = rng.uniform(1, 200);
    const Eigen::Vector3d c = random_point(rng);
    const auto s = sphere_samples(rng, c, radius, rng.unit_vector(), deg(rng.uniform(30, 180)), count(rng, 4),
                                  rng.uniform(0, 0.01) * radius);
    auto f = fit_sphere(s.points);
    INFO("seed " << seed);
    REQUIRE(f.ok());
    Eigen::MatrixXd J(static_cast<Eigen::Index>(s.points.size()), 4);
    Eigen::VectorXd r(J.rows());
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      const Eigen::Vector3d d = s.points[static_cast<std::size_t>(i)] - f->center;
      r(i) = d.norm() - f->radius();
      J.row(i) << -d.transpose() / d.norm(), -1.0;
    }
    Deviation d;
    d.location = (f->center - c).norm();
    d.size = std::abs(f->diameter - 2 * radius);
    const double cos = cosine_if_residual(J, r, radius);
    w.add(d, radius, cos);
    CHECK(d.location < kRelTol * radius);
    CHECK(d.size < kRelTol * radius);
    CHECK(cos < kCosTol);
  }
}

// The deviation amplitude of a draw: a quarter of the draws are exact.
double amplitude(Rng& rng, double size) { return rng.uniform(0, 1) < 0.25 ? 0.0 : rng.uniform(0, 0.01) * size; }

// Whether a result that is not the generator is still right: data with deviations, a sum of
// squares no larger than the generator's (then it is that minimum or a lower one).
bool no_worse(double ssq, double ssq_truth, double amp) { return amp > 0.0 && ssq <= ssq_truth * (1.0 + 1e-9); }

TEST_CASE("random cylinders on sectors down to 30 degrees are their exact least-squares fits", "[fit][random]") {
  WorstFit w{"cylinder"};
  for (int seed = 0; seed < draw_count(); ++seed) {
    Rng rng(4000 + seed);
    const double radius = rng.uniform(1, 200);
    const Eigen::Vector3d c = random_point(rng);
    const Eigen::Vector3d axis = rng.unit_vector();
    const std::size_t n = count(rng, kMinPointsCylinder);
    const double span = rng.uniform(30, 360);
    const double length = rng.uniform(0.3, 3) * radius;
    const double amp = amplitude(rng, radius);
    const auto s = cylinder_samples(rng, c, axis, radius, deg(span), length, n, amp);
    auto f = fit_cylinder(s.points);
    INFO("seed " << seed << " points " << n << " span " << span << " amplitude " << amp);
    if (n == kMinPointsCylinder) {  // several cylinders pass through 5 points: always refused
      REQUIRE_FALSE(f.ok());
      CHECK(f.error().code == FitErrorCode::AmbiguousSolution);
      ++w.ambiguous;
      continue;
    }
    REQUIRE(f.ok());
    Cylinder truth;
    truth.point = c;
    truth.direction = axis;
    truth.diameter = 2 * radius;
    Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 7);
    Eigen::VectorXd r(J.rows());
    for (Eigen::Index i = 0; i < J.rows(); ++i) {
      const Eigen::Vector3d p = s.points[static_cast<std::size_t>(i)];
      const Eigen::Vector3d radial = (p - f->point) - (p - f->point).dot(f->direction) * f->direction;
      r(i) = radial.norm() - f->radius();
      rigid_row(J, i, p, f->point, radial.normalized());
      J(i, 6) = -1.0;
    }
    const Deviation d = compare(*f, truth);
    const double cos = cosine_if_residual(J, r, radius);
    CHECK(cos < kCosTol);  // always a least-squares stationary point
    if (d.location < kRelTol * radius && d.size < kRelTol * radius && d.orientation < kRelTol) {
      w.add(d, radius, cos);
      continue;
    }
    double ssq_truth = 0.0;
    for (const auto& p : s.points) ssq_truth += std::pow(truth.distance_from_axis(p) - radius, 2);
    if (no_worse(r.squaredNorm(), ssq_truth, amp)) {
      w.cosine = std::max(w.cosine, cos);
      if (r.squaredNorm() < ssq_truth * (1.0 - 1e-9)) ++w.lower;
      continue;
    }
    ++w.misses;
    WARN("cylinder seed " << seed << " (" << n << " points): a worse minimum, rms " << f->stats.rms);
  }
  CHECK(w.misses == 0);
}

namespace {

// One cone of the generator: apex 10 to 120 degrees, a sector of 30 to 360 degrees and a band of
// 0.2 to 1.5 radii, drawn from Rng(seed), fitted and judged. Minimal sets must be refused; others
// must give the generator, or (data with deviations) a stationary point no worse than it, or be
// refused as a cylinder that fits no worse than it.
void check_random_cone(std::uint64_t seed, WorstFit& w) {
  Rng rng(seed);
  Cone truth;
  truth.direction = rng.unit_vector();
  truth.point = random_point(rng);
  truth.apex_angle_rad = deg(rng.uniform(10, 120));
  const double radius = rng.uniform(2, 100);
  truth.distance = radius * std::cos(truth.half_angle());
  const std::size_t n = count(rng, kMinPointsCone);
  const double h0 = rng.uniform(-0.5, 0.5) * radius;
  const double span = rng.uniform(30, 360);
  const double h1 = h0 + rng.uniform(0.2, 1.5) * radius;
  const double amp = amplitude(rng, radius);
  const auto s = cone_samples(rng, truth, deg(span), h0, h1, n, amp);
  auto f = fit_cone(s.points);
  INFO("seed " << seed << " points " << n << " span " << span << " amplitude " << amp);
  if (n == kMinPointsCone) {  // several cones pass through 6 points: always refused
    REQUIRE_FALSE(f.ok());
    CHECK(f.error().code == FitErrorCode::AmbiguousSolution);
    ++w.ambiguous;
    return;
  }
  double ssq_truth = 0.0;
  for (const auto& p : s.points) ssq_truth += std::pow(cone_row(truth, p, nullptr, 0), 2);
  if (!f.ok()) {
    // Refusing a cone as a cylinder is right when a cylinder fits the points at least as well as
    // the generator (a narrow band with deviations); every other refusal is a miss.
    if (f.error().code == FitErrorCode::ConeIsCylinder) {
      const auto cyl = fit_cylinder(s.points);
      double ssq_cyl = std::numeric_limits<double>::infinity();
      if (cyl.ok()) {
        ssq_cyl = 0.0;
        for (const auto& p : s.points) ssq_cyl += std::pow(cyl->distance_from_axis(p) - cyl->radius(), 2);
      }
      if (no_worse(ssq_cyl, ssq_truth, amp)) {
        ++w.cylinders;
        return;
      }
    }
    ++w.misses;
    WARN("cone seed " << seed << " (" << n << " points): refused, " << f.error().message);
    return;
  }
  Eigen::MatrixXd J(static_cast<Eigen::Index>(n), 8);
  Eigen::VectorXd r(J.rows());
  for (Eigen::Index i = 0; i < J.rows(); ++i) r(i) = cone_row(*f, s.points[static_cast<std::size_t>(i)], &J, i);
  const Deviation d = compare(*f, truth);
  const double cos = cosine_if_residual(J, r, radius);
  CHECK(cos < kCosTol);  // always a least-squares stationary point
  if (d.location < kRelTol * radius && d.size < kRelTol * radius && d.orientation < kRelTol && d.apex_angle < kRelTol) {
    w.add(d, radius, cos);
    return;
  }
  if (no_worse(r.squaredNorm(), ssq_truth, amp)) {
    w.cosine = std::max(w.cosine, cos);
    if (r.squaredNorm() < ssq_truth * (1.0 - 1e-9)) ++w.lower;
    return;
  }
  ++w.misses;
  WARN("cone seed " << seed << " (" << n << " points): a worse minimum, rms " << f->stats.rms);
}

}  // namespace

TEST_CASE("random cones (apex 10 to 120 degrees, sectors and height bands) are their exact fits", "[fit][random]") {
  WorstFit w{"cone"};
  for (int i = 0; i < draw_count(); ++i) check_random_cone(5000 + static_cast<std::uint64_t>(i), w);
  CHECK(w.misses == 0);
}

TEST_CASE("cones of the wider random check that were once missed or not converged are their exact fits",
          "[fit][random]") {
  // Draws of the same generator beyond the 500 above (docs/metrology.md 2.7), each one a failure of
  // an earlier state: the grid search missing the generator's basin (5583 6165 6304 6682 7275 7573
  // 101687 103834 103969; 100047 and 304845 by trial versions of the screened search),
  // Gauss–Newton crawling at large residuals until the iteration cap (6387 100015 101877 102199
  // 104004 203921 204324 304669 504436), the last step at the rounding floor refused (101617),
  // minimal sets on which no start converged (8588 102158 504596).
  const std::uint64_t seeds[] = {5583,   6165,   6304,   6682,   7275,   7573,   100047, 101687, 103834, 103969,
                                 304845, 6387,   100015, 101877, 102199, 104004, 203921, 204324, 304669, 504436,
                                 101617, 8588,   102158, 504596};
  WorstFit w{"cone+", static_cast<int>(std::size(seeds))};
  for (const std::uint64_t seed : seeds) check_random_cone(seed, w);
  CHECK(w.misses == 0);
}
