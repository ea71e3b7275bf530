// Internal: what the axial features (cylinder, cone) share — the input check, candidate axis
// directions and, for a given direction, the axis position and radius from a circle fit of
// the projection; and the solver's local frame at the axis.
#pragma once

#include <cmath>
#include <limits>
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

// Closed-form surface for a fixed axis direction (centred points q, unit axis a): the axis
// point (foot of the origin), the radius at the origin's cross-section, the radius slope
// (0 for a cylinder, tan(half apex angle) for a cone) and the sum of squared orthogonal
// distances of q from that surface — the score of the direction in the start search.
struct DirectionFit {
  Eigen::Vector3d point;
  double radius = 0.0;
  double slope = 0.0;
  double score = 0.0;
};
// Cylinder: algebraic (Kasa) circle of the projection. nullopt when the projection is collinear.
std::optional<DirectionFit> cylinder_on_direction(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& a);
// Cone: x^2 + y^2 = 2 c.(x, y) + A h + B h^2 + C is linear in (c, A, B, C) for a fixed axis
// direction; its c and the straight line rho = radius + slope * h start a Gauss–Newton
// iteration on the distances rho(c) - radius - slope * h (the axis direction held), so the
// score is that of the best cone about this direction. nullopt when degenerate.
std::optional<DirectionFit> cone_on_direction(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& a);

// Number of directions of the start search grid (a Fibonacci lattice on the half sphere, axis
// directions having no sign): about 9 degrees apart.
inline constexpr int kDirectionGrid = 256;
// Directions of the grid where `fit_on` scores a local minimum (no better neighbour within
// 2.5 grid spacings), best first, at most `keep` of them.
template <class FitOn>
std::vector<Eigen::Vector3d> grid_directions(const Eigen::Matrix3Xd& q, FitOn fit_on, std::size_t keep);
std::vector<Eigen::Vector3d> hemisphere_directions(int count);
std::vector<std::size_t> local_minima(const std::vector<Eigen::Vector3d>& dirs, const std::vector<double>& score,
                                      double neighbour_cos, std::size_t keep);

// The grid is coarse: the solver's basin about a narrow-sector or few-point solution can be
// smaller than a grid spacing, and descent from a grid direction may lead to another minimum.
// So each kept grid minimum is re-sampled on a 9 x 9 tangent grid of +-1 spacing about it, then
// on a 9 x 9 grid of +-1/4 of that about the best, and so on three times: the start is the best
// direction found (about 0.03 degrees apart at the end), not the end of a descent.
template <class FitOn>
Eigen::Vector3d refine_direction(const Eigen::Matrix3Xd& q, FitOn fit_on, Eigen::Vector3d d, double score) {
  double half = std::sqrt(2.0 * 3.141592653589793 / kDirectionGrid);
  for (int round = 0; round < 3; ++round, half *= 0.25) {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    perpendicular_basis(d, u, v);
    const Eigen::Vector3d centre = d;
    for (int i = -4; i <= 4; ++i) {
      for (int j = -4; j <= 4; ++j) {
        if (i == 0 && j == 0) continue;
        const Eigen::Vector3d trial = (centre + half * 0.25 * (i * u + j * v)).normalized();
        const auto f = fit_on(q, trial);
        if (f && f->score < score) {
          d = trial;
          score = f->score;
        }
      }
    }
  }
  return d;
}

template <class FitOn>
std::vector<Eigen::Vector3d> grid_directions(const Eigen::Matrix3Xd& q, FitOn fit_on, std::size_t keep) {
  static const std::vector<Eigen::Vector3d> grid = hemisphere_directions(kDirectionGrid);
  static const double neighbour_cos = std::cos(2.5 * std::sqrt(2.0 * 3.141592653589793 / kDirectionGrid));
  std::vector<double> score(grid.size());
  for (std::size_t i = 0; i < grid.size(); ++i) {
    const auto f = fit_on(q, grid[i]);
    score[i] = f && std::isfinite(f->score) ? f->score : std::numeric_limits<double>::infinity();
  }
  std::vector<Eigen::Vector3d> out;
  for (std::size_t i : local_minima(grid, score, neighbour_cos, keep))
    out.push_back(refine_direction(q, fit_on, grid[i], score[i]));
  return out;
}

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

// Grid directions kept for the start search (besides the candidate axes).
inline constexpr std::size_t kGridStarts = 8;

// The starting axis directions for centred points qs (a subsample of at most kStartSample):
// the candidate axes, then the best local minima of fit_on's score over the direction grid.
template <class FitOn>
std::vector<Eigen::Vector3d> start_directions(const Eigen::Matrix3Xd& qs, const PrincipalAxes<3>& pa, FitOn fit_on) {
  std::vector<Eigen::Vector3d> dirs = candidate_axes(qs, pa);
  for (const auto& d : grid_directions(qs, fit_on, kGridStarts)) dirs.push_back(d);
  return dirs;
}

}  // namespace imess::metrology::detail
