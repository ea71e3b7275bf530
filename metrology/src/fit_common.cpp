// Shared fit helpers: input checks, principal axes (SVD of the centred data), statistics.
#include "fit_common.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/SVD>

namespace imess::metrology::detail {

FitError make_error(FitErrorCode code, std::string_view feature, const std::string& why) {
  return FitError{code, std::string(feature) + ": " + why};
}

template <int Dim>
std::optional<FitError> check_input(std::span<const Eigen::Matrix<double, Dim, 1>> points,
                                    std::size_t min_points, std::string_view feature) {
  if (points.size() < min_points) {
    std::ostringstream os;
    os << "needs at least " << min_points << " points, got " << points.size();
    return make_error(FitErrorCode::TooFewPoints, feature, os.str());
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!points[i].allFinite()) {
      std::ostringstream os;
      os << "point " << i << " has a non-finite coordinate";
      return make_error(FitErrorCode::NonFiniteInput, feature, os.str());
    }
  }
  return std::nullopt;
}

template <int Dim>
Eigen::Matrix<double, Dim, Eigen::Dynamic> centred(std::span<const Eigen::Matrix<double, Dim, 1>> pts,
                                                  const Eigen::Matrix<double, Dim, 1>& centroid) {
  Eigen::Matrix<double, Dim, Eigen::Dynamic> q(Dim, static_cast<Eigen::Index>(pts.size()));
  for (std::size_t i = 0; i < pts.size(); ++i) q.col(static_cast<Eigen::Index>(i)) = pts[i] - centroid;
  return q;
}

template <int Dim>
double rms_spread(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& centred_points) {
  if (centred_points.cols() == 0) return 0.0;
  return std::sqrt(centred_points.squaredNorm() / static_cast<double>(centred_points.cols()));
}

template <int Dim>
PrincipalAxes<Dim> principal_axes(std::span<const Eigen::Matrix<double, Dim, 1>> points) {
  using Vec = Eigen::Matrix<double, Dim, 1>;
  PrincipalAxes<Dim> pa;
  // Two-pass centroid: the second pass removes the rounding of the first (large offsets).
  Vec c = Vec::Zero();
  for (const auto& p : points) c += p;
  c /= static_cast<double>(points.size());
  Vec corr = Vec::Zero();
  for (const auto& p : points) corr += p - c;
  c += corr / static_cast<double>(points.size());
  pa.centroid = c;
  // SVD of the centred N x Dim matrix, not an eigen-decomposition of the scatter matrix: the
  // scatter matrix squares the condition number and loses half the digits of the direction.
  // Fewer points than dimensions (a 2-point line in space): pad with zero rows, which changes
  // neither V nor the non-zero singular values but keeps Dim singular values.
  const auto n = static_cast<Eigen::Index>(points.size());
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(std::max<Eigen::Index>(n, Dim), Dim);
  m.topRows(n) = centred<Dim>(points, c).transpose();
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(m, Eigen::ComputeFullV);
  pa.axes = svd.matrixV();
  pa.sigma = svd.singularValues();
  return pa;
}

template <int Dim>
std::optional<FitError> check_spread(const PrincipalAxes<Dim>& pa, std::size_t n, int needed_dims,
                                     std::string_view feature) {
  const double offset = std::max(1.0, pa.centroid.cwiseAbs().maxCoeff());
  const double spread = pa.sigma(0) / std::sqrt(static_cast<double>(n));
  std::ostringstream os;
  if (spread <= kDegenerateRatio * offset) {
    os << "all " << n << " points coincide (rms spread " << spread << ")";
    return make_error(FitErrorCode::CoincidentPoints, feature, os.str());
  }
  if (needed_dims >= 2 && pa.sigma(1) <= kDegenerateRatio * pa.sigma(0)) {
    os << "the " << n << " points are collinear (spread across the line "
       << pa.sigma(1) / std::sqrt(static_cast<double>(n)) << ", along it " << spread
       << "); the feature needs points off one line";
    return make_error(FitErrorCode::CollinearPoints, feature, os.str());
  }
  if constexpr (Dim == 3) {
    if (needed_dims >= 3 && pa.sigma(2) <= kDegenerateRatio * pa.sigma(0)) {
      os << "the " << n << " points are coplanar (spread off the plane "
         << pa.sigma(2) / std::sqrt(static_cast<double>(n))
         << "); the feature needs points off one plane (e.g. at two heights)";
      return make_error(FitErrorCode::CoplanarPoints, feature, os.str());
    }
  }
  return std::nullopt;
}

