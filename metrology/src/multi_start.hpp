// Internal: runs Levenberg–Marquardt from several starting states and keeps the best solution
// (cylinder and cone fits), picks an evenly strided subsample for the start search, and says
// why no start gave the feature.
#pragma once

#include <algorithm>
#include <optional>
#include <sstream>
#include <string_view>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "fit_common.hpp"
#include "levenberg_marquardt.hpp"

namespace imess::metrology::detail {

// Condition number of the scaled Jacobian above which a parameter is taken as undetermined.
inline constexpr double kMaxAxialCondition = 1e10;
// Relative sum-of-squares difference below which two solutions are the same minimum.
inline constexpr double kSameMinimum = 1e-9;
// Above this many points the starts are compared on a strided subsample; only the winner is
// then refined on all points (the losing starts may each run to the iteration cap).
inline constexpr Eigen::Index kStartSample = 400;

// Residual rms (relative to the problem's length scale) at or below which a solution
// interpolates the points: the data are exact for it.
inline constexpr double kExactRms = 1e-10;
// Largest accepted cosine between the residual vector and a column of the independent
// (finite-difference) Jacobian at a solution that does not interpolate the points.
inline constexpr double kCheckCosine = 1e-7;
template <class Problem>
struct MultiStart {
  std::optional<typename Problem::State> state;
  LmOutcome outcome;
  bool any_converged = false;
  double worst_condition = 0.0;
  double worst_check = 0.0;  // largest independent gradient cosine of a rejected solution
  // Two different interpolating solutions: the points lie exactly on two different features,
  // so they do not determine one.
  std::optional<std::pair<typename Problem::State, typename Problem::State>> ambiguous;
};

// Problem requirements beyond levenberg_marquardt's:
//   double length() const;                          the length scale of the data
//   double independent_cosine(const State&) const;  largest gradient cosine of the residuals
//       computed from the public feature (finite differences), not from the solver's Jacobian
//   bool same_solution(const State&, const State&) const;

// `valid(state)` rejects solutions that are not the feature (e.g. a non-positive radius).
template <class Problem, class Valid>
MultiStart<Problem> multi_start(const Problem& pb, const std::vector<typename Problem::State>& starts,
                                const FitOptions& options, Valid valid) {
  MultiStart<Problem> best;
  std::vector<typename Problem::State> exact;
  const auto ssq_at = [&](double rel) {
    const double e = rel * pb.length();
    return e * e * static_cast<double>(pb.residual_count());
  };
  const double exact_ssq = ssq_at(kExactRms);
  for (const auto& start : starts) {
    typename Problem::State s = start;
    const LmOutcome out = levenberg_marquardt(pb, s, options);
    if (!out.converged) continue;
    best.any_converged = true;
    if (!(out.condition < kMaxAxialCondition) || !valid(s)) {
      best.worst_condition = std::max(best.worst_condition, out.condition);
      continue;
    }
    if (out.ssq <= exact_ssq) {
      // Interpolating solutions are all global minima: remember a second, different one.
      for (const auto& e : exact)
        if (!best.ambiguous && !pb.same_solution(e, s)) best.ambiguous.emplace(e, s);
      exact.push_back(s);
    } else if (const double check = pb.independent_cosine(s); !(check <= kCheckCosine)) {
      best.worst_check = std::max(best.worst_check, check);
      continue;
    }
    // A later start must be clearly better; of two equal minima keep the better converged one.
    if (!best.state || out.ssq < best.outcome.ssq * (1.0 - kSameMinimum) ||
        (out.ssq <= best.outcome.ssq * (1.0 + kSameMinimum) &&
         out.gradient_cosine < best.outcome.gradient_cosine)) {
      best.state = s;
      best.outcome = out;
    }
  }
  return best;
}

// Every k-th column of q so that at most about kStartSample remain (all of q if small).
inline Eigen::Matrix3Xd start_sample(const Eigen::Matrix3Xd& q) {
  if (q.cols() <= kStartSample) return q;
  const Eigen::Index stride = (q.cols() + kStartSample - 1) / kStartSample;
  Eigen::Matrix3Xd s(3, (q.cols() + stride - 1) / stride);
  for (Eigen::Index i = 0, k = 0; i < q.cols(); i += stride, ++k) s.col(k) = q.col(i);
  return s;
}

// The best solution on all of pb's points (centred points q). With sample_starts and a large
// cloud, the starts are compared on a subsample first and only the winner is refined on every
// point (the losing starts may each run to the iteration cap). Problem(q, scale) builds the
// problem on a point set.
template <class Problem, class Valid>
MultiStart<Problem> best_start(const Problem& pb, const Eigen::Matrix3Xd& q,
                               const std::vector<typename Problem::State>& starts, const FitOptions& options,
                               bool sample_starts, Valid valid) {
  std::vector<typename Problem::State> full_starts = starts;
  if (sample_starts && q.cols() > kStartSample) {
    const Eigen::Matrix3Xd qs = start_sample(q);
    const Problem ps(qs, rms_spread<3>(qs));
    const auto pick = multi_start(ps, starts, options, valid);
    if (pick.state) full_starts = {*pick.state};
  }
  return multi_start(pb, full_starts, options, valid);
}

// Why best_start found no solution: no start converged, or none determined the feature.
template <class Problem>
FitError no_solution_error(const MultiStart<Problem>& best, const FitOptions& options, std::size_t starts,
                           std::size_t points, std::string_view feature) {
  std::ostringstream os;
  if (best.any_converged && best.worst_check > 0.0 && best.worst_condition == 0.0) {
    os << "no start reached a least-squares solution: the best one fails the stationarity check "
          "(gradient cosine "
       << best.worst_check << " > " << kCheckCosine << ")";
    return make_error(FitErrorCode::NotConverged, feature, os.str());
  }
  if (!best.any_converged) {
    os << "no convergence within " << options.max_iterations << " iterations from any of " << starts
       << " starting axes";
    return make_error(FitErrorCode::NotConverged, feature, os.str());
  }
  os << "the " << points << " points do not determine a " << feature << " (Jacobian condition "
     << best.worst_condition << ")";
  return make_error(FitErrorCode::IllConditioned, feature, os.str());
}

// Residual statistics of the solution s on all of pb's points.
template <class Problem>
FitStats solution_stats(const Problem& pb, const typename Problem::State& s, int iterations) {
  Eigen::VectorXd res(pb.residual_count());
  pb.evaluate(s, res, nullptr);
  return make_stats(res, iterations);
}

// The error of an axial fit whose candidate axes all had degenerate projections.
inline FitError no_start_error(std::string_view feature) {
  return make_error(FitErrorCode::IllConditioned, feature, "no starting axis found (every projection is degenerate)");
}

}  // namespace imess::metrology::detail
