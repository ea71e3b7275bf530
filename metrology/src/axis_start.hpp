// Internal: starting values for the axial features (cylinder, cone) — candidate axis directions
// and, for a given direction, the axis position and radius from a circle fit of the projection.
#pragma once

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "fit_common.hpp"

namespace imess::metrology::detail {

// Candidate axis directions for centred points q: the three principal axes and, when there are
// at least 10 points, the distinguished axis of an algebraic quadric fit.
std::vector<Eigen::Vector3d> candidate_axes(const Eigen::Matrix3Xd& q, const PrincipalAxes<3>& pa);

struct AxisPosition {
  Eigen::Vector3d point;  // on the axis, foot of the origin (centroid), centred coordinates
  double radius = 0.0;
};

// Circle fit of the points projected onto the plane perpendicular to `axis` (unit); nullopt if
// the projection is degenerate (collinear) or the circle fit fails.
std::optional<AxisPosition> axis_position(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& axis);

}  // namespace imess::metrology::detail
