// Internal helpers shared by the fits: input checks, principal axes, residual statistics,
// bases perpendicular to a direction. Not installed; include only from metrology/src.
#pragma once

#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "imess/metrology/fit_result.hpp"

namespace imess::metrology::detail {

// Relative size below which a spread counts as zero (degenerate configuration). Spreads are
// compared with the largest spread, the total spread with the distance from the origin.
inline constexpr double kDegenerateRatio = 1e-10;

FitError make_error(FitErrorCode code, std::string_view feature, const std::string& why);

// Count and finiteness checks; nullopt when the input may be fitted.
template <int Dim>
std::optional<FitError> check_input(std::span<const Eigen::Matrix<double, Dim, 1>> points,
                                    std::size_t min_points, std::string_view feature);

// Centroid and principal axes of a point set: axes.col(0) is the direction of largest spread,
// sigma the singular values of the centred data (descending).
template <int Dim>
struct PrincipalAxes {
  Eigen::Matrix<double, Dim, 1> centroid;
  Eigen::Matrix<double, Dim, Dim> axes;
  Eigen::Matrix<double, Dim, 1> sigma;
};

template <int Dim>
PrincipalAxes<Dim> principal_axes(std::span<const Eigen::Matrix<double, Dim, 1>> points);

// Degeneracy of a point set judged from its principal axes: the returned error says which
// (coincident / collinear / coplanar) when the spread in `needed_dims` directions is missing.
template <int Dim>
std::optional<FitError> check_spread(const PrincipalAxes<Dim>& pa, std::size_t n, int needed_dims,
                                     std::string_view feature);

// Largest cosine between the residual vector r(p0) and a column of the central-difference
// Jacobian of r at p0 (step(k) per parameter): the stationarity test of a solution with a
// Jacobian independent of the solver's. Columns below 1e-6 of the longest (parameters the
// residuals do not depend on) are skipped; 0 when r(p0) is zero, or when the Gauss-Newton step
// to the stationary point is below 1e-3 of `step` in every parameter (p0 is the solution to
// 1e-9 of the feature's size: the cosine of rounded data's last digits says nothing more).
double fd_gradient_cosine(const std::function<Eigen::VectorXd(const Eigen::VectorXd&)>& residuals,
                          const Eigen::VectorXd& p0, const Eigen::VectorXd& step);

// Residual statistics; iterations as reported by the solver.
FitStats make_stats(const Eigen::VectorXd& residuals, int iterations);

// Flips v so that its largest-magnitude component is positive (canonical sign of an axis).
template <class V>
V canonical_sign(const V& v) {
  Eigen::Index k = 0;
  v.cwiseAbs().maxCoeff(&k);
  return v(k) < 0.0 ? V(-v) : v;
}

// Two unit vectors completing `a` (unit) to a right-handed orthonormal basis [u v a].
// A deterministic function of `a`, so the solver can rebuild the same local frame.
void perpendicular_basis(const Eigen::Vector3d& a, Eigen::Vector3d& u, Eigen::Vector3d& v);

// Moves point sets to their centroid (numerical conditioning for large offsets).
template <int Dim>
Eigen::Matrix<double, Dim, Eigen::Dynamic> centred(std::span<const Eigen::Matrix<double, Dim, 1>> pts,
                                                  const Eigen::Matrix<double, Dim, 1>& centroid);

// RMS distance of centred points from their centroid: the length scale of the data.
template <int Dim>
double rms_spread(const Eigen::Matrix<double, Dim, Eigen::Dynamic>& centred_points);

}  // namespace imess::metrology::detail
