// Circle/sphere fit: linear (Kåsa) start on centred, scaled data, then Levenberg–Marquardt on
// the geometric residuals |p - c| - r with the analytic Jacobian [-(p - c)/|p - c|, -1].
#include "ball_fit.hpp"

#include <cmath>
#include <sstream>

#include <Eigen/QR>

#include "fit_common.hpp"
#include "levenberg_marquardt.hpp"

namespace imess::metrology::detail {
namespace {

// Condition number of the scaled Jacobian above which a parameter is taken as undetermined.
constexpr double kMaxCondition = 1e10;
// Residual rms (relative to the data spread) below which the points lie exactly on the ball, and
// the largest accepted independent gradient cosine otherwise (as for the axial fits).
constexpr double kExactRms = 1e-10;
constexpr double kCheckCosine = 1e-7;

template <int Dim>
class BallProblem {
 public:
  using State = Eigen::Matrix<double, Dim + 1, 1>;  // centre (centred coordinates), radius
  BallProblem(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& q, double scale) : q_(q), scale_(scale) {}

  Eigen::Index residual_count() const { return q_.cols(); }
  Eigen::Index parameter_count() const { return Dim + 1; }

  void evaluate(const State& s, Eigen::VectorXd& r, Eigen::MatrixXd* J) const {
    const Eigen::Matrix<double, Dim, 1> c = s.template head<Dim>();
    for (Eigen::Index i = 0; i < q_.cols(); ++i) {
      const Eigen::Matrix<double, Dim, 1> d = q_.col(i) - c;
      const double dist = d.norm();
      r(i) = dist - s(Dim);
      if (J) {
        // A point exactly at the centre has no defined direction; its row then only moves r.
        if (dist > 0.0)
          J->row(i).template head<Dim>() = -d.transpose() / dist;
        else
          J->row(i).template head<Dim>().setZero();
        (*J)(i, Dim) = -1.0;
      }
    }
  }
  State apply(const State& s, const Eigen::VectorXd& delta) const { return s + delta; }
  Eigen::VectorXd scales(const State& s) const {
    return Eigen::VectorXd::Constant(Dim + 1, std::max(scale_, std::abs(s(Dim))));
  }

 private:
  const Eigen::Matrix<double, Dim, Eigen::Dynamic>& q_;
  double scale_;
};

}  // namespace

template <int Dim>
Fit<BallFit<Dim>> fit_ball(std::span<const Eigen::Matrix<double, Dim, 1>> points, std::size_t min_points,
                           std::string_view feature, const FitOptions& options) {
  if (auto e = check_input<Dim>(points, min_points, feature)) return *e;
  const auto pa = principal_axes<Dim>(points);
  if (auto e = check_spread<Dim>(pa, points.size(), Dim, feature)) return *e;

  const Eigen::Matrix<double, Dim, Eigen::Dynamic> q = centred<Dim>(points, pa.centroid);
  const double spread = rms_spread<Dim>(q);

  // Algebraic start on scaled coordinates: |p|^2 + g.p + f = 0 solved in the least-squares sense.
  const Eigen::Index n = q.cols();
  Eigen::MatrixXd m(n, Dim + 1);
  Eigen::VectorXd rhs(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const Eigen::Matrix<double, Dim, 1> p = q.col(i) / spread;
    m.row(i).template head<Dim>() = p.transpose();
    m(i, Dim) = 1.0;
    rhs(i) = -p.squaredNorm();
  }
  const Eigen::VectorXd g = m.colPivHouseholderQr().solve(rhs);
  typename BallProblem<Dim>::State s;
  const Eigen::Matrix<double, Dim, 1> c0 = -0.5 * g.template head<Dim>();
  const double r2 = c0.squaredNorm() - g(Dim);
  s.template head<Dim>() = c0 * spread;
  s(Dim) = (r2 > 0.0 ? std::sqrt(r2) : 1.0) * spread;

  BallProblem<Dim> pb(q, spread);
  const LmOutcome out = levenberg_marquardt(pb, s, options);
  if (!out.converged) {
    std::ostringstream os;
    os << "no convergence within " << options.max_iterations << " iterations";
    return make_error(FitErrorCode::NotConverged, feature, os.str());
  }
  if (!(out.condition < kMaxCondition)) {
    std::ostringstream os;
    os << "the points do not determine the " << (Dim == 2 ? "circle" : "sphere")
       << " (Jacobian condition " << out.condition << ")";
    return make_error(FitErrorCode::IllConditioned, feature, os.str());
  }
  if (!(s(Dim) > 0.0))
    return make_error(FitErrorCode::IllConditioned, feature, "the solver ended at a non-positive radius");
  // Stationarity check with a Jacobian independent of the solver's: central differences of
  // |p - c| - r (skipped when the points lie exactly on the circle / sphere).
  Eigen::VectorXd r0(n);
  pb.evaluate(s, r0, nullptr);
  if (r0.norm() > kExactRms * spread * std::sqrt(static_cast<double>(n))) {
    const auto residuals = [&q, n](const Eigen::VectorXd& x) {
      Eigen::VectorXd r(n);
      for (Eigen::Index i = 0; i < n; ++i) r(i) = (q.col(i) - x.template head<Dim>()).norm() - x(Dim);
      return r;
    };
    const Eigen::VectorXd step = Eigen::VectorXd::Constant(Dim + 1, 1e-6 * std::max(spread, s(Dim)));
    if (const double cosine = fd_gradient_cosine(residuals, Eigen::VectorXd(s), step); !(cosine <= kCheckCosine)) {
      std::ostringstream os;
      os << "the solver stopped at a point that fails the stationarity check (gradient cosine " << cosine << ")";
      return make_error(FitErrorCode::NotConverged, feature, os.str());
    }
  }
  BallFit<Dim> res;
  res.center = pa.centroid + s.template head<Dim>();
  res.radius = s(Dim);
  Eigen::VectorXd r(n);
  pb.evaluate(s, r, nullptr);
  res.stats = make_stats(r, out.iterations);
  return res;
}

template Fit<BallFit<2>> fit_ball<2>(std::span<const Eigen::Vector2d>, std::size_t, std::string_view,
                                     const FitOptions&);
template Fit<BallFit<3>> fit_ball<3>(std::span<const Eigen::Vector3d>, std::size_t, std::string_view,
                                     const FitOptions&);

}  // namespace imess::metrology::detail
