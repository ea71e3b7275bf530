// Signed distances of the workpiece primitives (exact forms for box with one rounded edge,
// bore, sphere, shaft, half-space).
#include "imess/sim/scene.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

namespace imess::sim {
namespace {

double len2(double a, double b) { return std::hypot(a, b); }

// Rectangle with half sizes (ha, hb) in the (u, v) plane; the corner in quadrant (su, sv)
// rounded with radius r (r = 0: sharp). Exact signed distance.
double rounded_rect(double u, double v, double ha, double hb, int su, int sv, double r) {
  bool in_quadrant = (u * su > 0) && (v * sv > 0);
  double rr = in_quadrant ? r : 0.0;
  double qa = std::abs(u) - ha + rr, qb = std::abs(v) - hb + rr;
  return len2(std::max(qa, 0.0), std::max(qb, 0.0)) + std::min(std::max(qa, qb), 0.0) - rr;
}

// Extrudes a 2D distance d along a third coordinate with half length ht.
double extrude(double d, double t, double ht) {
  double w = std::abs(t) - ht;
  return std::min(std::max(d, w), 0.0) + len2(std::max(d, 0.0), std::max(w, 0.0));
}

struct Distance {
  const Vec3& p;
  double operator()(const PlaneSolid& s) const { return (p - s.point).dot(s.normal.normalized()); }
  double operator()(const BoxSolid& s) const { return box_distance(s, p); }
  double operator()(const SphereSolid& s) const { return (p - s.center).norm() - s.diameter / 2; }
  double operator()(const CylinderSolid& s) const {
    double dxy = len2(p.x() - s.base.x(), p.y() - s.base.y()) - s.diameter / 2;
    double dz = std::abs(p.z() - (s.base.z() + s.height / 2)) - s.height / 2;
    return std::min(std::max(dxy, dz), 0.0) + len2(std::max(dxy, 0.0), std::max(dz, 0.0));
  }
};

}  // namespace

double box_distance(const BoxSolid& box, const Vec3& p) noexcept {
  double yaw = box.yaw_deg * std::numbers::pi / 180.0;
  double c = std::cos(yaw), s = std::sin(yaw);
  Vec3 d = p - box.center;
  Vec3 q(c * d.x() + s * d.y(), -s * d.x() + c * d.y(), d.z());  // into the box frame
  Vec3 h = box.size / 2;
  double r = box.fillet == FilletEdge::None ? 0.0 : box.fillet_radius;
  double dist = 0;
  switch (box.fillet) {
    case FilletEdge::None:
    case FilletEdge::FrontTop: dist = extrude(rounded_rect(q.y(), q.z(), h.y(), h.z(), -1, 1, r), q.x(), h.x()); break;
    case FilletEdge::BackTop: dist = extrude(rounded_rect(q.y(), q.z(), h.y(), h.z(), 1, 1, r), q.x(), h.x()); break;
    case FilletEdge::LeftTop: dist = extrude(rounded_rect(q.x(), q.z(), h.x(), h.z(), -1, 1, r), q.y(), h.y()); break;
    case FilletEdge::RightTop: dist = extrude(rounded_rect(q.x(), q.z(), h.x(), h.z(), 1, 1, r), q.y(), h.y()); break;
  }
  for (const auto& b : box.bores) dist = std::max(dist, b.diameter / 2 - len2(q.x() - b.x, q.y() - b.y));
  return dist;
}

Scene::Scene(std::vector<Solid> solids) : solids_(std::move(solids)) {}

double Scene::distance(const Vec3& p) const noexcept {
  double d = std::numeric_limits<double>::infinity();
  for (const auto& s : solids_) d = std::min(d, std::visit(Distance{p}, s));
  return d;
}

Scene worked_example_scene() {
  BoxSolid cube;
  cube.center = Vec3(460, 350, 40);
  cube.size = Vec3(120, 100, 80);
  cube.yaw_deg = 0.3;
  cube.fillet = FilletEdge::FrontTop;
  cube.fillet_radius = 10;
  cube.bores = {Bore{0, 0, 30}};
  return Scene({PlaneSolid{Vec3::Zero(), Vec3::UnitZ()}, cube});
}

SphereSolid reference_sphere() { return SphereSolid{Vec3(750, 650, 60), 25}; }

CylinderSolid reference_sphere_stem() {
  const SphereSolid ball = reference_sphere();
  return CylinderSolid{Vec3(ball.center.x(), ball.center.y(), 0), 10, ball.center.z()};
}

Scene default_scene() {
  std::vector<Solid> solids = worked_example_scene().solids();
  solids.push_back(reference_sphere());
  solids.push_back(reference_sphere_stem());
  return Scene(std::move(solids));
}

}  // namespace imess::sim
