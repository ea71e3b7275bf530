// Circle fits: 2-D directly; 3-D as NIST defines it (least-squares plane, projection of the
// points into that plane, 2-D circle in plane coordinates).
#include <vector>

#include "ball_fit.hpp"
#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"

namespace imess::metrology {

Fit<Circle2> fit_circle2d(std::span<const Eigen::Vector2d> points, const FitOptions& options) {
  auto ball = detail::fit_ball<2>(points, kMinPointsCircle, "circle2d", options);
  if (!ball) return ball.error();
  Circle2 c;
  c.center = ball->center;
  c.diameter = 2.0 * ball->radius;
  c.stats = ball->stats;
  return c;
}

Fit<Circle3> fit_circle3d(std::span<const Eigen::Vector3d> points, const FitOptions& options) {
  constexpr std::string_view kName = "circle3d";
  if (auto e = detail::check_input<3>(points, kMinPointsCircle, kName)) return *e;
  const auto pa = detail::principal_axes<3>(points);
  if (auto e = detail::check_spread<3>(pa, points.size(), 2, kName)) return *e;

  const Eigen::Vector3d normal = detail::canonical_sign(Eigen::Vector3d(pa.axes.col(2).normalized()));
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  detail::perpendicular_basis(normal, u, v);
  std::vector<Eigen::Vector2d> in_plane(points.size());
  Eigen::VectorXd off_plane(static_cast<Eigen::Index>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector3d d = points[i] - pa.centroid;
    in_plane[i] = Eigen::Vector2d(u.dot(d), v.dot(d));
    off_plane(static_cast<Eigen::Index>(i)) = normal.dot(d);
  }
  auto ball = detail::fit_ball<2>(std::span<const Eigen::Vector2d>(in_plane), kMinPointsCircle, kName,
                                  options);
  if (!ball) return ball.error();
  Circle3 c;
  c.center = pa.centroid + u * ball->center.x() + v * ball->center.y();
  c.normal = normal;
  c.diameter = 2.0 * ball->radius;
  c.stats = ball->stats;
  c.plane_stats = detail::make_stats(off_plane, 0);
  return c;
}

}  // namespace imess::metrology
