// Internal: the cone least-squares problem for the Levenberg–Marquardt driver and the start
// search (fit_cone.cpp, cone_start.cpp). NIST parameterisation: axis point, direction, distance
// s from the point to the surface, half apex angle phi; signed distance rho*cos(phi) - h*sin(phi) - s.
#pragma once

#include <algorithm>
#include <cmath>

#include <Eigen/Core>

#include "axis_start.hpp"
#include "fit_common.hpp"
#include "imess/metrology/features.hpp"

namespace imess::metrology::detail {

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
  using Row = Eigen::Matrix<double, 6, 1>;

  ConeProblem(const Eigen::Matrix3Xd& q, double scale) : q_(q), scale_(scale) {}

  Eigen::Index residual_count() const { return q_.cols(); }
  Eigen::Index parameter_count() const { return 6; }

  void evaluate(const State& st, Eigen::VectorXd& res, Eigen::MatrixXd* J) const {
    const Frame f(st);
    Row row;
    for (Eigen::Index i = 0; i < q_.cols(); ++i) {
      res(i) = residual(f, st, q_.col(i), J ? &row : nullptr);
      if (J) J->row(i) = row.transpose();
    }
  }

  // The sum of squares at st and the normal equations J'J, J'r of a step from it, in one pass
  // with fixed-size storage (the start search runs a few steps from some 260 starts).
  double normal_equations(const State& st, Eigen::Matrix<double, 6, 6>& jtj, Row& jtr) const {
    const Frame f(st);
    jtj.setZero();
    jtr.setZero();
    double ssq = 0.0;
    Row row;
    for (Eigen::Index i = 0; i < q_.cols(); ++i) {
      const double r = residual(f, st, q_.col(i), &row);
      ssq += r * r;
      jtj.noalias() += row * row.transpose();
      jtr += r * row;
    }
    return ssq;
  }

  State apply(const State& st, const Eigen::VectorXd& delta) const {
    State n;
    step_axis(st.c, st.a, delta, n.c, n.a);
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

  double length() const { return scale_; }

  // Residuals from the public Cone, by finite differences — not the solver's local frame or
  // Jacobian. Perturbed are its degrees of freedom only: the point across the axis, the direction
  // tilted, the distance and the apex angle (as for the cylinder: no column of rounding noise).
  double independent_cosine(const State& st) const {
    const Eigen::Vector3d u = st.a.unitOrthogonal();
    const Eigen::Vector3d v = st.a.cross(u);
    const auto residuals = [&](const Eigen::VectorXd& x) {
      Cone k;
      k.point = st.c + x(0) * u + x(1) * v;
      k.direction = (st.a + x(2) * u + x(3) * v).normalized();
      k.distance = st.s + x(4);
      k.apex_angle_rad = 2.0 * st.phi + x(5);
      Eigen::VectorXd r(q_.cols());
      for (Eigen::Index i = 0; i < q_.cols(); ++i) r(i) = k.signed_distance(q_.col(i));
      return r;
    };
    const double len = std::max(scale_, std::abs(st.s));
    Eigen::VectorXd step(6);
    step << 1e-6 * len, 1e-6 * len, 1e-6, 1e-6, 1e-6 * len, 1e-6;
    return fd_gradient_cosine(residuals, Eigen::VectorXd::Zero(6), step);
  }

  // Whether x and y are the same cone within `tol` (directions and angles in rad, lengths
  // relative to the data size).
  bool same_solution(const State& x0, const State& y0, double tol = 1e-6) const {
    const State x = oriented(x0);
    const State y = oriented(y0);
    const double len = std::max(scale_, std::max(std::abs(x.s), std::abs(y.s)));
    const Eigen::Vector3d dc = y.c - x.c;
    return (x.a - y.a).norm() < tol && (dc - dc.dot(x.a) * x.a).norm() < tol * len &&
           std::abs(x.s - y.s) < tol * len && std::abs(x.phi - y.phi) < tol;
  }

  // (a, phi) and (-a, -phi) are the same cone: the one with phi >= 0.
  static State oriented(State st) {
    if (st.phi < 0.0) {
      st.a = -st.a;
      st.phi = -st.phi;
    }
    return st;
  }

 private:
  // What a state's residuals share: the basis across the axis and the angle's cosine and sine.
  struct Frame {
    explicit Frame(const State& st) : cp(std::cos(st.phi)), sp(std::sin(st.phi)) { perpendicular_basis(st.a, u, v); }
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    double cp;
    double sp;
  };

  // Signed distance of the centred point p from the cone st and, with row, its derivative with
  // respect to the step parameters. rho by a plain square root, not std::hypot (several times
  // slower, and the start search computes some million of them for 400 points): the points are
  // centred, so x^2 + y^2 can neither overflow nor underflow to a loss.
  static double residual(const Frame& f, const State& st, const Eigen::Vector3d& p, Row* row) {
    const Eigen::Vector3d d = p - st.c;
    const double x = f.u.dot(d);
    const double y = f.v.dot(d);
    const double z = st.a.dot(d);
    const double rho = std::sqrt(x * x + y * y);
    if (row) {
      const double ex = rho > 0.0 ? x / rho : 0.0;
      const double ey = rho > 0.0 ? y / rho : 0.0;
      *row << -ex * f.cp, -ey * f.cp, -ex * z * f.cp - x * f.sp, -ey * z * f.cp - y * f.sp, -1.0,
          -rho * f.sp - z * f.cp;
    }
    return rho * f.cp - z * f.sp - st.s;
  }

  const Eigen::Matrix3Xd& q_;
  double scale_;
};

}  // namespace imess::metrology::detail
