// Sphere fit: linear start, then Levenberg–Marquardt on the geometric residuals.
#include "ball_fit.hpp"
#include "imess/metrology/fit.hpp"

namespace imess::metrology {

Fit<Sphere> fit_sphere(std::span<const Eigen::Vector3d> points, const FitOptions& options) {
  auto ball = detail::fit_ball<3>(points, kMinPointsSphere, "sphere", options);
  if (!ball) return ball.error();
  Sphere s;
  s.center = ball->center;
  s.diameter = 2.0 * ball->radius;
  s.stats = ball->stats;
  return s;
}

}  // namespace imess::metrology
