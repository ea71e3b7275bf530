// Internal: least-squares circle (Dim = 2) and sphere (Dim = 3) — the "ball" family sharing one
// algebraic start and one Levenberg–Marquardt problem.
#pragma once

#include <span>
#include <string_view>

#include <Eigen/Core>

#include "imess/metrology/fit_result.hpp"

namespace imess::metrology::detail {

template <int Dim>
struct BallFit {
  Eigen::Matrix<double, Dim, 1> center;
  double radius = 0.0;
  FitStats stats;
};

// Checks count/finiteness/spread (needs Dim independent directions), then fits.
template <int Dim>
Fit<BallFit<Dim>> fit_ball(std::span<const Eigen::Matrix<double, Dim, 1>> points, std::size_t min_points,
                           std::string_view feature, const FitOptions& options);

}  // namespace imess::metrology::detail
