// Cone fit in the NIST parameterisation (axis point, direction, distance s from the point to
// the surface, half apex angle phi): starting cones from a screened direction search
// (cone_start.cpp), Levenberg–Marquardt on the signed distance rho*cos(phi) - h*sin(phi) - s;
// the smallest sum of squares wins.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>

#include <Eigen/SVD>

#include "axis_start.hpp"
#include "cone_problem.hpp"
#include "cone_start.hpp"
#include "fit_common.hpp"
#include "imess/metrology/fit.hpp"
#include "levenberg_marquardt.hpp"
#include "multi_start.hpp"

namespace imess::metrology {
namespace {

using detail::ConeProblem;

constexpr std::string_view kCone = "cone";

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
  return detail::make_error(FitErrorCode::ConeIsCylinder, kCone, os.str());
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
    return detail::make_error(FitErrorCode::AmbiguousSolution, kCone, os.str());
  }
  if (sample_starts && points.size() == kMinPointsCone) {
    // A minimal set has no redundancy: the search found one exact solution, but several cones
    // generally pass through 6 points, and no fit can tell which one the workpiece is. Refused
    // like two found ones — and also when no start converged (a narrow sector can leave the
    // solver crawling along a valley of nearly exact cones): the answer would be the same.
    std::ostringstream os;
    os << "the " << points.size() << " points are the minimum for a cone: ";
    if (best.state)
      os << "they lie exactly on " << describe(*best.state, pa.centroid) << ", but several cones";
    else
      os << "no start converged to a cone through them, and several cones";
    os << " generally pass through 6 points, and the points cannot tell which one the workpiece is; probe more "
          "points (or refine from a nominal cone)";
    return detail::make_error(FitErrorCode::AmbiguousSolution, kCone, os.str());
  }
  if (!best.state) return detail::no_solution_error(best, options, starts.size(), points.size(), kCone);
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
  if (auto e = detail::check_axial_input(points, kMinPointsCone, kCone, pa)) return *e;
  const Eigen::Matrix3Xd q = detail::centred<3>(points, pa.centroid);
  const std::vector<ConeProblem::State> starts = detail::cone_starts(detail::start_sample(q), pa);
  if (starts.empty()) return detail::no_start_error(kCone);
  return refine(points, pa, q, starts, options, true);
}

Fit<Cone> fit_cone(std::span<const Eigen::Vector3d> points, const Cone& start, const FitOptions& options) {
  detail::PrincipalAxes<3> pa;
  if (auto e = detail::check_axial_input(points, kMinPointsCone, kCone, pa)) return *e;
  if (!start.point.allFinite() || !start.direction.allFinite() || !std::isfinite(start.distance) ||
      !std::isfinite(start.apex_angle_rad) || start.direction.norm() == 0.0 ||
      !(start.apex_angle_rad > -std::numbers::pi && start.apex_angle_rad < std::numbers::pi))
    return detail::make_error(FitErrorCode::InvalidArgument, kCone,
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
