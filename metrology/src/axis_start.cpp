// Starting axes for cylinder and cone fits: input check, principal axes, quadric axis,
// projected circle.
#include "axis_start.hpp"

#include <cmath>
#include <span>

#include <Eigen/Eigenvalues>
#include <Eigen/SVD>

#include "ball_fit.hpp"

namespace imess::metrology::detail {
namespace {

// Axis of the quadric x'Ax + b'x + c = 0 that best fits the points (smallest singular vector of
// the design matrix). A cylinder has eigenvalues (l, l, 0) and a cone (l, l, -m): the axis is the
// eigenvector whose eigenvalue stands apart from the other two.
std::optional<Eigen::Vector3d> quadric_axis(const Eigen::Matrix3Xd& q) {
  const Eigen::Index n = q.cols();
  if (n < 10) return std::nullopt;
  const double scale = rms_spread<3>(q);
  if (!(scale > 0.0)) return std::nullopt;
  Eigen::MatrixXd m(n, 10);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d p = q.col(i) / scale;
    m.row(i) << p.x() * p.x(), p.y() * p.y(), p.z() * p.z(), p.x() * p.y(), p.x() * p.z(),
        p.y() * p.z(), p.x(), p.y(), p.z(), 1.0;
  }
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeThinV);
  const Eigen::VectorXd k = svd.matrixV().col(9);
  Eigen::Matrix3d a;
  a << k(0), 0.5 * k(3), 0.5 * k(4), 0.5 * k(3), k(1), 0.5 * k(5), 0.5 * k(4), 0.5 * k(5), k(2);
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(a);
  if (es.info() != Eigen::Success) return std::nullopt;
  const Eigen::Vector3d l = es.eigenvalues();  // ascending
  const Eigen::Index odd = (l(1) - l(0)) < (l(2) - l(1)) ? 2 : 0;
  const Eigen::Vector3d axis = es.eigenvectors().col(odd);
  if (!axis.allFinite()) return std::nullopt;
  return axis.normalized();
}

}  // namespace

std::vector<Eigen::Vector3d> candidate_axes(const Eigen::Matrix3Xd& q, const PrincipalAxes<3>& pa) {
  std::vector<Eigen::Vector3d> axes;
  if (auto qa = quadric_axis(q)) axes.push_back(*qa);
  for (int k = 0; k < 3; ++k) axes.emplace_back(pa.axes.col(k).normalized());
  return axes;
}

std::optional<AxisPosition> axis_position(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& axis) {
  Eigen::Vector3d u;
  Eigen::Vector3d v;
  perpendicular_basis(axis, u, v);
  std::vector<Eigen::Vector2d> flat(static_cast<std::size_t>(q.cols()));
  for (Eigen::Index i = 0; i < q.cols(); ++i)
    flat[static_cast<std::size_t>(i)] = Eigen::Vector2d(u.dot(q.col(i)), v.dot(q.col(i)));
  FitOptions quick;
  quick.max_iterations = 50;
  auto circle = fit_ball<2>(std::span<const Eigen::Vector2d>(flat), 3, "axis start", quick);
  if (!circle) return std::nullopt;
  AxisPosition pos;
  pos.point = u * circle->center.x() + v * circle->center.y();
  pos.radius = circle->radius;
  return pos;
}

std::optional<FitError> check_axial_input(std::span<const Eigen::Vector3d> points, std::size_t min_points,
                                          std::string_view feature, PrincipalAxes<3>& pa) {
  if (auto e = check_input<3>(points, min_points, feature)) return e;
  pa = principal_axes<3>(points);
  return check_spread<3>(pa, points.size(), 3, feature);
}

}  // namespace imess::metrology::detail
