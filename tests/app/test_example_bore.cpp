// examples/programs/bore-inspection.ngc against the default simulated CMM
// (config/sim-servo-card.json): every G38.2 starts on the bore's axis at half height and runs
// radially out past where the ball must touch the wall of the scene's bore; the touch points,
// found in the scene itself, compensated by the tip radius as messd reports a Hit, lie on the
// bore and fit its circle within 1 µm; no other move comes near the part.
#include <catch2/catch.hpp>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "example_bench.hpp"

using namespace imess;
using namespace imess::test;

namespace {

struct BoreOf {
  hal::Vec3 centre;  // on the axis at half the block's height
  double radius = 0;
};

// The scene's one bore (a box with one bore), in machine coordinates.
BoreOf the_bore(const sim::Scene& scene) {
  std::optional<BoreOf> found;
  for (const auto& solid : scene.solids()) {
    const auto* box = std::get_if<sim::BoxSolid>(&solid);
    if (!box || box->bores.empty()) continue;
    REQUIRE_FALSE(found);
    REQUIRE(box->bores.size() == 1);
    const double yaw = box->yaw_deg * M_PI / 180;
    const auto& bore = box->bores[0];
    found = BoreOf{box->center + hal::Vec3(std::cos(yaw) * bore.x - std::sin(yaw) * bore.y,
                                           std::sin(yaw) * bore.x + std::cos(yaw) * bore.y, 0),
                   bore.diameter / 2};
  }
  REQUIRE(found);
  return *found;
}

// Where the ball first touches the scene on the straight way from a to b, if it does.
std::optional<hal::Vec3> first_touch(const sim::Scene& scene, double ball, const hal::Vec3& a, const hal::Vec3& b) {
  const int n = static_cast<int>(std::ceil((b - a).norm() / 0.01));
  auto touches = [&](double f) { return scene.distance(a + f * (b - a)) <= ball; };
  if (touches(0)) return a;
  for (int k = 1; k <= n; ++k) {
    if (!touches(double(k) / n)) continue;
    double lo = double(k - 1) / n, hi = double(k) / n;
    for (int i = 0; i < 60; ++i) (touches((lo + hi) / 2) ? hi : lo) = (lo + hi) / 2;
    return a + hi * (b - a);
  }
  return std::nullopt;
}

// The least-squares circle through points in a horizontal plane: x² + y² + D x + E y + F = 0.
BoreOf fit_circle(const std::vector<hal::Vec3>& pts) {
  Eigen::MatrixXd M(pts.size(), 3);
  Eigen::VectorXd rhs(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) {
    M.row(i) << pts[i].x(), pts[i].y(), 1;
    rhs[i] = -(pts[i].x() * pts[i].x() + pts[i].y() * pts[i].y());
  }
  const Eigen::Vector3d s = M.colPivHouseholderQr().solve(rhs);
  const hal::Vec3 c(-s[0] / 2, -s[1] / 2, pts[0].z());
  return {c, std::sqrt(c.x() * c.x() + c.y() * c.y() - s[2])};
}

}  // namespace

TEST_CASE("examples: bore-inspection.ngc on the simulated CMM — probes from the bore's axis hit its wall, the hits fit the bore within 1 µm") {
  ExampleBench b("sim-servo-card.json", "bore-inspection.ngc");
  const BoreOf bore = the_bore(b.scene());
  const double ball = b.ball_radius(), tip = b.tip_radius();
  REQUIRE(tip == ball);  // messd compensates by the ball the simulated stylus carries
  const auto t = b.translation();
  INFO(t.error.message());
  REQUIRE(t.ok);

  // Each probe: from the axis at half height, radially outward, to a target past the touch.
  std::vector<programs::Item> as_run;  // each probe ends where the ball touches, as it will
  std::vector<hal::Vec3> hits;
  std::vector<double> angles;
  planner::Pose here = b.setup.start;
  for (const auto& item : t.items) {
    programs::Item run = item;
    if (const auto* p = std::get_if<programs::Probe>(&item.step)) {
      const hal::Vec3 from = xyz(here), to = xyz(p->target);
      CHECK(p->error_on_miss);  // G38.2
      CHECK((from - bore.centre).norm() < 1e-9);
      CHECK(to.z() == Approx(bore.centre.z()).margin(1e-9));
      const auto touch = first_touch(b.scene(), ball, from, to);
      REQUIRE(touch);
      const hal::Vec3 dir = (to - from).normalized();
      // The target lies past the touch (the probe hits), by at most 2 mm ("a little").
      const double past = (to - *touch).norm();
      CHECK(past > 0.5);
      CHECK(past <= 2.0);
      hits.push_back(*touch + tip * dir);
      angles.push_back(std::atan2(dir.y(), dir.x()));
      auto ran = *p;
      ran.target = here;
      for (int a = 0; a < 3; ++a) ran.target[a] = (*touch)[a];
      run.step = ran;
      here = ran.target;
    } else if (const auto* l = std::get_if<planner::Line>(&item.step)) {
      here = l->target;
    }
    as_run.push_back(run);
  }
  CHECK(hits.size() == 8);
  REQUIRE(hits.size() >= 6);
  // Spread round the wall: no gap between neighbouring directions wider than 90°.
  std::sort(angles.begin(), angles.end());
  double widest = angles.front() + 2 * M_PI - angles.back();
  for (std::size_t i = 1; i < angles.size(); ++i) widest = std::max(widest, angles[i] - angles[i - 1]);
  CHECK(widest < M_PI / 2);
  // Every compensated hit on the wall; their circle is the bore.
  for (const auto& h : hits) CHECK(std::hypot(h.x() - bore.centre.x(), h.y() - bore.centre.y()) == Approx(bore.radius).margin(1e-6));
  const BoreOf fitted = fit_circle(hits);
  CHECK((fitted.centre - bore.centre).norm() < 1e-6);
  CHECK(fitted.radius == Approx(bore.radius).margin(1e-6));
  CHECK(programs::end_pose(t.items, b.setup.start) == b.setup.start);

  // The program as it will run (each probe stopping at its touch) passes the dry run, and no
  // move but a probe comes within 1 mm of the part; the way back from a touch leaves the wall
  // at once (as far from it as it has gone, up to that 1 mm).
  double worst = INFINITY;  // clearance beyond what is needed, least over every point
  bool after_probe = false;
  const auto c = programs::check_items(as_run, b.setup.machine, b.options, b.setup.start, 0,
                                       [&](const planner::PlannedSegment& seg, const programs::Item& item) {
                                         const bool probe = std::holds_alternative<programs::Probe>(item.step);
                                         if (!probe) {
                                           each_point(seg, !after_probe, [&](const planner::Pose& p) {
                                             const double gone = (xyz(p) - xyz(seg.start)).norm();
                                             const double need = after_probe ? std::min(gone, 1.0) : 1.0;
                                             worst = std::min(worst, b.scene().distance(xyz(p)) - ball - need);
                                           });
                                         }
                                         if (seg.length > 0) after_probe = probe;
                                       });
  INFO(c.error);
  REQUIRE(c.ok);
  CHECK(worst >= -1e-6);
  // The unchanged program passes the dry run too (messd's Load: probes as misses to the target).
  const auto whole = b.check();
  INFO(whole.error);
  CHECK(whole.ok);
  b.report(whole);
}
