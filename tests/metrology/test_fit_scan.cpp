// Fits on scanned point sets: thousands of points with 1 µm of Gaussian noise, every fit kind,
// random placement, orientation and size (fixed seeds). A least-squares fit of N points with
// noise sigma finds a feature's location and size to about sigma / sqrt(N) (0.02 µm at 3 600
// points): each fit must come within a few times that of the generator, report an rms of sigma
// within 10 % and a form (max - min) of 5 to 10 sigma — what 1 µm of noise makes on a dense scan.
// Arcs and bands (a quarter circle, a 60° cap) are checked too, with bounds scaled by their
// weaker geometry. The speed of these fits is bench_fits' (bench/), not a test's.
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <catch2/catch.hpp>

#include "imess/metrology/fit.hpp"

using namespace imess::metrology;

namespace {

constexpr double kSigma = 0.001;  // mm
constexpr int kScanPoints = 3600;
constexpr std::uint64_t kSeeds = 6;

struct ScanRng {
  explicit ScanRng(std::uint64_t seed) : gen(seed) {}
  std::mt19937_64 gen;
  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(gen); }
  double noise() { return std::normal_distribution<double>(0.0, kSigma)(gen); }
  Eigen::Vector3d direction() {
    Eigen::Vector3d d;
    do d = Eigen::Vector3d(uniform(-1, 1), uniform(-1, 1), uniform(-1, 1));
    while (d.norm() < 0.1 || d.norm() > 1.0);
    return d.normalized();
  }
  Eigen::Vector3d place() { return Eigen::Vector3d(uniform(0, 1000), uniform(0, 1000), uniform(0, 600)); }
};

double angle_between_axes(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  return std::asin(std::min(1.0, a.normalized().cross(b.normalized()).norm()));
}

void check_stats(const FitStats& s) {
  CHECK(s.point_count == static_cast<std::size_t>(kScanPoints));
  CHECK(s.rms > 0.9 * kSigma);
  CHECK(s.rms < 1.1 * kSigma);
  CHECK(s.form() > 5.0 * kSigma);
  CHECK(s.form() < 10.0 * kSigma);
}

// Points on a circle (centre c, axis a, radius r) over `sweep` radians, noise along the radius.
std::vector<Eigen::Vector3d> circle_scan(ScanRng& rng, const Eigen::Vector3d& c, const Eigen::Vector3d& a, double r,
                                         double sweep) {
  const Eigen::Vector3d u = a.unitOrthogonal(), v = a.cross(u);
  const double t0 = rng.uniform(0, 2 * std::numbers::pi);
  std::vector<Eigen::Vector3d> p;
  for (int i = 0; i < kScanPoints; ++i) {
    const double t = t0 + sweep * i / kScanPoints;
    p.push_back(c + (r + rng.noise()) * (std::cos(t) * u + std::sin(t) * v));
  }
  return p;
}

}  // namespace

TEST_CASE("scans: lines and planes of 3 600 noisy points are found to within a few sigma over root N", "[fit][scan]") {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    ScanRng rng(seed);
    const Eigen::Vector3d c = rng.place(), n = rng.direction(), u = n.unitOrthogonal(), v = n.cross(u);
    const double L = rng.uniform(20, 200);
    std::vector<Eigen::Vector3d> face, line;
    std::vector<Eigen::Vector2d> line2;
    for (int i = 0; i < kScanPoints; ++i) {
      const double s = rng.uniform(-L / 2, L / 2), t = rng.uniform(-L / 2, L / 2);
      face.push_back(c + s * u + t * v + rng.noise() * n);
      const double w = L * (i / double(kScanPoints) - 0.5);
      line.push_back(c + w * u + rng.noise() * n);
      line2.push_back(Eigen::Vector2d(w, 3.0 + rng.noise()));
    }
    INFO("seed " << seed << ", size " << L);
    const auto plane = fit_plane(face);
    REQUIRE(plane.ok());
    CHECK(std::abs(plane->signed_distance(c)) < 5 * kSigma / std::sqrt(kScanPoints));
    CHECK(angle_between_axes(plane->normal, n) < 20 * kSigma / (L * std::sqrt(kScanPoints)));
    check_stats(plane->stats);
    const auto l3 = fit_line3d(line);
    REQUIRE(l3.ok());
    CHECK(angle_between_axes(l3->direction, u) < 20 * kSigma / (L * std::sqrt(kScanPoints)));
    CHECK(l3->stats.rms < 1.1 * kSigma);  // unsigned distances in space: no form window
    const auto l2 = fit_line2d(line2);
    REQUIRE(l2.ok());
    CHECK(std::abs(l2->point.y() - 3.0) < 5 * kSigma / std::sqrt(kScanPoints));
    check_stats(l2->stats);
  }
}

