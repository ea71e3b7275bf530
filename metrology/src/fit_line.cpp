// Line fits (2-D and 3-D): centroid plus principal direction; the exact orthogonal-distance
// least-squares solution, so no iteration.
#include <cmath>

#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"

namespace imess::metrology {

Fit<Line2> fit_line2d(std::span<const Eigen::Vector2d> points) {
  constexpr std::string_view kName = "line2d";
  if (auto e = detail::check_input<2>(points, kMinPointsLine, kName)) return *e;
  const auto pa = detail::principal_axes<2>(points);
  if (auto e = detail::check_spread<2>(pa, points.size(), 1, kName)) return *e;
  Line2 line;
  line.point = pa.centroid;
  line.direction = detail::canonical_sign(Eigen::Vector2d(pa.axes.col(0).normalized()));
  Eigen::VectorXd res(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    res(static_cast<Eigen::Index>(i)) = line.signed_distance(points[i]);
  line.stats = detail::make_stats(res, 0);
  return line;
}

Fit<Line3> fit_line3d(std::span<const Eigen::Vector3d> points) {
  constexpr std::string_view kName = "line3d";
  if (auto e = detail::check_input<3>(points, kMinPointsLine, kName)) return *e;
  const auto pa = detail::principal_axes<3>(points);
  if (auto e = detail::check_spread<3>(pa, points.size(), 1, kName)) return *e;
  Line3 line;
  line.point = pa.centroid;
  line.direction = detail::canonical_sign(Eigen::Vector3d(pa.axes.col(0).normalized()));
  Eigen::VectorXd res(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    res(static_cast<Eigen::Index>(i)) = line.distance(points[i]);
  line.stats = detail::make_stats(res, 0);
  return line;
}

}  // namespace imess::metrology
