// Comparison of a tested fit with a reference fit in the style of ISO 10360-6: location,
// orientation and size differences (mm, rad, mm). Used by the reference-data tests and by
// anything that checks a fitter against known results.
#pragma once

#include <Eigen/Core>

#include "imess/metrology/features.hpp"

namespace imess::metrology {

struct Deviation {
  double location = 0.0;     // mm, see compare() for the per-feature definition
  double orientation = 0.0;  // rad, angle between the directions/normals after fixing the sign
  double size = 0.0;         // mm, |delta diameter| (0 for lines and planes)
  double apex_angle = 0.0;   // rad, |delta full apex angle| (cones only)
};

// 2*asin(|a - b|/2) with b flipped onto a's hemisphere first; a and b need not be unit.
double direction_angle(const Eigen::Vector3d& a, const Eigen::Vector3d& b);
double direction_angle(const Eigen::Vector2d& a, const Eigen::Vector2d& b);

// Distance of p from the line through `point` with direction `direction` (not necessarily unit).
double point_line_distance(const Eigen::Vector3d& p, const Eigen::Vector3d& point,
                           const Eigen::Vector3d& direction);

// Location for point features (circles, sphere): distance between the centres.
// Location for lines and axes (line, cylinder, cone): the larger of (tested point to reference
// line) and (reference point to tested line). Both are the distance of a point from a line, so
// the choice of point along the axis does not matter; taking the larger is stricter than either.
// Location for planes: the larger of (tested point to reference plane) and (reference point to
// tested plane).
// Size for cones: |delta diameter| of the cross-sections through the reference point's foot.
Deviation compare(const Line2& tested, const Line2& reference);
Deviation compare(const Line3& tested, const Line3& reference);
Deviation compare(const Plane& tested, const Plane& reference);
Deviation compare(const Circle2& tested, const Circle2& reference);
Deviation compare(const Circle3& tested, const Circle3& reference);
Deviation compare(const Sphere& tested, const Sphere& reference);
Deviation compare(const Cylinder& tested, const Cylinder& reference);
Deviation compare(const Cone& tested, const Cone& reference);

}  // namespace imess::metrology
