// Internal: what the axial features (cylinder, cone) share — the input check, candidate axis
// directions and, for a given direction, the axis position and radius from a circle fit of
// the projection; and the solver's local frame at the axis.
#pragma once

#include <cmath>
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

// A point d (relative to the axis point) in the local frame [u v a] of an axis a: x and y
// across the axis, z along it, rho the distance from it.
struct AxialCoordinates {
  double x, y, z, rho;
};

inline AxialCoordinates axial_coordinates(const Eigen::Vector3d& u, const Eigen::Vector3d& v,
                                          const Eigen::Vector3d& a, const Eigen::Vector3d& d) {
  const double x = u.dot(d);
  const double y = v.dot(d);
  return {x, y, a.dot(d), std::hypot(x, y)};
}

// The axis (point c, direction a) moved by the first four step parameters: shift along u and
// v, tilt toward u and v, in the local frame [u v a].
inline void step_axis(const Eigen::Vector3d& c, const Eigen::Vector3d& a, const Eigen::VectorXd& delta,
                      Eigen::Vector3d& new_c, Eigen::Vector3d& new_a) {
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  perpendicular_basis(a, u, v);
  new_c = c + delta(0) * u + delta(1) * v;
  new_a = (a + delta(2) * u + delta(3) * v).normalized();
}

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
