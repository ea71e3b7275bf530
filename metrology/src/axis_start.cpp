// Starting axes for cylinder and cone fits: input check, principal axes, quadric axis,
// projected circle.
#include "axis_start.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <span>

#include <Eigen/Cholesky>
#include <Eigen/QR>

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

std::vector<Eigen::Vector3d> hemisphere_directions(int count) {
  // Fibonacci lattice on the upper half sphere: z evenly spaced in (0, 1], azimuth by the golden
  // angle. Every axis direction is within about one spacing of a lattice direction or its negative.
  std::vector<Eigen::Vector3d> dirs;
  const double golden = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < count; ++i) {
    const double z = (i + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    dirs.emplace_back(r * std::cos(golden * i), r * std::sin(golden * i), z);
  }
  return dirs;
}

std::vector<std::size_t> local_minima(const std::vector<Eigen::Vector3d>& dirs, const std::vector<double>& score,
                                      double neighbour_cos, std::size_t keep) {
  std::vector<std::size_t> minima;
  for (std::size_t i = 0; i < dirs.size(); ++i) {
    if (!std::isfinite(score[i])) continue;
    bool lowest = true;
    for (std::size_t j = 0; j < dirs.size() && lowest; ++j) {
      // Axis directions have no sign: a neighbour is close to +d or to -d.
      if (j == i || std::abs(dirs[i].dot(dirs[j])) < neighbour_cos) continue;
      lowest = score[i] < score[j] || (score[i] == score[j] && i < j);
    }
    if (lowest) minima.push_back(i);
  }
  std::sort(minima.begin(), minima.end(), [&](std::size_t x, std::size_t y) { return score[x] < score[y]; });
  if (minima.size() > keep) minima.resize(keep);
  return minima;
}

namespace {

// Projection of q into the plane perpendicular to a (scaled by 1/scale): x, y and the axial h.
void project(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& a, double scale, Eigen::Vector3d& u,
             Eigen::Vector3d& v, Eigen::VectorXd& x, Eigen::VectorXd& y, Eigen::VectorXd& h) {
  perpendicular_basis(a, u, v);
  const Eigen::Index n = q.cols();
  x.resize(n);
  y.resize(n);
  h.resize(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    x(i) = u.dot(q.col(i)) / scale;
    y(i) = v.dot(q.col(i)) / scale;
    h(i) = a.dot(q.col(i)) / scale;
  }
}

}  // namespace

std::optional<DirectionFit> cylinder_on_direction(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& a) {
  const double scale = rms_spread<3>(q);
  if (!(scale > 0.0) || q.cols() < 3) return std::nullopt;
  Eigen::Vector3d u, v;
  Eigen::VectorXd x, y, h;
  project(q, a, scale, u, v, x, y, h);
  const Eigen::Index n = q.cols();
  Eigen::MatrixXd m(n, 3);
  m << 2.0 * x, 2.0 * y, Eigen::VectorXd::Ones(n);
  const Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(m);
  if (qr.rank() < 3) return std::nullopt;
  const Eigen::Vector3d k = qr.solve(Eigen::VectorXd(x.array().square() + y.array().square()));
  const double r2 = k(2) + k(0) * k(0) + k(1) * k(1);
  if (!(r2 > 0.0)) return std::nullopt;
  DirectionFit f;
  f.radius = std::sqrt(r2);
  const Eigen::VectorXd rho = ((x.array() - k(0)).square() + (y.array() - k(1)).square()).sqrt();
  f.score = (rho.array() - f.radius).square().sum() * scale * scale;
  f.radius *= scale;
  f.point = (k(0) * u + k(1) * v) * scale;
  return f;
}

