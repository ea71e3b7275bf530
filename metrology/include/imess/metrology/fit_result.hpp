// Outcome types shared by every fit: the error codes, the value-or-error wrapper Fit<T>,
// the residual statistics attached to each result and the solver options.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <variant>

namespace imess::metrology {

// Why a fit produced no result. Values are stable: never renumber, only append.
enum class FitErrorCode : int {
  TooFewPoints = 1,          // fewer points than the feature has free parameters
  NonFiniteInput = 2,        // a coordinate, approach vector or radius is NaN or infinite
  CoincidentPoints = 3,      // all points (nearly) at one place
  CollinearPoints = 4,       // plane / circle / sphere / cylinder / cone need a spread off one line
  CoplanarPoints = 5,        // sphere / cylinder / cone need points off one plane
  NotConverged = 6,          // iteration cap reached before any convergence criterion held
  IllConditioned = 7,        // the data do not determine every parameter (singular Jacobian)
  InconsistentApproach = 8,  // probe compensation: hits approached the surface from both sides
  InvalidArgument = 9,       // sizes of inputs disagree, negative tip radius, ...
  NonPositiveSize = 10,      // compensation would leave a radius / distance <= 0
  AmbiguousSolution = 11,    // the points lie exactly on two different features (a minimal
                             // cylinder or cone set): they do not determine one
  ConeIsCylinder = 12,       // cone: the apex angle is not distinguishable from 0; fit a cylinder
};

// Stable lower_snake name of a code, e.g. "collinear_points".
std::string_view to_string(FitErrorCode code) noexcept;

struct FitError {
  FitErrorCode code;
  std::string message;  // says which input and why, e.g. "circle: 5 points are collinear ..."
};

// Thrown by Fit<T>::value() when the fit failed: the caller asked for a value that is not there.
class BadFitAccess : public std::logic_error {
 public:
  explicit BadFitAccess(const FitError& e)
      : std::logic_error("fit failed (" + std::string(to_string(e.code)) + "): " + e.message) {}
};

// Value-or-error result of a fit (a small std::expected). Fitting never throws; a failed fit
// carries a FitErrorCode and a message naming the feature and the reason.
template <class T>
class Fit {
 public:
  Fit(T value) : v_(std::move(value)) {}           // NOLINT: implicit on purpose, like expected
  Fit(FitError error) : v_(std::move(error)) {}    // NOLINT

  bool ok() const noexcept { return v_.index() == 0; }
  explicit operator bool() const noexcept { return ok(); }

  const T& value() const& {
    if (!ok()) throw BadFitAccess(std::get<1>(v_));
    return std::get<0>(v_);
  }
  T& value() & {
    if (!ok()) throw BadFitAccess(std::get<1>(v_));
    return std::get<0>(v_);
  }
  T value() && {  // by value: `auto x = fit_plane(pts).value();` never dangles
    if (!ok()) throw BadFitAccess(std::get<1>(v_));
    return std::move(std::get<0>(v_));
  }
  const T& operator*() const& { return value(); }
  const T* operator->() const { return &value(); }
  T* operator->() { return &value(); }

  // Precondition: !ok().
  const FitError& error() const { return std::get<1>(v_); }

 private:
  std::variant<T, FitError> v_;
};

// Residual statistics of a fit. The sign convention of a residual is the feature's (see
// features.hpp): positive = outside / along the normal.
struct FitStats {
  std::size_t point_count = 0;
  int iterations = 0;          // accepted + rejected solver steps; 0 for closed-form fits
  double rms = 0.0;            // sqrt(sum r^2 / N)
  double min_residual = 0.0;   // most negative signed residual
  double max_residual = 0.0;   // most positive signed residual
  double form() const noexcept { return max_residual - min_residual; }  // form deviation
};

// Controls of the iterative (Levenberg–Marquardt) fits. Defaults reach the rounding floor of
// double precision on well-posed data in a handful of iterations.
struct FitOptions {
  int max_iterations = 200;
  double step_tolerance = 1e-13;      // max |step_k| / scale_k (lengths scaled by feature size)
  double gradient_tolerance = 1e-13;  // max cosine between residual vector and a Jacobian column
  double ssq_tolerance = 1e-15;       // actual and predicted relative reduction of sum r^2
};

}  // namespace imess::metrology
