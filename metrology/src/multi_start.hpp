// Internal: runs Levenberg–Marquardt from several starting states and keeps the best solution
// (cylinder and cone fits), and picks an evenly strided subsample for the start search.
#pragma once

#include <algorithm>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "levenberg_marquardt.hpp"

namespace imess::metrology::detail {

// Condition number of the scaled Jacobian above which a parameter is taken as undetermined.
inline constexpr double kMaxAxialCondition = 1e10;
// Relative sum-of-squares difference below which two solutions are the same minimum.
inline constexpr double kSameMinimum = 1e-9;
// Above this many points the starts are compared on a strided subsample; only the winner is
// then refined on all points (the losing starts may each run to the iteration cap).
inline constexpr Eigen::Index kStartSample = 400;

template <class Problem>
struct MultiStart {
  std::optional<typename Problem::State> state;
  LmOutcome outcome;
  bool any_converged = false;
  double worst_condition = 0.0;
};

// `valid(state)` rejects solutions that are not the feature (e.g. a non-positive radius).
template <class Problem, class Valid>
MultiStart<Problem> multi_start(const Problem& pb, const std::vector<typename Problem::State>& starts,
                                const FitOptions& options, Valid valid) {
  MultiStart<Problem> best;
  for (const auto& start : starts) {
    typename Problem::State s = start;
    const LmOutcome out = levenberg_marquardt(pb, s, options);
    if (!out.converged) continue;
    best.any_converged = true;
    if (!(out.condition < kMaxAxialCondition) || !valid(s)) {
      best.worst_condition = std::max(best.worst_condition, out.condition);
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

}  // namespace imess::metrology::detail
