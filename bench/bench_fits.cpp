// bench_fits: what the fits cost on scanned point sets (thousands of points with 1 µm noise):
// circle (2-D and in space), plane, sphere, cylinder, at 360, 3 600 and 36 000 points. Each time
// (best of 5) is printed raw and as a ratio to a reference measured in the same run on the same
// points: one pass computing every point's distance from the true centre (or axis / plane), the
// least work any fit of those points must do. The figure: a 3 600-point circle in
// < 10 ms. Prints figures; not a test.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>

#include "imess/metrology/fit.hpp"

using namespace imess::metrology;
using Clock = std::chrono::steady_clock;

namespace {

volatile double g_sink = 0;  // keeps the reference loops from being optimised away
constexpr double kNoise = 0.001;  // mm, 1 µm rms
constexpr int kReps = 5;

double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// A bore as a scan sees it: Ø30 at (450, 350, 40), turned a little out of the XY plane.
struct Scene {
  Eigen::Vector3d centre{450.0, 350.0, 40.0};
  Eigen::Vector3d axis = Eigen::Vector3d(0.01, -0.02, 1.0).normalized();
  double radius = 15.0;
  Eigen::Vector3d u = axis.unitOrthogonal();
  Eigen::Vector3d v = axis.cross(u);
};

std::vector<Eigen::Vector3d> circle_points(const Scene& s, int n, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, kNoise);
  std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * i / n;
    p[static_cast<std::size_t>(i)] =
        s.centre + (s.radius + noise(rng)) * (std::cos(t) * s.u + std::sin(t) * s.v) + noise(rng) * s.axis;
  }
  return p;
}

// A helix of n points over 20 mm of the bore (a scan of the cylinder).
std::vector<Eigen::Vector3d> cylinder_points(const Scene& s, int n, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, kNoise);
  std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(n));
  for (int i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * 10.0 * i / n;
    p[static_cast<std::size_t>(i)] = s.centre + (s.radius + noise(rng)) * (std::cos(t) * s.u + std::sin(t) * s.v) +
                                     (-10.0 + 20.0 * i / n) * s.axis;
  }
  return p;
}

// Circles of latitude from the equator to 60° on a Ø25 sphere.
std::vector<Eigen::Vector3d> sphere_points(const Scene& s, int n, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, kNoise);
  std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(n));
  const int rings = 10;
  for (int i = 0; i < n; ++i) {
    const double lat = std::numbers::pi / 3.0 * (i % rings) / (rings - 1);
    const double lon = 2.0 * std::numbers::pi * (i / rings) / (n / rings);
    const Eigen::Vector3d d = std::cos(lat) * (std::cos(lon) * s.u + std::sin(lon) * s.v) + std::sin(lat) * s.axis;
    p[static_cast<std::size_t>(i)] = s.centre + (12.5 + noise(rng)) * d;
  }
  return p;
}

// A raster over a 100 x 80 mm face.
std::vector<Eigen::Vector3d> plane_points(const Scene& s, int n, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, kNoise);
  std::uniform_real_distribution<double> x(-50.0, 50.0), y(-40.0, 40.0);
  std::vector<Eigen::Vector3d> p(static_cast<std::size_t>(n));
  for (auto& q : p) q = s.centre + x(rng) * s.u + y(rng) * s.v + noise(rng) * s.axis;
  return p;
}

// The reference: every point's distance from the true centre (ball) or axis, one pass.
double reference_ms(const std::vector<Eigen::Vector3d>& pts, const Scene& s) {
  double best = 1e30;
  for (int rep = 0; rep < kReps; ++rep) {
    const auto t0 = Clock::now();
    double acc = 0.0;
    for (const auto& p : pts) {
      const Eigen::Vector3d d = p - s.centre;
      acc += (d - d.dot(s.axis) * s.axis).norm() - s.radius;
    }
    g_sink = acc;
    best = std::min(best, ms_since(t0));
  }
  return best;
}

template <class F>
void row(const char* name, int n, const std::vector<Eigen::Vector3d>& pts, const Scene& s, F fit) {
  double best = 1e30;
  int iterations = 0;
  double rms = 0.0;
  bool ok = true;
  for (int rep = 0; rep < kReps; ++rep) {
    const auto t0 = Clock::now();
    const auto r = fit(pts);
    best = std::min(best, ms_since(t0));
    ok = r.ok();
    if (ok) {
      iterations = r->stats.iterations;
      rms = r->stats.rms;
    }
  }
  const double ref = reference_ms(pts, s);
  std::printf("  %-10s %6d points  %9.3f ms  %7.0f x one distance pass (%7.4f ms)  %2d iterations  rms %.2f um%s\n",
              name, n, best, best / ref, ref, iterations, rms * 1000.0, ok ? "" : "  FAILED");
}

}  // namespace

int main() {
  const Scene s;
  std::mt19937_64 rng(31);
  std::printf("fits on scanned points (1 um noise), best of %d; ratio to one pass of point distances\n", kReps);
  for (const int n : {360, 3600, 36000}) {
    const auto circle = circle_points(s, n, rng);
    std::vector<Eigen::Vector2d> flat(circle.size());
    for (std::size_t i = 0; i < circle.size(); ++i) {
      const Eigen::Vector3d d = circle[i] - s.centre;
      flat[i] = Eigen::Vector2d(d.dot(s.u), d.dot(s.v));
    }
    row("circle2d", n, circle, s, [&](const auto&) { return fit_circle2d(flat); });
    row("circle3d", n, circle, s, [](const auto& p) { return fit_circle3d(p); });
    row("plane", n, plane_points(s, n, rng), s, [](const auto& p) { return fit_plane(p); });
    row("sphere", n, sphere_points(s, n, rng), s, [](const auto& p) { return fit_sphere(p); });
    row("cylinder", n, cylinder_points(s, n, rng), s, [](const auto& p) { return fit_cylinder(p); });
  }
  return 0;
}
