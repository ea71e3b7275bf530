// Internal Levenberg–Marquardt driver used by the iterative fits (circle, sphere, cylinder, cone).
// The problem supplies residuals, an analytic Jacobian and how a step changes its state.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>
#include <Eigen/QR>
#include <Eigen/SVD>

#include "imess/metrology/fit_result.hpp"

namespace imess::metrology::detail {

// What the driver reports. `converged` is false only when the iteration cap was hit.
struct LmOutcome {
  int iterations = 0;
  bool converged = false;
  double ssq = 0.0;
  const char* reason = "";
  double condition = 0.0;  // condition number of the column-scaled Jacobian at the solution
  double gradient_cosine = 0.0;  // max cosine between r and a column of J at the solution
};

// Largest cosine between the residual vector and a column of J (0 at a stationary point).
inline double max_gradient_cosine(const Eigen::MatrixXd& J, const Eigen::VectorXd& r) {
  const double rnorm = r.norm();
  double worst = 0.0;
  if (rnorm == 0.0) return worst;
  for (Eigen::Index k = 0; k < J.cols(); ++k) {
    const double cn = J.col(k).norm();
    if (cn > 0.0) worst = std::max(worst, std::abs(J.col(k).dot(r)) / (cn * rnorm));
  }
  return worst;
}

// Condition number of J with its columns scaled to unit norm (infinite when rank-deficient).
inline double scaled_condition(const Eigen::MatrixXd& J) {
  const Eigen::Index n = J.cols();
  Eigen::MatrixXd js = J;
  for (Eigen::Index k = 0; k < n; ++k) {
    const double cn = js.col(k).norm();
    if (cn > 0.0) js.col(k) /= cn;
  }
  const Eigen::VectorXd sv = Eigen::JacobiSVD<Eigen::MatrixXd>(js).singularValues();
  return sv(n - 1) > 0.0 ? sv(0) / sv(n - 1) : std::numeric_limits<double>::infinity();
}

// The step d minimising |J d + r|^2 + lambda |D d|^2 (D = diag), by QR of the stacked matrix
// [J; sqrt(lambda) D] (a and rhs: the caller's storage for it).
inline Eigen::VectorXd damped_step(const Eigen::MatrixXd& J, const Eigen::VectorXd& r, const Eigen::VectorXd& diag,
                                   double lambda, Eigen::MatrixXd& a, Eigen::VectorXd& rhs) {
  const Eigen::Index m = J.rows();
  const Eigen::Index n = J.cols();
  a.topRows(m) = J;
  a.bottomRows(n).setZero();
  a.bottomRows(n).diagonal() = std::sqrt(lambda) * diag;
  rhs.head(m) = -r;
  rhs.tail(n).setZero();
  return a.colPivHouseholderQr().solve(rhs);
}

// Large residuals: an accepted step whose actual decrease of the sum of squares differs from
// the one the Gauss–Newton model predicted by more than this fraction shows that the residuals'
// curvature (the term Gauss–Newton leaves out) is a sizeable part of the Hessian along the step.
// For an undamped step and a true curvature of mu times the model's the ratio is 2 - mu, and
// Gauss–Newton converges only at the rate |1 - mu| (measured: mu = 0.015 on a noisy 12-point
// cone, 200 iterations not enough; mu = 2.3 on another, every undamped step rejected and the
// damped ones crawling). The driver then takes Newton steps.
inline constexpr double kNewtonModelError = 0.25;
// At rounding level: a Gauss–Newton step that leaves more than this fraction of the gradient
// cosine converges too slowly (a rate |1 - mu| near 1); the driver then takes Newton steps.
inline constexpr double kSlowCosine = 0.5;
// Central-difference step of the Newton Hessian, relative to each parameter's scale.
inline constexpr double kNewtonStep = 1e-5;
// Smallest eigenvalue of the Newton Hessian, relative to its largest, for a Newton step.
inline constexpr double kNewtonMinCurvature = 1e-12;
// Longest multiple of a Gauss–Newton step tried along its direction when the curvature along
// the step is far below Gauss–Newton's (or negative: near a saddle).
inline constexpr double kMaxStretch = 100.0;

// The Newton step for 0.5 |r|^2 at state x (residuals r, Jacobian J): the Hessian by central
// differences of the gradient J^T r over steps of 1e-5 of each parameter's scale (Problem::apply
// and evaluate at x +- h e_k; the step parameters are x's local ones, so the difference also
// carries terms proportional to the gradient, which vanish at the solution). False when the
// Hessian is not positive definite (a saddle region): then there is no Newton step to take.
// predicted: the reduction of |r|^2 the quadratic model promises, g' H^-1 g.
template <class Problem>
bool newton_step(const Problem& pb, const typename Problem::State& x, const Eigen::VectorXd& r, const Eigen::MatrixXd& J,
                 const Eigen::VectorXd& scales, Eigen::VectorXd& delta, double& predicted) {
  const Eigen::Index m = r.size();
  const Eigen::Index n = J.cols();
  Eigen::MatrixXd H(n, n);
  Eigen::VectorXd rp(m);
  Eigen::VectorXd rm(m);
  Eigen::MatrixXd Jp(m, n);
  Eigen::MatrixXd Jm(m, n);
  for (Eigen::Index k = 0; k < n; ++k) {
    const double h = kNewtonStep * scales(k);
    Eigen::VectorXd e = Eigen::VectorXd::Zero(n);
    e(k) = h;
    pb.evaluate(pb.apply(x, e), rp, &Jp);
    pb.evaluate(pb.apply(x, -e), rm, &Jm);
    H.col(k) = (Jp.transpose() * rp - Jm.transpose() * rm) / (2.0 * h);
  }
  if (!H.allFinite()) return false;
  const Eigen::MatrixXd Hs = 0.5 * (H + H.transpose());
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Hs);
  if (es.info() != Eigen::Success) return false;
  const Eigen::VectorXd ev = es.eigenvalues();
  if (!(ev(0) > kNewtonMinCurvature * ev(n - 1))) return false;
  const Eigen::VectorXd g = J.transpose() * r;
  const Eigen::VectorXd w = es.eigenvectors().transpose() * g;
  delta = -es.eigenvectors() * (w.array() / ev.array()).matrix();
  predicted = (w.array().square() / ev.array()).sum();
  return delta.allFinite();
}

