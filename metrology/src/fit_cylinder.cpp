// Cylinder fit: starting axes from the principal axes, an algebraic quadric and a search over
// axis directions; each refined by Levenberg–Marquardt on (distance from the axis) - r; the
// smallest sum of squares that passes the independent stationarity check wins.
#include <algorithm>
#include <cmath>
#include <sstream>

#include <Eigen/Geometry>

#include "axis_start.hpp"
#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"
#include "levenberg_marquardt.hpp"
#include "multi_start.hpp"

namespace imess::metrology {
namespace {

constexpr std::string_view kCylinder = "cylinder";

// Parameters are linearised in a local frame [u v a] at the current axis point c (centred
// coordinates): step = (shift along u, shift along v, tilt toward u, tilt toward v, d radius).
// After each step the axis point is moved back to the foot of the centroid, so the point never
// drifts along the axis and the tilts stay well conditioned.
class CylinderProblem {
 public:
  struct State {
    Eigen::Vector3d c;
    Eigen::Vector3d a;
    double r = 0.0;
  };
  CylinderProblem(const Eigen::Matrix3Xd& q, double scale) : q_(q), scale_(scale) {}

  Eigen::Index residual_count() const { return q_.cols(); }
  Eigen::Index parameter_count() const { return 5; }
  double length() const { return scale_; }

  void evaluate(const State& s, Eigen::VectorXd& res, Eigen::MatrixXd* J) const {
    Eigen::Vector3d u;
    Eigen::Vector3d v;
    detail::perpendicular_basis(s.a, u, v);
    for (Eigen::Index i = 0; i < q_.cols(); ++i) {
      const auto [x, y, z, rho] = detail::axial_coordinates(u, v, s.a, q_.col(i) - s.c);
      res(i) = rho - s.r;
      if (J) {
        if (rho > 0.0) {
          J->row(i) << -x / rho, -y / rho, -x * z / rho, -y * z / rho, -1.0;
        } else {
          J->row(i) << 0.0, 0.0, 0.0, 0.0, -1.0;
        }
      }
    }
  }

  State apply(const State& s, const Eigen::VectorXd& delta) const {
    State n;
    detail::step_axis(s.c, s.a, delta, n.c, n.a);
    n.r = s.r + delta(4);
    n.c -= n.c.dot(n.a) * n.a;
    return n;
  }

  Eigen::VectorXd scales(const State& s) const {
    const double len = std::max(scale_, std::abs(s.r));
    Eigen::VectorXd sc(5);
    sc << len, len, 1.0, 1.0, len;
    return sc;
  }

  // Residuals from the public Cylinder, by finite differences — not the solver's local frame or
  // Jacobian. Perturbed are the five degrees of freedom only: the point across the axis, the
  // direction tilted, the radius (docs/metrology.md 2.7: a point moved along the axis or a
  // direction scaled along itself change nothing but rounding, and such a column's cosine is noise).
  double independent_cosine(const State& s) const {
    const Eigen::Vector3d u = s.a.unitOrthogonal();
    const Eigen::Vector3d v = s.a.cross(u);
    const auto residuals = [&](const Eigen::VectorXd& x) {
      Cylinder cyl;
      cyl.point = s.c + x(0) * u + x(1) * v;
      cyl.direction = (s.a + x(2) * u + x(3) * v).normalized();
      Eigen::VectorXd r(q_.cols());
      for (Eigen::Index i = 0; i < q_.cols(); ++i) r(i) = cyl.distance_from_axis(q_.col(i)) - (s.r + x(4));
      return r;
    };
    const double len = std::max(scale_, std::abs(s.r));
    Eigen::VectorXd step(5);
    step << 1e-6 * len, 1e-6 * len, 1e-6, 1e-6, 1e-6 * len;
    return detail::fd_gradient_cosine(residuals, Eigen::VectorXd::Zero(5), step);
  }

  bool same_solution(const State& x, const State& y) const {
    const double len = std::max(scale_, std::max(x.r, y.r));
    const Eigen::Vector3d dc = y.c - x.c;
    return x.a.cross(y.a).norm() < 1e-6 && (dc - dc.dot(x.a) * x.a).norm() < 1e-6 * len &&
           std::abs(x.r - y.r) < 1e-6 * len;
  }