std::optional<DirectionFit> cone_on_direction(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& a) {
  const double scale = rms_spread<3>(q);
  if (!(scale > 0.0) || q.cols() < 5) return std::nullopt;
  Eigen::Vector3d u, v;
  Eigen::VectorXd x, y, h;
  project(q, a, scale, u, v, x, y, h);
  const Eigen::Index n = q.cols();
  // Normal equations (scaled coordinates): a start needs no more precision, and the search
  // evaluates this for some 260 directions.
  Eigen::Matrix<double, 5, 5> mtm = Eigen::Matrix<double, 5, 5>::Zero();
  Eigen::Matrix<double, 5, 1> mtb = Eigen::Matrix<double, 5, 1>::Zero();
  for (Eigen::Index i = 0; i < n; ++i) {
    Eigen::Matrix<double, 5, 1> row;
    row << 2.0 * x(i), 2.0 * y(i), h(i), h(i) * h(i), 1.0;
    mtm.noalias() += row * row.transpose();
    mtb += row * (x(i) * x(i) + y(i) * y(i));
  }
  const Eigen::LDLT<Eigen::Matrix<double, 5, 5>> ldlt(mtm);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 1e-12 * ldlt.vectorD().maxCoeff()))
    return std::nullopt;
  const Eigen::Matrix<double, 5, 1> k = ldlt.solve(mtb);
  const Eigen::VectorXd rho = ((x.array() - k(0)).square() + (y.array() - k(1)).square()).sqrt();
  const double hm = h.mean();
  const double hvar = (h.array() - hm).square().sum();
  if (!(hvar > 0.0)) return std::nullopt;
  const double slope = ((h.array() - hm) * rho.array()).sum() / hvar;
  const Eigen::Vector2d rs(rho.mean() - slope * hm, slope);
  // Parameters (cx, cy, radius, slope); Gauss–Newton while the sum of squares drops. One pass
  // over the points gives the sum of squares at w and the normal equations of the next step
  // (fixed size, no allocation per call: the start search evaluates this for every grid
  // direction). It stops once a step lowers the sum of squares by 1e-12 of it or less.
  struct Pass {
    double ssq = 0.0;
    Eigen::Matrix4d jtj = Eigen::Matrix4d::Zero();
    Eigen::Vector4d jte = Eigen::Vector4d::Zero();
  };
  const auto pass = [&](const Eigen::Vector4d& w) {
    Pass out;
    for (Eigen::Index i = 0; i < n; ++i) {
      const double dx = x(i) - w(0);
      const double dy = y(i) - w(1);
      const double r = std::sqrt(dx * dx + dy * dy);
      const double e = r - w(2) - w(3) * h(i);
      const Eigen::Vector4d row(r > 0.0 ? -dx / r : 0.0, r > 0.0 ? -dy / r : 0.0, -1.0, -h(i));
      out.ssq += e * e;
      out.jtj.noalias() += row * row.transpose();
      out.jte += e * row;
    }
    return out;
  };
  Eigen::Vector4d p(k(0), k(1), rs(0), rs(1));
  Pass at = pass(p);
  for (int it = 0; it < 10; ++it) {
    const Eigen::LLT<Eigen::Matrix4d> llt(at.jtj);
    if (llt.info() != Eigen::Success) break;
    const Eigen::Vector4d step = llt.solve(-at.jte);
    if (!step.allFinite()) break;
    const Eigen::Vector4d trial = p + step;
    const Pass next = pass(trial);
    if (!(next.ssq < at.ssq)) break;
    const bool settled = at.ssq - next.ssq <= 1e-12 * at.ssq;
    p = trial;
    at = next;
    if (settled || step.norm() < 1e-12) break;
  }
  DirectionFit f;
  f.slope = p(3);
  const double cp = std::cos(std::atan(f.slope));
  f.score = at.ssq * cp * cp * scale * scale;
  f.radius = p(2) * scale;
  f.point = (p(0) * u + p(1) * v) * scale;
  return f;
}

std::optional<FitError> check_axial_input(std::span<const Eigen::Vector3d> points, std::size_t min_points,
                                          std::string_view feature, PrincipalAxes<3>& pa) {
  if (auto e = check_input<3>(points, min_points, feature)) return e;
  pa = principal_axes<3>(points);
  return check_spread<3>(pa, points.size(), 3, feature);
}

}  // namespace imess::metrology::detail
