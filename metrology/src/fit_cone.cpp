// Cone fit in the NIST parameterisation (axis point, direction, distance s from the point to
// the surface, half apex angle phi): candidate starting axes, Levenberg–Marquardt on the signed
// distance rho*cos(phi) - h*sin(phi) - s; the smallest sum of squares wins.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/SVD>

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
    return detail::fd_gradient_cosine(residuals, Eigen::VectorXd::Zero(6), step);
  }

  bool same_solution(const State& x0, const State& y0) const {
    const State x = oriented(x0);
    const State y = oriented(y0);
    const double len = std::max(scale_, std::max(std::abs(x.s), std::abs(y.s)));
    const Eigen::Vector3d dc = y.c - x.c;
    return (x.a - y.a).norm() < 1e-6 && (dc - dc.dot(x.a) * x.a).norm() < 1e-6 * len &&
           std::abs(x.s - y.s) < 1e-6 * len && std::abs(x.phi - y.phi) < 1e-6;
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

std::string describe(const ConeProblem::State& s0, const Eigen::Vector3d& centroid) {
  const ConeProblem::State s = ConeProblem::oriented(s0);
  std::ostringstream os;
  const Eigen::Vector3d p = centroid + s.c;
  os << "axis through (" << p.x() << ", " << p.y() << ", " << p.z() << ") along (" << s.a.x() << ", " << s.a.y()
     << ", " << s.a.z() << "), apex angle " << 2.0 * s.phi * 180.0 / std::numbers::pi << " deg";
  return os.str();
}

// A cone whose apex angle does not differ from 0 beyond its standard uncertainty (3 sigma from
// the residuals and the Jacobian), or by less than a radius change of 1e-9 of the data size over
// the probed axial extent (exact data), is a cylinder: say so instead of reporting a cone with
// its apex far away.
// Half apex angle up to which a statistically insignificant angle makes the cone a cylinder.
constexpr double kCylinderHalfAngle = 0.5 * std::numbers::pi / 180.0;

std::optional<FitError> cylinder_check(const ConeProblem& pb, const Eigen::Matrix3Xd& q, const ConeProblem::State& st) {
  const Eigen::Index n = q.cols();
  Eigen::VectorXd r(n);
  Eigen::MatrixXd J(n, 6);
  pb.evaluate(st, r, &J);
  const Eigen::VectorXd h = st.a.transpose() * q;
  const double extent = h.maxCoeff() - h.minCoeff();
  const double floor = 1e-9 * pb.length() / std::max(extent, 1e-300);
  double sigma = 0.0;
  if (n > 6) {
    const Eigen::JacobiSVD<Eigen::MatrixXd> svd(J, Eigen::ComputeThinV);
    const Eigen::VectorXd sv = svd.singularValues();
    double var = 0.0;
    for (Eigen::Index k = 0; k < sv.size(); ++k)
      if (sv(k) > 0.0) var += std::pow(svd.matrixV()(5, k) / sv(k), 2);
    sigma = std::sqrt(r.squaredNorm() / static_cast<double>(n - 6) * var);
  }
  // The statistical bound only matters for an apex angle near 0: a cone of a degree or more
  // whose angle is poorly determined (few points, a narrow sector) is still reported as a cone.
  const double bound = std::max(std::min(3.0 * sigma, kCylinderHalfAngle), floor);
  if (std::abs(st.phi) > bound) return std::nullopt;
  std::ostringstream os;
  os << "the apex angle " << 2.0 * st.phi * 180.0 / std::numbers::pi
     << " deg is not distinguishable from 0 (bound " << 2.0 * bound * 180.0 / std::numbers::pi
     << " deg: 3 standard deviations up to 1 deg, or a radius change of 1e-9 of the size over the probed "
        "length): the "
     << n << " points lie on a cylinder; fit a cylinder instead (fit_cylinder, messcap fit cylinder)";
  return detail::make_error(FitErrorCode::ConeIsCylinder, kName, os.str());
}

Fit<Cone> refine(std::span<const Eigen::Vector3d> points, const detail::PrincipalAxes<3>& pa,
                 const Eigen::Matrix3Xd& q, const std::vector<ConeProblem::State>& starts,
                 const FitOptions& options, bool sample_starts) {
  const ConeProblem pb(q, detail::rms_spread<3>(q));
  const auto valid = [](const ConeProblem::State& st) { return std::abs(st.phi) < 0.5 * std::numbers::pi; };
  const auto best = detail::best_start(pb, q, starts, options, sample_starts, valid);
  if (best.ambiguous) {
    std::ostringstream os;
    os << "the " << points.size() << " points lie exactly on at least two different cones ("
       << describe(best.ambiguous->first, pa.centroid) << "; " << describe(best.ambiguous->second, pa.centroid)
       << "), so they do not determine one (" << kMinPointsCone
       << " points are the minimum, but several cones pass through 6 points); probe more points";
    return detail::make_error(FitErrorCode::AmbiguousSolution, kName, os.str());
  }
  if (!best.state) return detail::no_solution_error(best, options, starts.size(), points.size(), kName);
  if (sample_starts && points.size() == kMinPointsCone) {
    // A minimal set has no redundancy: the search found one exact solution, but several cones
    // generally pass through 6 points, and no fit can tell which one the workpiece is. Refused
    // like two found ones.
    std::ostringstream os;
    os << "the " << points.size() << " points are the minimum for a cone: they lie exactly on "
       << describe(*best.state, pa.centroid) << ", but several cones generally pass through 6 points, and the points cannot tell which one "
       << "the workpiece is; probe more points (or refine from a nominal cone)";
    return detail::make_error(FitErrorCode::AmbiguousSolution, kName, os.str());
  }
  // Orient the axis toward increasing radius.
  const ConeProblem::State st = ConeProblem::oriented(*best.state);
  if (auto e = cylinder_check(pb, q, st)) return *e;
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
  std::vector<ConeProblem::State> starts;
  for (const Eigen::Vector3d& axis : detail::start_directions(qs, pa, detail::cone_on_direction)) {
    if (auto f = detail::cone_on_direction(qs, axis)) {
      ConeProblem::State st;
      st.c = f->point;
      st.a = axis;
      st.phi = std::atan(f->slope);
      st.s = f->radius * std::cos(st.phi);
      starts.push_back(st);
    } else if (auto pos = detail::axis_position(qs, axis)) {
      starts.push_back(start_on_axis(qs, pos->point, axis));
    }
  }
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