// Whether the change from ssq to ssq_new (m residuals, parameters of typical size L) is
// rounding. Rounding of a residual is about eps * L since it is a difference of lengths
// (e.g. |p - c| - r), so the rounding of the sum of squares is about 2 |r| eps L.
inline bool ssq_change_is_rounding(double ssq, double ssq_new, double length_scale, Eigen::Index m) {
  constexpr double kRoundingFactor = 64.0;  // safety factor on the rounding estimate
  const double ssq_rounding = kRoundingFactor * std::numeric_limits<double>::epsilon() *
                              (length_scale * std::sqrt(static_cast<double>(m) * ssq) + ssq);
  return std::abs(ssq - ssq_new) <= ssq_rounding;
}

// Iterations in a row whose change of the sum of squares is within its rounding after which the
// solver stops ("rounding floor"): with large residuals and a poorly conditioned problem (a wide
// cone on a sector) Gauss–Newton steps can keep jumping by 1e-7 of the size around the minimum
// while the sum of squares changes only in its last digits, and no other test fires.
inline constexpr int kRoundingSteps = 10;
inline constexpr double kFloorCosine = 1e-9;

// Problem requirements:
//   using State = ...;
//   Eigen::Index residual_count() const;  Eigen::Index parameter_count() const;
//   void evaluate(const State&, Eigen::VectorXd& r, Eigen::MatrixXd* J) const;
//       J is the derivative of r with respect to a step taken from this state (delta = 0)
//   State apply(const State&, const Eigen::VectorXd& delta) const;
//   Eigen::VectorXd scales(const State&) const;   typical size of each parameter (step test)
//
// Each step solves min |J d + r|^2 + lambda |D d|^2 (D = column norms of J, Moré scaling) by a
// QR factorisation of the stacked matrix, not via the normal equations, so the step keeps the
// full precision of J. lambda starts at 0 (pure Gauss–Newton), grows x10 on a rejected step and
// shrinks x10 on an accepted one. A step is accepted when the sum of squares decreases, or when
// its actual change is within the rounding of the sum of squares and either its predicted
// relative change is at rounding level too or it lowers the gradient cosine: there the sum of
// squares can no longer judge a step, but the step itself (from r and J) is still exact, and
// the gradient (from r and J) still tells a step toward the solution from one away from it.
// After a step whose decrease the Gauss–Newton model predicted poorly (kNewtonModelError) the
// driver takes Newton steps (newton_step) while they lower the sum of squares and the Hessian is
// positive definite, and goes back to Gauss–Newton otherwise.
// Convergence: (a) residual vector orthogonal to every column of J within gradient_tolerance
// (cosine), (b) max |d_k| / scale_k <= step_tolerance, or (c) actual and predicted relative
// reductions of the sum of squares both <= ssq_tolerance on three accepted steps in a row.
template <class Problem>
LmOutcome levenberg_marquardt(const Problem& pb, typename Problem::State& x, const FitOptions& opt) {
  const Eigen::Index m = pb.residual_count();
  const Eigen::Index n = pb.parameter_count();
  Eigen::VectorXd r(m);
  Eigen::MatrixXd J(m, n);
  pb.evaluate(x, r, &J);
  double ssq = r.squaredNorm();
  Eigen::VectorXd diag = J.colwise().norm().transpose();
  double lambda = 0.0;
  LmOutcome out;
  int flat_steps = 0;
  int rounding_steps = 0;  // iterations in a row whose change of the sum of squares is rounding

  Eigen::MatrixXd a(m + n, n);
  Eigen::VectorXd rhs(m + n);
  Eigen::VectorXd r_new(m);
  Eigen::MatrixXd J_new(m, n);
  Eigen::VectorXd r_long(m);
  Eigen::MatrixXd J_long(m, n);
  bool newton = false;  // take Newton steps (large residuals, see kNewtonModelError)

  auto finish = [&](bool converged, const char* why) {
    out.converged = converged;
    out.reason = why;
    out.ssq = ssq;
    out.gradient_cosine = max_gradient_cosine(J, r);
    out.condition = scaled_condition(J);
    return out;
  };

  for (int it = 0; it < opt.max_iterations; ++it) {
    if (ssq == 0.0) return finish(true, "zero residual");
    const double cosine = max_gradient_cosine(J, r);
    if (cosine <= opt.gradient_tolerance) return finish(true, "gradient");

    diag = diag.cwiseMax(J.colwise().norm().transpose());
    const Eigen::VectorXd sc = pb.scales(x);
    Eigen::VectorXd delta;
    double predicted = 0.0;
    const bool newton_taken = newton && newton_step(pb, x, r, J, sc, delta, predicted);
    if (!newton_taken) {
      newton = false;
      delta = damped_step(J, r, diag, lambda, a, rhs);
      predicted = ssq - (J * delta + r).squaredNorm();
    }
    out.iterations = it + 1;

    const double step = (delta.array().abs() / sc.array()).maxCoeff();

    const typename Problem::State x_old = x;
    const typename Problem::State candidate = pb.apply(x, delta);
    pb.evaluate(candidate, r_new, &J_new);
    const double ssq_new = r_new.squaredNorm();

    const double predicted_rel = predicted / ssq;
    const double actual_rel = (ssq - ssq_new) / ssq;
    // Near the minimum the sum of squares stops resolving the step (its change is rounding),
    // while the step itself, computed from the residuals and J, is still accurate: take it.
    const bool change_is_rounding = std::isfinite(ssq_new) && ssq_change_is_rounding(ssq, ssq_new, sc.maxCoeff(), m);
    const double cosine_new = change_is_rounding ? max_gradient_cosine(J_new, r_new) : cosine;
    const bool rounding_level = change_is_rounding && (predicted_rel <= opt.ssq_tolerance || cosine_new < cosine);
    // At the rounding floor: the sum of squares has not changed beyond its rounding for
    // kRoundingSteps iterations (taken or not) — no step can be verified any more.
    rounding_steps = change_is_rounding ? rounding_steps + 1 : 0;
    if (std::isfinite(ssq_new) && (ssq_new < ssq || rounding_level)) {
      const double ssq_old = ssq;
      x = candidate;
      r = r_new;
      J = J_new;
      ssq = ssq_new;
      // Large residuals (kNewtonModelError): take Newton steps from here on. When an undamped
      // step's sum of squares fell clearly more than predicted (mu < 1), also try the step
      // stretched to the minimum along it by the measured curvature, 1 / mu (kMaxStretch when
      // mu is about 0 or negative, near a saddle).
      // At rounding level the sum of squares cannot measure the model error, but the gradient
      // shows the convergence rate: a Gauss–Newton step that left more than kSlowCosine of the
      // gradient cosine is converging linearly and slowly (large residuals): Newton steps too.
      if (!newton_taken && change_is_rounding && cosine_new > kSlowCosine * cosine) newton = true;
      if (!newton_taken && predicted > 0.0 && !change_is_rounding &&
          std::abs((ssq_old - ssq_new) / predicted - 1.0) > kNewtonModelError) {
        newton = true;
        const double mu = 2.0 - (ssq_old - ssq_new) / predicted;
        if (lambda == 0.0 && mu < 1.0 - kNewtonModelError) {
          const double stretch = mu > 1.0 / kMaxStretch ? 1.0 / mu : kMaxStretch;
          const typename Problem::State longer = pb.apply(x_old, stretch * delta);
          pb.evaluate(longer, r_long, &J_long);
          if (const double ssq_long = r_long.squaredNorm(); std::isfinite(ssq_long) && ssq_long < ssq) {
            x = longer;
            r = r_long;
            J = J_long;
            ssq = ssq_long;
          }
        }
      }
      if (step <= opt.step_tolerance) return finish(true, "step");
      const bool flat = actual_rel <= opt.ssq_tolerance && predicted_rel <= opt.ssq_tolerance;
      // Sum of squares stationary (actual and predicted relative change) on 3 undamped steps in a
      // row. A flat damped step only means the damping is no longer needed: drop it.
      if (flat && lambda == 0.0) {
        if (++flat_steps >= 3) return finish(true, "sum of squares");
      } else {
        flat_steps = 0;
      }
      // Damping is relaxed only when the model predicted the decrease well (gain ratio > 0.75):
      // with large residuals the undamped step can overshoot right after a damped one succeeded.
      const bool good_model = predicted > 0.0 && (ssq_old - ssq) > 0.75 * predicted;
      if (flat || lambda < 1e-10) {
        lambda = 0.0;
      } else if (good_model) {
        lambda *= 0.1;
      }
      if (rounding_steps >= kRoundingSteps && max_gradient_cosine(J, r) <= kFloorCosine)
        return finish(true, "rounding floor");
    } else {
      // No decrease: at the rounding floor when the step was already negligible.
      if (step <= opt.step_tolerance) return finish(true, "step");
      if (rounding_steps >= kRoundingSteps) return finish(true, "rounding floor");
      if (newton_taken) {  // the quadratic model failed: back to (damped) Gauss–Newton
        newton = false;
        continue;
      }
      lambda = lambda == 0.0 ? 1e-4 : lambda * 10.0;
      if (lambda > 1e30) return finish(true, "stalled");
    }
  }
  return finish(false, "iteration cap");
}

}  // namespace imess::metrology::detail
