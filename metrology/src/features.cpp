// Geometry helpers of the fitted elements (distances, cone re-description).
#include "imess/metrology/features.hpp"

#include <cmath>
#include <numbers>

#include <Eigen/Geometry>

namespace imess::metrology {

double Line2::signed_distance(const Eigen::Vector2d& p) const {
  const Eigen::Vector2d normal(-direction.y(), direction.x());
  return normal.dot(p - point);
}

double Line3::distance(const Eigen::Vector3d& p) const { return direction.cross(p - point).norm(); }

double Plane::signed_distance(const Eigen::Vector3d& p) const { return normal.dot(p - point); }

double Cylinder::distance_from_axis(const Eigen::Vector3d& p) const {
  return direction.cross(p - point).norm();
}

double Cone::apex_angle_deg() const noexcept { return apex_angle_rad * 180.0 / std::numbers::pi; }

double Cone::signed_distance(const Eigen::Vector3d& p) const {
  const Eigen::Vector3d d = p - point;
  const double h = d.dot(direction);
  const double rho = direction.cross(d).norm();
  const double phi = half_angle();
  return rho * std::cos(phi) - h * std::sin(phi) - distance;
}

double Cone::radius_at(double h) const {
  const double phi = half_angle();
  return (distance + h * std::sin(phi)) / std::cos(phi);
}

Cone Cone::moved_to(const Eigen::Vector3d& axis_point) const {
  Cone c = *this;
  const double t = (axis_point - point).dot(direction);
  c.point = point + t * direction;
  c.distance = distance + t * std::sin(half_angle());
  return c;
}

}  // namespace imess::metrology
