// Internal: what the axial features (cylinder, cone) share before the solver — the input
// check, candidate axis directions and, for a given direction, the axis position and radius
// from a circle fit of the projection.
#pragma once

#include <optional>
#include <span>
#include <string_view>
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

// The count, finiteness and spread (in all three directions) of an axial feature's points;
// fills pa on the way. nullopt when the points may be fitted.
std::optional<FitError> check_axial_input(std::span<const Eigen::Vector3d> points, std::size_t min_points,
                                          std::string_view feature, PrincipalAxes<3>& pa);

// One starting state for each candidate axis whose projection gives a position:
// make(axis position, axis direction) builds it. Starts on the subsample qs of the points.
template <class State, class Make>
std::vector<State> axial_starts(const Eigen::Matrix3Xd& qs, const PrincipalAxes<3>& pa, Make make) {
  std::vector<State> starts;
  for (const Eigen::Vector3d& axis : candidate_axes(qs, pa)) {
    if (auto pos = axis_position(qs, axis)) starts.push_back(make(*pos, axis));
  }
  return starts;
}

}  // namespace imess::metrology::detail