double fd_gradient_cosine(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals,
                          const Eigen::VectorXd& p0, const Eigen::VectorXd& step) {
  const Eigen::VectorXd r = residuals(p0);
  const double rn = r.norm();
  if (rn == 0.0) return 0.0;
  Eigen::MatrixXd J(r.size(), p0.size());
  for (Eigen::Index k = 0; k < p0.size(); ++k) {
    Eigen::VectorXd plus = p0;
    Eigen::VectorXd minus = p0;
    plus(k) += step(k);
    minus(k) -= step(k);
    J.col(k) = (residuals(plus) - residuals(minus)) / (2.0 * step(k));
  }
  const double longest = J.colwise().norm().maxCoeff();
  double worst = 0.0;
  for (Eigen::Index k = 0; k < J.cols(); ++k) {
    const double cn = J.col(k).norm();
    if (cn > 1e-6 * longest) worst = std::max(worst, std::abs(J.col(k).dot(r)) / (cn * rn));
  }
  if (worst == 0.0) return 0.0;
  // How far the stationary point is: the Gauss-Newton step from p0 with this Jacobian. Within
  // 1e-3 of a finite-difference step (step is 1e-6 of the feature's size, so 1e-9 of it) p0 is
  // the least-squares solution to any precision the data carry — the cosine alone is not
  // enough there: with residuals of a few rounded decimals (1e-5 of the size) the last step
  // the solver can take still leaves a cosine of about 1e-6 (measured on a probed bore).
  const Eigen::VectorXd gn = J.colPivHouseholderQr().solve(r);
  if ((gn.array() / step.array()).abs().maxCoeff() <= 1e-3) return 0.0;
  return worst;
}

FitStats make_stats(const Eigen::VectorXd& residuals, int iterations) {
  FitStats s;
  s.point_count = static_cast<std::size_t>(residuals.size());
  s.iterations = iterations;
  if (residuals.size() == 0) return s;
  s.rms = std::sqrt(residuals.squaredNorm() / static_cast<double>(residuals.size()));
  s.min_residual = residuals.minCoeff();
  s.max_residual = residuals.maxCoeff();
  return s;
}

void perpendicular_basis(const Eigen::Vector3d& a, Eigen::Vector3d& u, Eigen::Vector3d& v) {
  // Start from the coordinate axis least aligned with a: well conditioned for every a.
  Eigen::Index k = 0;
  a.cwiseAbs().minCoeff(&k);
  Eigen::Vector3d e = Eigen::Vector3d::Zero();
  e(k) = 1.0;
  u = (e - a.dot(e) * a).normalized();
  v = a.cross(u);
}

template std::optional<FitError> check_input<2>(std::span<const Eigen::Vector2d>, std::size_t,
                                                std::string_view);
template std::optional<FitError> check_input<3>(std::span<const Eigen::Vector3d>, std::size_t,
                                                std::string_view);
template PrincipalAxes<2> principal_axes<2>(std::span<const Eigen::Vector2d>);
template PrincipalAxes<3> principal_axes<3>(std::span<const Eigen::Vector3d>);
template std::optional<FitError> check_spread<2>(const PrincipalAxes<2>&, std::size_t, int,
                                                 std::string_view);
template std::optional<FitError> check_spread<3>(const PrincipalAxes<3>&, std::size_t, int,
                                                 std::string_view);
template Eigen::Matrix<double, 2, Eigen::Dynamic> centred<2>(std::span<const Eigen::Vector2d>,
                                                            const Eigen::Vector2d&);
template Eigen::Matrix<double, 3, Eigen::Dynamic> centred<3>(std::span<const Eigen::Vector3d>,
                                                            const Eigen::Vector3d&);
template double rms_spread<2>(const Eigen::Matrix<double, 2, Eigen::Dynamic>&);
template double rms_spread<3>(const Eigen::Matrix<double, 3, Eigen::Dynamic>&);

}  // namespace imess::metrology::detail
