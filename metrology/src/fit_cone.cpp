// Cone fit in the NIST parameterisation (axis point, direction, distance s from the point to
// the surface, half apex angle phi): candidate starting axes, Levenberg–Marquardt on the signed
// distance rho*cos(phi) - h*sin(phi) - s; the smallest sum of squares wins.
#include <algorithm>
#include <cmath>
#include <numbers>

#include <Eigen/QR>

#include "axis_start.hpp"
#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"
#include "levenberg_marquardt.hpp"
#include "multi_start.hpp"

namespace imess::metrology {
namespace {

constexpr std::string_view kName = "cone";

// Local frame [u v a] at the axis point c (centred coordinates); step = (shift u, shift v,
// tilt u, tilt v, d s, d phi). After each step the axis point is moved to the foot of the
// centroid and s adjusted so the surface is unchanged (s' = s + t sin phi for a shift t).
// phi may go negative during the iteration; (a, phi) and (-a, -phi) are the same cone.
class ConeProblem {
 public:
  struct State {
    Eigen::Vector3d c;
    Eigen::Vector3d a;
    double s = 0.0;
    double phi = 0.0;
  };
  ConeProblem(const Eigen::Matrix3Xd& q, double scale) : q_(q), scale_(scale) {}

  Eigen::Index residual_count() const { return q_.cols(); }
  Eigen::Index parameter_count() const { return 6; }

  void evaluate(const State& st, Eigen::VectorXd& res, Eigen::MatrixXd* J) const {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    detail::perpendicular_basis(st.a, u, v);
    const double cp = std::cos(st.phi);
    const double sp = std::sin(st.phi);
    for (Eigen::Index i = 0; i < q_.cols(); ++i) {
      const auto [x, y, z, rho] = detail::axial_coordinates(u, v, st.a, q_.col(i) - st.c);
      res(i) = rho * cp - z * sp - st.s;
      if (J) {
        const double ex = rho > 0.0 ? x / rho : 0.0;
        const double ey = rho > 0.0 ? y / rho : 0.0;
        J->row(i) << -ex * cp, -ey * cp, -ex * z * cp - x * sp, -ey * z * cp - y * sp, -1.0,
            -rho * sp - z * cp;
      }
    }
  }

  State apply(const State& st, const Eigen::VectorXd& delta) const {
    State n;
    detail::step_axis(st.c, st.a, delta, n.c, n.a);
    n.s = st.s + delta(4);
    n.phi = st.phi + delta(5);
    const double t = -n.c.dot(n.a);
    n.c += t * n.a;
    n.s += t * std::sin(n.phi);
    return n;
  }

  Eigen::VectorXd scales(const State& st) const {
    const double len = std::max(scale_, std::abs(st.s));
    Eigen::VectorXd sc(6);
    sc << len, len, 1.0, 1.0, len, 1.0;
    return sc;
  }

 private:
  const Eigen::Matrix3Xd& q_;
  double scale_;
};

// Start for a given axis line: the radius as a straight-line function of the axial position.
ConeProblem::State start_on_axis(const Eigen::Matrix3Xd& q, const Eigen::Vector3d& c,
                                 const Eigen::Vector3d& a) {
  const Eigen::Index n = q.cols();
  Eigen::MatrixXd m(n, 2);
  Eigen::VectorXd rho(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Vector3d d = q.col(i) - c;
    m(i, 0) = 1.0;
    m(i, 1) = a.dot(d);
    rho(i) = a.cross(d).norm();
  }
  const Eigen::Vector2d k = m.colPivHouseholderQr().solve(rho);
  ConeProblem::State st;
  st.c = c - c.dot(a) * a;
  st.a = a;
  st.phi = std::atan(k(1));
  st.s = (k(0) + k(1) * (st.c - c).dot(a)) * std::cos(st.phi);
  return st;
}

Fit<Cone> refine(std::span<const Eigen::Vector3d> points, const detail::PrincipalAxes<3>& pa,
                 const Eigen::Matrix3Xd& q, const std::vector<ConeProblem::State>& starts,
                 const FitOptions& options, bool sample_starts) {
  const ConeProblem pb(q, detail::rms_spread<3>(q));
  const auto valid = [](const ConeProblem::State& st) { return std::abs(st.phi) < 0.5 * std::numbers::pi; };
  const auto best = detail::best_start(pb, q, starts, options, sample_starts, valid);
  if (!best.state) return detail::no_solution_error(best, options, starts.size(), points.size(), kName);
  ConeProblem::State st = *best.state;
  if (st.phi < 0.0) {  // orient the axis toward increasing radius
    st.a = -st.a;
    st.phi = -st.phi;
  }
  Cone cone;
  cone.point = pa.centroid + st.c;
  cone.direction = st.a;
  cone.distance = st.s;
  cone.apex_angle_rad = 2.0 * st.phi;
  cone.stats = detail::solution_stats(pb, st, best.outcome.iterations);
  return cone;
}

}  // namespace

Fit<Cone> fit_cone(std::span<const Eigen::Vector3d> points, const FitOptions& options) {
  detail::PrincipalAxes<3> pa;
  if (auto e = detail::check_axial_input(points, kMinPointsCone, kName, pa)) return *e;
  const Eigen::Matrix3Xd q = detail::centred<3>(points, pa.centroid);
  const Eigen::Matrix3Xd qs = detail::start_sample(q);
  const auto starts = detail::axial_starts<ConeProblem::State>(
      qs, pa, [&qs](const detail::AxisPosition& pos, const Eigen::Vector3d& axis) {
        return start_on_axis(qs, pos.point, axis);
      });
  if (starts.empty()) return detail::no_start_error(kName);
  return refine(points, pa, q, starts, options, true);
}

Fit<Cone> fit_cone(std::span<const Eigen::Vector3d> points, const Cone& start, const FitOptions& options) {
  detail::PrincipalAxes<3> pa;
  if (auto e = detail::check_axial_input(points, kMinPointsCone, kName, pa)) return *e;
  if (!start.point.allFinite() || !start.direction.allFinite() || !std::isfinite(start.distance) ||
      !std::isfinite(start.apex_angle_rad) || start.direction.norm() == 0.0 ||
      !(start.apex_angle_rad > -std::numbers::pi && start.apex_angle_rad < std::numbers::pi))
    return detail::make_error(FitErrorCode::InvalidArgument, kName,
                              "the starting cone needs a finite point, a non-zero direction, a "
                              "finite distance and an apex angle in (-pi, pi)");
  const Eigen::Matrix3Xd q = detail::centred<3>(points, pa.centroid);
  Cone unit = start;
  unit.direction.normalize();
  const Cone moved = unit.moved_to(pa.centroid);
  ConeProblem::State st;
  st.a = unit.direction;
  st.c = moved.point - pa.centroid;
  st.c -= st.c.dot(st.a) * st.a;
  st.s = moved.distance;
  st.phi = 0.5 * start.apex_angle_rad;
  return refine(points, pa, q, {st}, options, false);
}

}  // namespace imess::metrology
