// Plane fit: centroid plus the direction of least spread; the exact orthogonal-distance
// least-squares solution, so no iteration.
#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"

namespace imess::metrology {

Fit<Plane> fit_plane(std::span<const Eigen::Vector3d> points) {
  constexpr std::string_view kName = "plane";
  if (auto e = detail::check_input<3>(points, kMinPointsPlane, kName)) return *e;
  const auto pa = detail::principal_axes<3>(points);
  if (auto e = detail::check_spread<3>(pa, points.size(), 2, kName)) return *e;
  Plane plane;
  plane.point = pa.centroid;
  plane.normal = detail::canonical_sign(Eigen::Vector3d(pa.axes.col(2).normalized()));
  Eigen::VectorXd res(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    res(static_cast<Eigen::Index>(i)) = plane.signed_distance(points[i]);
  plane.stats = detail::make_stats(res, 0);
  return plane;
}

}  // namespace imess::metrology
