// The fitted geometric elements: parameters in the NIST ATS conventions plus residual statistics.
// Lengths in mm (or whatever unit the points are in), angles in radians unless the name says deg.
#pragma once

#include <Eigen/Core>

#include "imess/metrology/fit_result.hpp"

namespace imess::metrology {

// Line in the plane. Residual: signed distance along the left normal (-dir.y, dir.x).
struct Line2 {
  Eigen::Vector2d point;      // centroid of the data
  Eigen::Vector2d direction;  // unit; sign: largest |component| positive
  FitStats stats;
  double signed_distance(const Eigen::Vector2d& p) const;
};

// Line in space. Residual: distance from the line (>= 0, so min_residual is the closest point).
struct Line3 {
  Eigen::Vector3d point;      // centroid of the data
  Eigen::Vector3d direction;  // unit; sign: largest |component| positive
  FitStats stats;
  double distance(const Eigen::Vector3d& p) const;
};

// Plane. Residual: signed distance along the normal.
struct Plane {
  Eigen::Vector3d point;   // centroid of the data
  Eigen::Vector3d normal;  // unit; sign: largest |component| positive (probe compensation
                           // re-orients it to point out of the material)
  FitStats stats;
  double signed_distance(const Eigen::Vector3d& p) const;
};

// Circle in the plane. Residual: distance from the centre minus the radius.
struct Circle2 {
  Eigen::Vector2d center;
  double diameter = 0.0;
  FitStats stats;
  double radius() const noexcept { return 0.5 * diameter; }
};

// Circle in space, fitted as NIST defines it: least-squares plane, points projected into it,
// least-squares circle in that plane. `stats` are the in-plane radial residuals; `plane_stats`
// the out-of-plane ones (flatness of the probed ring).
struct Circle3 {
  Eigen::Vector3d center;  // lies in the fitted plane
  Eigen::Vector3d normal;  // unit, the plane's normal (same sign rule)
  double diameter = 0.0;
  FitStats stats;
  FitStats plane_stats;
  double radius() const noexcept { return 0.5 * diameter; }
};

// Sphere. Residual: distance from the centre minus the radius.
struct Sphere {
  Eigen::Vector3d center;
  double diameter = 0.0;
  FitStats stats;
  double radius() const noexcept { return 0.5 * diameter; }
};

// Cylinder. Residual: distance from the axis minus the radius.
struct Cylinder {
  Eigen::Vector3d point;      // on the axis: foot of the data centroid
  Eigen::Vector3d direction;  // unit; sign: largest |component| positive
  double diameter = 0.0;
  FitStats stats;
  double radius() const noexcept { return 0.5 * diameter; }
  double distance_from_axis(const Eigen::Vector3d& p) const;
};

// Cone, NIST convention: signed distance of p is rho*cos(phi) - h*sin(phi) - distance, with
// h = (p - point)·direction, rho = distance of p from the axis and phi = apex_angle_rad / 2.
// The radius grows along `direction` (the apex is on the -direction side of `point`).
struct Cone {
  Eigen::Vector3d point;      // on the axis: foot of the data centroid
  Eigen::Vector3d direction;  // unit, toward increasing radius
  double distance = 0.0;      // orthogonal distance from `point` to the surface
  double apex_angle_rad = 0.0;  // full apex angle
  FitStats stats;
  double half_angle() const noexcept { return 0.5 * apex_angle_rad; }
  double apex_angle_deg() const noexcept;
  double signed_distance(const Eigen::Vector3d& p) const;
  // Radius of the cone in the cross-section through point + h*direction.
  double radius_at(double h) const;
  // The same cone described from another axis point (its projection onto the axis is used).
  Cone moved_to(const Eigen::Vector3d& axis_point) const;
};

}  // namespace imess::metrology