TEST_CASE("scans: circles of 3 600 noisy points, full and a quarter arc, in the plane and in space", "[fit][scan]") {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    ScanRng rng(seed);
    const Eigen::Vector3d c = rng.place(), a = rng.direction();
    const double r = rng.uniform(3, 100);
    INFO("seed " << seed << ", radius " << r);
    // A full circle: centre and radius to sigma * sqrt(2 / N) and sigma / sqrt(N).
    const auto full = fit_circle3d(circle_scan(rng, c, a, r, 2 * std::numbers::pi));
    REQUIRE(full.ok());
    CHECK((full->center - c).norm() < 6 * kSigma / std::sqrt(kScanPoints));
    CHECK(std::abs(full->radius() - r) < 5 * kSigma / std::sqrt(kScanPoints));
    CHECK(angle_between_axes(full->normal, a) < 1e-9);  // exactly in plane: the plane fit is exact
    check_stats(full->stats);
    // A quarter arc: the radius and centre trade off along the arc's bisector (about 10 x worse).
    const auto arc = fit_circle3d(circle_scan(rng, c, a, r, std::numbers::pi / 2));
    REQUIRE(arc.ok());
    CHECK((arc->center - c).norm() < 60 * kSigma / std::sqrt(kScanPoints));
    CHECK(std::abs(arc->radius() - r) < 60 * kSigma / std::sqrt(kScanPoints));
    check_stats(arc->stats);
    // 2-D: the same circle in its own plane coordinates.
    std::vector<Eigen::Vector2d> flat;
    for (int i = 0; i < kScanPoints; ++i) {
      const double t = 2 * std::numbers::pi * i / kScanPoints;
      const double rho = r + rng.noise();
      flat.push_back(Eigen::Vector2d(100 + rho * std::cos(t), -50 + rho * std::sin(t)));
    }
    const auto c2 = fit_circle2d(flat);
    REQUIRE(c2.ok());
    CHECK((c2->center - Eigen::Vector2d(100, -50)).norm() < 6 * kSigma / std::sqrt(kScanPoints));
    CHECK(std::abs(c2->radius() - r) < 5 * kSigma / std::sqrt(kScanPoints));
    check_stats(c2->stats);
  }
}

TEST_CASE("scans: spheres of 3 600 noisy points on rings from the equator to 60 degrees", "[fit][scan]") {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    ScanRng rng(seed);
    const Eigen::Vector3d c = rng.place(), pole = rng.direction(), u = pole.unitOrthogonal(), v = pole.cross(u);
    const double r = rng.uniform(5, 50);
    std::vector<Eigen::Vector3d> pts;
    for (int i = 0; i < kScanPoints; ++i) {  // 12 rings of 300 points
      const double lat = std::numbers::pi / 3 * (i % 12) / 11.0, lon = 2 * std::numbers::pi * (i / 12) / 300.0;
      pts.push_back(c + (r + rng.noise()) *
                            (std::cos(lat) * (std::cos(lon) * u + std::sin(lon) * v) + std::sin(lat) * pole));
    }
    INFO("seed " << seed << ", radius " << r);
    const auto s = fit_sphere(pts);
    REQUIRE(s.ok());
    CHECK((s->center - c).norm() < 15 * kSigma / std::sqrt(kScanPoints));  // a cap: weaker along the pole
    CHECK(std::abs(s->radius() - r) < 15 * kSigma / std::sqrt(kScanPoints));
    check_stats(s->stats);
  }
}

TEST_CASE("scans: cylinders (a helix) and cones (rings) of 3 600 noisy points", "[fit][scan]") {
  for (std::uint64_t seed = 1; seed <= kSeeds; ++seed) {
    ScanRng rng(seed);
    const Eigen::Vector3d c = rng.place(), a = rng.direction(), u = a.unitOrthogonal(), v = a.cross(u);
    const double r = rng.uniform(3, 50), len = rng.uniform(10, 60);
    const double half = rng.uniform(10, 45) * std::numbers::pi / 180;  // cone: half apex angle
    const double rk = r + len / 2 * std::tan(half);  // cone: its radius at c, so the band stays clear of the apex
    std::vector<Eigen::Vector3d> cyl, cone;
    for (int i = 0; i < kScanPoints; ++i) {
      const double t = 2 * std::numbers::pi * 10 * i / kScanPoints, h = len * (i / double(kScanPoints) - 0.5);
      const Eigen::Vector3d radial = std::cos(t) * u + std::sin(t) * v;
      cyl.push_back(c + h * a + (r + rng.noise()) * radial);
      // cone surface: radius r + h tan(half); noise along the surface normal
      const Eigen::Vector3d normal = std::cos(half) * radial - std::sin(half) * a;
      cone.push_back(c + h * a + (rk + h * std::tan(half)) * radial + rng.noise() * normal);
    }
    INFO("seed " << seed << ", radius " << r << ", length " << len << ", half angle " << half);
    const auto fc = fit_cylinder(cyl);
    REQUIRE(fc.ok());
    CHECK(fc->distance_from_axis(c) < 10 * kSigma / std::sqrt(kScanPoints));
    CHECK(angle_between_axes(fc->direction, a) < 40 * kSigma / (len * std::sqrt(kScanPoints)));
    CHECK(std::abs(fc->radius() - r) < 5 * kSigma / std::sqrt(kScanPoints));
    check_stats(fc->stats);
    const auto fk = fit_cone(cone);
    REQUIRE(fk.ok());
    CHECK(std::abs(fk->radius_at((c - fk->point).dot(fk->direction)) - rk) < 20 * kSigma / std::sqrt(kScanPoints));
    CHECK(angle_between_axes(fk->direction, a) < 60 * kSigma / (len * std::sqrt(kScanPoints)));
    CHECK(std::abs(fk->half_angle() - half) < 60 * kSigma / (len * std::sqrt(kScanPoints)));
    check_stats(fk->stats);
  }
}