 private:
  const Eigen::Matrix3Xd& q_;
  double scale_;
};

std::string describe(const CylinderProblem::State& s, const Eigen::Vector3d& centroid) {
  std::ostringstream os;
  const Eigen::Vector3d p = centroid + s.c;
  const Eigen::Vector3d a = detail::canonical_sign(s.a);
  os << "axis through (" << p.x() << ", " << p.y() << ", " << p.z() << ") along (" << a.x() << ", " << a.y()
     << ", " << a.z() << "), diameter " << 2.0 * s.r;
  return os.str();
}

Fit<Cylinder> refine(std::span<const Eigen::Vector3d> points, const detail::PrincipalAxes<3>& pa,
                     const Eigen::Matrix3Xd& q, const std::vector<CylinderProblem::State>& starts,
                     const FitOptions& options, bool sample_starts) {
  const CylinderProblem pb(q, detail::rms_spread<3>(q));
  const auto valid = [](const CylinderProblem::State& st) { return st.r > 0.0; };
  const auto best = detail::best_start(pb, q, starts, options, sample_starts, valid);
  if (best.ambiguous) {
    std::ostringstream os;
    os << "the " << points.size() << " points lie exactly on at least two different cylinders ("
       << describe(best.ambiguous->first, pa.centroid) << "; " << describe(best.ambiguous->second, pa.centroid)
       << "), so they do not determine one (" << kMinPointsCylinder
       << " points are the minimum, but up to 6 cylinders pass through 5 points); probe more points";
    return detail::make_error(FitErrorCode::AmbiguousSolution, kCylinder, os.str());
  }
  if (!best.state) return detail::no_solution_error(best, options, starts.size(), points.size(), kCylinder);
  if (sample_starts && points.size() == kMinPointsCylinder) {
    // A minimal set has no redundancy: the search found one exact solution, but an even number
    // of cylinders (2, 4 or 6) passes through 5 points in general position when one does, and
    // no fit can tell which one the workpiece is. Refused like two found ones.
    std::ostringstream os;
    os << "the " << points.size() << " points are the minimum for a cylinder: they lie exactly on "
       << describe(*best.state, pa.centroid) << ", but an even number of cylinders (2, 4 or 6) passes through 5 points in general position "
          "when one does, and the points cannot tell which one "
       << "the workpiece is; probe more points (or refine from a nominal cylinder)";
    return detail::make_error(FitErrorCode::AmbiguousSolution, kCylinder, os.str());
  }
  Cylinder cyl;
  cyl.point = pa.centroid + best.state->c;
  cyl.direction = detail::canonical_sign(best.state->a);
  cyl.diameter = 2.0 * best.state->r;
  cyl.stats = detail::solution_stats(pb, *best.state, best.outcome.iterations);
  return cyl;
}

}  // namespace

Fit<Cylinder> fit_cylinder(std::span<const Eigen::Vector3d> points, const FitOptions& options) {
  detail::PrincipalAxes<3> pa;
  if (auto e = detail::check_axial_input(points, kMinPointsCylinder, kCylinder, pa)) return *e;
  const Eigen::Matrix3Xd q = detail::centred<3>(points, pa.centroid);
  const Eigen::Matrix3Xd qs = detail::start_sample(q);
  std::vector<CylinderProblem::State> starts;
  for (const Eigen::Vector3d& axis : detail::start_directions(qs, pa, detail::cylinder_on_direction)) {
    if (auto pos = detail::axis_position(qs, axis)) starts.push_back({pos->point, axis, pos->radius});
  }
  if (starts.empty()) return detail::no_start_error(kCylinder);
  return refine(points, pa, q, starts, options, true);
}

Fit<Cylinder> fit_cylinder(std::span<const Eigen::Vector3d> points, const Cylinder& start,
                           const FitOptions& options) {
  detail::PrincipalAxes<3> pa;
  if (auto e = detail::check_axial_input(points, kMinPointsCylinder, kCylinder, pa)) return *e;
  if (!start.point.allFinite() || !start.direction.allFinite() || !std::isfinite(start.diameter) ||
      start.direction.norm() == 0.0 || !(start.diameter > 0.0))
    return detail::make_error(FitErrorCode::InvalidArgument, kCylinder,
                              "the starting cylinder needs a finite point, a non-zero direction "
                              "and a positive diameter");
  const Eigen::Matrix3Xd q = detail::centred<3>(points, pa.centroid);
  CylinderProblem::State s;
  s.a = start.direction.normalized();
  s.c = start.point - pa.centroid;
  s.c -= s.c.dot(s.a) * s.a;
  s.r = 0.5 * start.diameter;
  return refine(points, pa, q, {s}, options, false);
}

}  // namespace imess::metrology
