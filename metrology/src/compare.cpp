// ISO 10360-6 style comparison metrics between a tested and a reference fit.
#include "imess/metrology/compare.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace imess::metrology {
namespace {

template <class V>
double angle_between(const V& a, const V& b) {
  const V ua = a.normalized();
  V ub = b.normalized();
  if (ua.dot(ub) < 0.0) ub = -ub;
  // asin argument can exceed 1 only by rounding (|a-b| <= sqrt(2) after the flip).
  return 2.0 * std::asin(std::min(1.0, 0.5 * (ua - ub).norm()));
}

Eigen::Vector3d lift(const Eigen::Vector2d& v) { return {v.x(), v.y(), 0.0}; }

double axis_location(const Eigen::Vector3d& tp, const Eigen::Vector3d& td, const Eigen::Vector3d& rp,
                     const Eigen::Vector3d& rd) {
  return std::max(point_line_distance(tp, rp, rd), point_line_distance(rp, tp, td));
}

}  // namespace

double direction_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b) { return angle_between(a, b); }
double direction_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b) { return angle_between(a, b); }

double point_line_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& point,
                           const Eigen::Vector3d& direction) {
  return direction.normalized().cross(p - point).norm();
}

Deviation compare(const Line2& tested, const Line2& reference) {
  Deviation d;
  d.location = axis_location(lift(tested.point), lift(tested.direction), lift(reference.point),
                             lift(reference.direction));
  d.orientation = direction_angle(tested.direction, reference.direction);
  return d;
}

Deviation compare(const Line3& tested, const Line3& reference) {
  Deviation d;
  d.location = axis_location(tested.point, tested.direction, reference.point, reference.direction);
  d.orientation = direction_angle(tested.direction, reference.direction);
  return d;
}

Deviation compare(const Plane& tested, const Plane& reference) {
  Deviation d;
  d.location = std::max(std::abs(reference.normal.normalized().dot(tested.point - reference.point)),
                        std::abs(tested.normal.normalized().dot(reference.point - tested.point)));
  d.orientation = direction_angle(tested.normal, reference.normal);
  return d;
}

Deviation compare(const Circle2& tested, const Circle2& reference) {
  Deviation d;
  d.location = (tested.center - reference.center).norm();
  d.size = std::abs(tested.diameter - reference.diameter);
  return d;
}

Deviation compare(const Circle3& tested, const Circle3& reference) {
  Deviation d;
  d.location = (tested.center - reference.center).norm();
  d.orientation = direction_angle(tested.normal, reference.normal);
  d.size = std::abs(tested.diameter - reference.diameter);
  return d;
}

Deviation compare(const Sphere& tested, const Sphere& reference) {
  Deviation d;
  d.location = (tested.center - reference.center).norm();
  d.size = std::abs(tested.diameter - reference.diameter);
  return d;
}

Deviation compare(const Cylinder& tested, const Cylinder& reference) {
  Deviation d;
  d.location = axis_location(tested.point, tested.direction, reference.point, reference.direction);
  d.orientation = direction_angle(tested.direction, reference.direction);
  d.size = std::abs(tested.diameter - reference.diameter);
  return d;
}

Deviation compare(const Cone& tested, const Cone& reference) {
  Deviation d;
  d.location = axis_location(tested.point, tested.direction, reference.point, reference.direction);
  d.orientation = direction_angle(tested.direction, reference.direction);
  Cone t = tested;
  t.direction.normalize();
  Cone r = reference;
  r.direction.normalize();
  d.size = 2.0 * std::abs(t.moved_to(r.point).radius_at(0.0) - r.radius_at(0.0));
  d.apex_angle = std::abs(tested.apex_angle_rad - reference.apex_angle_rad);
  return d;
}

}  // namespace imess::metrology
