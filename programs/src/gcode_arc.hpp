// LinuxCNC's arc tolerances (Debian's LinuxCNC 2.9, measured with rs274 -g): how far a
// centre-format end may lie off the circle, and how short an R-format radius may be.
#pragma once
#include <cmath>
#include <string>

#include "scanner.hpp"

namespace imess::programs::detail {

// Zero radius (centre format) and the R format's reach: 0.00005 in = 0.00127 mm.
inline constexpr double kArcRadiusTolerance = 0.00127;
inline constexpr double kArcRelativeTolerance = 0.001;  // 0.1 % of the larger radius

// Centre format, |r_end - r_start|: 0.02·√2 mm (G21) or 0.002·√2 in (G20), in mm.
inline double arc_spiral_tolerance(bool inches) { return (inches ? 0.002 * 25.4 : 0.02) * std::sqrt(2.0); }

// LinuxCNC's rule: refused beyond 100 × the tolerance, or beyond the tolerance and 0.1 %.
inline bool arc_ends_fit(double r0, double r1, bool inches) {
  const double abs_err = std::fabs(r1 - r0), tol = arc_spiral_tolerance(inches);
  if (abs_err > 100 * tol) return false;
  return !(abs_err > tol && abs_err / std::max(r0, r1) > kArcRelativeTolerance);
}

inline std::string arc_ends_rule(bool inches) {
  const double tol = arc_spiral_tolerance(inches), unit = inches ? 25.4 : 1.0;
  const char* u = inches ? " in" : " mm";
  return "an end on the circle (as LinuxCNC: within " + num(tol / unit) + u + ", or 0.1 % of the radius up to " +
         num(100 * tol / unit) + u + ")";
}

}  // namespace imess::programs::detail
